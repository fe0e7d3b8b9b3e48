// Rule: any() and all() take a scalar as well as a vector or matrix, true when it is not zero
// (`if (any(weight))`, `clip(all(mask) ? 1 : -1)`); SPIR-V's OpAny and OpAll take bool vectors only.
float g_weight;
int g_mask;

void VS(float4 position : POSITION, float2 uv : TEXCOORD0, out float4 oPosition : POSITION, out float2 oUv : TEXCOORD0)
{
    oPosition = position;
    oUv = uv;
}

float4 PS(float2 uv : TEXCOORD0) : COLOR0
{
    float4 color = float4(uv, 0, 1);
    if (any(g_weight)) color.z = g_weight;
    if (all(g_mask)) color.w = 0.5;
    bool lit = any(uv.x) && all(uv.y > 0.5) && any(uv > 0.25);
    return lit ? color : color * 0.5;
}

technique ScalarAnyAll
{
    pass P0
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
