// Beside the main file only: include_stack/parts/lighting.fxh finds it through the include stack.
float4 g_tint = float4(1, 1, 1, 1);
