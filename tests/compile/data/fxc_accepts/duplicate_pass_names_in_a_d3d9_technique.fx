// Rule: a Direct3D 9 technique may hold two passes of one name: D3DX9 effects ship so and
// load, since ID3DXEffect addresses passes by index (a name finds the first). Each pass is
// compiled on its own; the front end warns (duplicate-pass-name), it does not refuse.
float4x4 g_worldViewProjection;
float4 g_color;

float4 VS(float4 position : POSITION) : POSITION { return mul(position, g_worldViewProjection); }

float4 Base() : COLOR { return g_color; }

float4 Glow() : COLOR { return g_color * 2; }

technique TwoPassesOneName
{
    pass Layer
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 Base();
    }
    pass Layer
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 Glow();
        AlphaBlendEnable = TRUE;
    }
}
