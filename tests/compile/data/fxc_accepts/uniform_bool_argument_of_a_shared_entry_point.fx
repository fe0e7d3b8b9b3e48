// fxc converts a compile-time argument to its uniform parameter's type. Here the geometry
// shader is an entry point on its own (technique Plain: `uniform` kept) and called with `1` for
// its `uniform bool` (technique Axis): glslang passed the int unconverted and its SPIR-V then
// branched on an int (vvvv's Sprite.fx, gsBILLBOARD(1)).
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct V { float4 p : SV_Position; };
V VS(float4 p : POSITION) { V o; o.p = mul(p, WorldViewProjection); return o; }
[maxvertexcount(3)] void GS(point V In[1], inout TriangleStream<V> S, uniform bool axis = 0, uniform float3 shift = 0) {
  V o = In[0];
  float3 moved = o.p.xyz;
  if (axis) moved += shift;
  for (int i = 0; i < 3; i++) { o.p.xyz = moved + i; S.Append(o); }
}
float4 PS(V i) : SV_Target { return 1; }
technique11 Plain { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(CompileShader(gs_4_0, GS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
technique11 Axis { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(CompileShader(gs_4_0, GS(1, 2))); SetPixelShader(CompileShader(ps_4_0, PS())); } }
