// A "simulate, then draw" effect for the viewer tests: a compute pass writes the colour into a
// structured buffer (a zeroed stand-in) that the draw pass reads, so a window that skips the
// compute pass draws black.
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4x4 World : WORLD;
RWStructuredBuffer<float4> Palette;

[numthreads(1, 1, 1)] void Simulate() { Palette[0] = float4(0.9, 0.6, 0.2, 1); }

struct V {
  float4 pos : SV_Position;
  float3 normal : TEXCOORD0;
};
V VS(float4 p : POSITION, float3 n : NORMAL) {
  V o;
  o.pos = mul(p, WorldViewProjection);
  o.normal = mul(n, (float3x3)World);
  return o;
}
float4 PS(V i) : SV_Target { return float4(Palette[0].rgb * (0.4 + 0.6 * saturate(normalize(i.normal).z)), 1); }

technique11 SimulateThenDraw {
  pass Simulate < int3 Dispatch = {1, 1, 1}; > { SetComputeShader(CompileShader(cs_5_0, Simulate())); }
  pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
}
