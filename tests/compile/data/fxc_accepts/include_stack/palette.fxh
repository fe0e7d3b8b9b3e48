// Beside material.fxh: found from parts/lighting.fxh through its includer's folder.
float4 g_palette[2] = { float4(1, 0, 0, 1), float4(0, 0, 1, 1) };
