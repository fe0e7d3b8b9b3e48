// Rule: HLSL 5 resources have operators as well as methods (fxc takes them from vs_4_0 up):
// `t[pos]` loads mip 0, `t.mips[level][pos]` a chosen mip, `ms.sample[s][pos]` one sample of a
// multisampled texture, `b[i]` an element of a buffer. HLSL has no `.Length` property on
// resources; the size is `GetDimensions`.
Texture2D<float4> Albedo;
Texture2DArray<float4> Layers;
Texture2DMS<float4, 4> Resolved;
Buffer<float4> Palette;
StructuredBuffer<float4> Colours;
RWTexture2D<float4> Output;

struct V { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
V VS(uint id : SV_VertexID) { V v; v.uv = float2((id << 1) & 2, id & 2); v.pos = float4(v.uv * 2 - 1, 0, 1); return v; }
float4 PS(V v) : SV_Target {
  uint2 p = uint2(v.pos.xy);
  uint w, h;
  Albedo.GetDimensions(w, h);
  float4 c = Albedo[p] + Albedo.mips[1][p / 2] + Layers[uint3(p, 1)] + Layers.mips[0][uint3(p, 0)];
  c += Resolved.sample[2][p] + Resolved[p];
  return c + Palette[p.x % 4] + Colours[p.y % 4] + float(w + h);
}
[numthreads(8, 8, 1)] void CS(uint3 id : SV_DispatchThreadID) { Output[id.xy] = Albedo[id.xy] + Output[id.xy]; }

technique11 Draw { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
technique11 Compute { pass P { SetComputeShader(CompileShader(cs_5_0, CS())); } }
