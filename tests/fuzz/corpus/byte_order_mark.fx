#include "common.fxh"
float4 Tint = SCALE(1);
technique T { pass P { } }
