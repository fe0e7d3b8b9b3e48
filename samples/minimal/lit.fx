// A lit, tinted surface: what samples/minimal draws.
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4x4 World : WORLD;
float3 LightDirection : DIRECTION = {0.3, -0.8, -0.5};
float4 Tint = {0.9, 0.9, 0.9, 1.0};

struct VsOut { float4 position : POSITION; float3 normal : TEXCOORD0; };

VsOut VS(float4 position : POSITION, float3 normal : NORMAL) {
  VsOut o;
  o.position = mul(position, WorldViewProjection);
  o.normal = mul(normal, (float3x3)World);
  return o;
}

float4 PS(VsOut i) : COLOR0 {
  float diffuse = saturate(dot(normalize(i.normal), -LightDirection));
  return float4(Tint.rgb * (0.15 + 0.85 * diffuse), 1.0);
}

technique lit { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
