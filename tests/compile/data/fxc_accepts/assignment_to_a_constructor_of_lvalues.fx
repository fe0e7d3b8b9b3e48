// Rule: fxc assigns to a constructor of l-values, `float4(a, b) = value;`, part by part
// (the DirectX SDK's parallax occlusion mapping takes two float2 derivatives at once).
sampler2D HeightMap;
float2 TextureSize = float2(512, 512);

struct V { float4 pos : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 pos : POSITION, float2 uv : TEXCOORD0) { V v; v.pos = pos; v.uv = uv; return v; }

float4 PS(float2 uv : TEXCOORD0, float3 n : TEXCOORD1) : COLOR0 {
  float2 dxSize, dySize;
  float2 dx, dy;
  float4(dxSize, dx) = ddx(float4(uv * TextureSize, uv));
  float4(dySize, dy) = ddy(float4(uv * TextureSize, uv));
  float scale; float3 axis;
  float4(axis, scale) = float4(n, length(n));
  float mip = max(0, 0.5 * log2(max(dot(dxSize, dxSize), dot(dySize, dySize))));
  return tex2Dgrad(HeightMap, uv, dx, dy) * mip + float4(axis * scale, 1);
}

technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
