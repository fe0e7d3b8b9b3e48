// Rule: D3D9 constant registers are assigned per shader profile, so a vertex-shader
// constant and a pixel-shader constant may both sit in c0 (the XNA stock effects do this).
// fxc accepts it; the Vulkan unit must not turn both into offset 0 of one uniform block.
float4 Tint          : register(vs, c0);
float4 AlphaRef      : register(ps, c0);
float3 FogColor      : register(ps, c1);
float4x4 WorldViewProj : register(vs, c1);
bool UseFog          : register(b0);
sampler2D Diffuse    : register(s0);

struct VSOut { float4 pos : POSITION; float4 color : COLOR0; float2 uv : TEXCOORD0; };

VSOut VS(float4 pos : POSITION, float2 uv : TEXCOORD0) {
  VSOut o;
  o.pos = mul(pos, WorldViewProj);
  o.color = Tint;
  o.uv = uv;
  return o;
}

float4 PS(float4 color : COLOR0, float2 uv : TEXCOORD0) : COLOR0 {
  float4 c = tex2D(Diffuse, uv) * color;
  clip(c.a - AlphaRef.x);
  if (UseFog) c.rgb = lerp(c.rgb, FogColor, 0.5);
  return c;
}

technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
