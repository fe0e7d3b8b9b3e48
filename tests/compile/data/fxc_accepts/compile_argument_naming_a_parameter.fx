// Rule: a compile-time argument may name a parameter rather than a literal,
// `compile vs_2_0 VS(g_bones)`: the shader reads the parameter, so its unit declares it
// even though no function body names it.
int g_bones = 2;
float4x4 g_palette[4];

float4 VS(float4 position : POSITION, uniform int bones) : POSITION
{
    float4 sum = 0;
    for (int i = 0; i < bones; i++)
        sum += mul(position, g_palette[i]);
    return sum;
}

float4 PS() : COLOR0 { return 1; }

technique Palette
{
    pass P0
    {
        VertexShader = compile vs_2_0 VS(g_bones);
        PixelShader = compile ps_2_0 PS();
    }
}
