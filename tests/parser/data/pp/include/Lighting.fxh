#ifndef LIGHTING_FXH
#define LIGHTING_FXH
float Gloss = 32;
#endif
