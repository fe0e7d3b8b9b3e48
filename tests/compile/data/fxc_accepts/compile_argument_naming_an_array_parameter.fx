// Rule: a compile-time argument may name a parameter whose value the compiler cannot fold,
// an array the application sets (`compile ps_2_0 Blur(g_kernel, 12)`, as the DirectX SDK's
// DepthOfField passes its kernel): the `uniform` parameter reads that global.
float2 g_kernel[12];
texture g_scene;
sampler2D g_sceneSampler = sampler_state { Texture = <g_scene>; };

float4 Blur(float2 uv : TEXCOORD0, uniform float2 kernel[12], uniform int count) : COLOR0
{
    float4 sum = 0;
    for (int i = 0; i < count; i++)
        sum += tex2D(g_sceneSampler, uv + kernel[i]);
    return sum / count;
}

float4 VS(float4 position : POSITION, inout float2 uv : TEXCOORD0) : POSITION { return position; }

technique Blur12
{
    pass P0
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 Blur(g_kernel, 12);
    }
}
