// Rule: a flat initializer list fills a multi-dimensional array element by element, row after
// row: `float a[2][3] = { 1, 2, 3, 4, 5, 6 };` is a[0] = {1, 2, 3}, a[1] = {4, 5, 6}, for
// scalars and vectors alike, in a function or at global scope, a trailing comma allowed.
static const float g_kernel[2][3] = { 1, 2, 1, 2, 4, 2, };
static const float2 g_offsets[2][2] = { -1, -1, 1, -1, -1, 1, 1, 1 };
static const float g_nested[2][2] = { { 0.25, 0.75 }, { 0.5, 0.5 } };

void VS(float4 position : POSITION, float2 uv : TEXCOORD0, out float4 oPosition : POSITION, out float2 oUv : TEXCOORD0)
{
    oPosition = position;
    oUv = uv;
}

float4 PS(float2 uv : TEXCOORD0) : COLOR0
{
    float weights[3][2] = { uv.x, uv.y, 1, 0, 0.5, max(uv.x, uv.y) };
    float sum = 0;
    for (int row = 0; row < 2; row++)
        for (int column = 0; column < 3; column++)
            sum += g_kernel[row][column] * weights[column][row];
    float2 shift = g_offsets[1][0] + g_offsets[0][1];
    return float4(sum, shift, g_nested[1][0]);
}

technique FlatRows
{
    pass P0
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
