// Rule: `uniform` on a parameter means something only to an entry point; a helper that
// declares one still converts its argument like any parameter (`2` for a uniform float is
// 2.0), and so does an entry compiled with compile-time arguments. The D3D10 procedural
// materials sample passes its noise octaves and lacunarity so.
float g_time;

float Octaves(float4 coords, uniform uint count, uniform float lacunarity, uniform float gain)
{
    float sum = 0, amplitude = 1;
    [unroll]
    for (uint i = 0; i < count; i++)
    {
        sum += amplitude * frac(coords.x + coords.y);
        coords *= lacunarity;
        amplitude *= gain;
    }
    return sum;
}

struct V { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V v; v.pos = p; v.uv = uv; return v; }

float4 Noise(V v, uniform float scale) : SV_Target
{
    return Octaves(float4(v.uv * scale, g_time, 1), 4, 2, 0.5);
}

technique10 Procedural
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetPixelShader(CompileShader(ps_4_0, Noise(16)));
    }
}
