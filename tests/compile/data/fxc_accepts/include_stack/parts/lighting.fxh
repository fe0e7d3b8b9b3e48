// Names "palette.fxh" (beside its includer, material.fxh) and "tint.fxh" (beside the main file).
#include "palette.fxh"
#include "tint.fxh"

float4 Light(float2 uv) { return lerp(g_palette[0], g_palette[1], uv.x); }
