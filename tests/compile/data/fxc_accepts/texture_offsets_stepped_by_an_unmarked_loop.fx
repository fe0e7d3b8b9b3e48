// Rule: fxc unrolls a loop with a constant trip count whose counter reaches a texture offset
// even without [unroll] (the D3D10 HDR samples' 3x3 down-scale: two nested plain `for`
// loops); the offsets are immediates after that. A loop that needs no unrolling stays one.
Texture2D T;
SamplerState S;
int g_taps = 4;

struct V { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V v; v.pos = p; v.uv = uv; return v; }

float4 DownScale(V v, uniform bool average) : SV_Target
{
    float4 sum = 0;
    for (int y = -1; y <= 1; y++)
        for (int x = -1; x <= 1; x++)
            sum += T.Sample(S, v.uv, int2(x, y));
    for (int i = 0; i < g_taps; i++)  // a trip count known only at run time
        sum += T.SampleLevel(S, v.uv + i * 0.01, 0);
    return average ? sum / 9 : sum;
}

technique10 DownScale3x3
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetPixelShader(CompileShader(ps_4_0, DownScale(true)));
    }
}
