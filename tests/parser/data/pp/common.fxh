#pragma once
#define TINT(r, g, b) float4(r, g, b, 1)
float4 Tint = TINT(1, 0.5, 0.25);
