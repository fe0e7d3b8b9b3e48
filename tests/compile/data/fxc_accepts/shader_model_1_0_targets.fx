// Rule: vs_1_0 and ps_1_0 are compile targets of a D3D9 effect, as vs_1_1 and ps_1_1 are
// (stock effects of D3D9-era tools name them; the DirectX 10 compiler, in its backwards
// compatibility mode, compiles an effect's ps_1_x targets as ps_2_0).
float4x4 g_worldViewProjection;
float4 g_color;

float4 VS(float4 position : POSITION) : POSITION { return mul(position, g_worldViewProjection); }

float4 PS() : COLOR { return g_color; }

technique ShaderModel10
{
    pass P0
    {
        VertexShader = compile vs_1_0 VS();
        PixelShader = compile ps_1_0 PS();
    }
}
