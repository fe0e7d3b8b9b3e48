#include "common.fxh"
#define TEX(n) texture n < string ResourceName = #n; >
shared float4x4 WorldViewProj : WORLDVIEWPROJECTION < string UIWidget = "None"; >;
float3 LightDir < string UIName = "Light"; float UIMin = -1; > = {0.577, -0.577, 0.577};
TEX(Diffuse);
sampler2D DiffuseSampler = sampler_state { Texture = <Diffuse>; MinFilter = Linear; AddressU = Wrap; };
struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; };
VSOut VS(float4 p : POSITION, float2 uv : TEXCOORD0) { VSOut o; o.pos = mul(p, WorldViewProj); o.uv = uv; return o; }
float4 PS(VSOut i, uniform bool bright) : COLOR0 { return tex2D(DiffuseSampler, i.uv) * (bright ? SCALE(1) : 1); }
technique Main < string Scheme = "quality"; > {
  pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(true);
            ZEnable = true; CullMode = CCW; AlphaBlendEnable = false; SrcBlend = SrcAlpha; }
}
