// Rule: a D3D9 `stateblock` variable holds pass states, shaders included
// (`stateblock sb = stateblock_state { ... };`), and `StateBlock = <sb>;` in a pass applies
// them there, as D3DX9 applies the block it captured; a pass may add states of its own.
float4 g_tint = float4(1, 0.5, 0.25, 1);

void VS(float4 position : POSITION, out float4 oPosition : POSITION, out float4 oColor : COLOR0)
{
    oPosition = position;
    oColor = g_tint;
}

float4 PS(float4 color : COLOR0, uniform bool lit) : COLOR0
{
    return lit ? color : color * 0.5;
}

stateblock Overlay = stateblock_state
{
    CullMode = None;
    ZWriteEnable = false;
    VertexShader = compile vs_2_0 VS();
    PixelShader = compile ps_2_0 PS(false);
};

technique StateBlocks
{
    pass Plain
    {
        StateBlock = <Overlay>;
    }
    pass Lit
    {
        StateBlock = <Overlay>;
        PixelShader = compile ps_2_0 PS(true);
    }
}
