// Rule: fxc takes C's `unsigned int`, and `unsigned` alone, as uint (a loop counter in the
// D3D10 samples' n-body shader is written so); glslang reserves the word `unsigned`.
float4 g_step;

float4 Accumulate(unsigned int count)
{
    float4 sum = 0;
    for (unsigned int i = 0; i < count; i++)
        sum += g_step * (float)i;
    return sum;
}

float4 VS(float4 position : POSITION) : SV_Position { return position; }

float4 PS(float4 position : SV_Position) : SV_Target
{
    unsigned texels = 4;
    unsigned   int  more = texels + 1u;
    return Accumulate(more);
}

technique10 Unsigned
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}
