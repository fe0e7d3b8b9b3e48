// Rule: an entry point's `uniform` interface parameters take compile-time arguments, as the
// DirectX SDK's DynamicShaderLinkageFX11 passes them: interface variables for late binding
// (shader model 5), or class instances for a static specialization that pre-5.0 targets
// compile with the interface calls resolved.
interface iMaterial
{
    float3 Albedo(float2 uv);
};

class cFlat : iMaterial
{
    float3 colour;
    float3 Albedo(float2 uv) { return colour; }
};

class cChecker : iMaterial
{
    float3 odd;
    float3 even;
    float3 Albedo(float2 uv)
    {
        return (frac(uv.x * 4) < 0.5) == (frac(uv.y * 4) < 0.5) ? even : odd;
    }
};

cFlat g_flat;
cChecker g_checker;
iMaterial g_abstractMaterial;

float4x4 g_mWorldViewProjection;

struct VS_OUTPUT
{
    float4 position : SV_POSITION;
    float2 uv : TEXCOORD0;
};

VS_OUTPUT VS(float4 position : POSITION, float2 uv : TEXCOORD0)
{
    VS_OUTPUT o;
    o.position = mul(position, g_mWorldViewProjection);
    o.uv = uv;
    return o;
}

float4 PSUniform(VS_OUTPUT input, uniform iMaterial material, uniform float alpha) : SV_TARGET
{
    return float4(material.Albedo(input.uv), alpha);
}

technique11 LateBound
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetPixelShader(CompileShader(ps_5_0, PSUniform(g_abstractMaterial, 1.0)));
    }
}

technique11 StaticSpecialization
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetPixelShader(CompileShader(ps_4_0, PSUniform(g_checker, 0.5)));
    }
}
