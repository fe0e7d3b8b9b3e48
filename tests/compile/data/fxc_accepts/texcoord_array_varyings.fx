// Rule: a varying may be an array, `float2 JitterUV[5] : TEXCOORD1`, whose elements take
// TEXCOORD1..TEXCOORD5 (the DirectX SDK's DepthOfField): a vertex shader writing those
// semantics one by one feeds it, and so does the fixed-function vertex stage of a pass that
// sets only a pixel shader.
texture g_scene;
sampler2D g_sceneSampler = sampler_state { Texture = <g_scene>; };
float4x4 g_worldViewProjection : WORLDVIEWPROJECTION;

struct Jittered {
    float4 position : POSITION;
    float2 uv : TEXCOORD0;
    float2 jitter0 : TEXCOORD1;
    float2 jitter1 : TEXCOORD2;
    float2 jitter2 : TEXCOORD3;
};

Jittered VS(float4 position : POSITION, float2 uv : TEXCOORD0)
{
    Jittered o;
    o.position = mul(position, g_worldViewProjection);
    o.uv = uv;
    o.jitter0 = uv + float2(0.01, 0);
    o.jitter1 = uv - float2(0.01, 0);
    o.jitter2 = uv + float2(0, 0.01);
    return o;
}

float4 Blur(float2 uv : TEXCOORD0, float2 jitter[3] : TEXCOORD1) : COLOR0
{
    float4 sum = tex2D(g_sceneSampler, uv);
    for (int i = 0; i < 3; i++)
        sum += tex2D(g_sceneSampler, jitter[i]);
    return sum / 4;
}

technique WithVertexShader
{
    pass P0
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 Blur();
    }
}

technique PixelShaderOnly
{
    pass P0
    {
        PixelShader = compile ps_2_0 Blur();
    }
}
