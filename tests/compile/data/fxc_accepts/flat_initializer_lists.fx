// Rule: an initializer list is flat: the scalars of `float4 a[3] = { 0, 0, 0, 0, ... }` fill
// the array's vectors component by component, in a function or at global scope, a trailing
// comma allowed. Lists with one element per vector keep working.
static const int4 g_permutation[2] =
{
    151, 160, 137, 91,
    90, 15, 131, 13,
};
static const float2 g_taps[2] = { float2(0, 1), float2(1, 0) };

float4 VS(float4 position : POSITION) : POSITION { return position; }

float4 PS(float2 uv : TEXCOORD0) : COLOR0
{
    float4 radiance[3] = { 0, 0, 0, 0, 1, 1, 1, 1, 0.5, 0.5, 0.5, 0.5 };
    float3 scale[2] = { uv.x, uv.y, 1, 2 * uv.x, (uv.y + 1) * 0.5, max(uv.x, uv.y) };
    float4 sum = radiance[0] + radiance[1] * g_permutation[1].x / 255.0 + radiance[2];
    sum.xyz += scale[0] * scale[1] + float3(g_taps[1], 0);
    return sum;
}

technique Flat
{
    pass P0
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
