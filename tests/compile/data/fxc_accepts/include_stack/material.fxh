// Includes a header of its subfolder, which names headers beside this file and the main file.
#include "parts/lighting.fxh"

float4 Shade(float2 uv) { return Light(uv) * g_tint; }
