// Rule: one effect holds several geometry shaders (a stream per face, instancing, two
// point streams with stream output). Each pass compiles with its own shader's functions:
// glslang crashed on a stream Append in a function that was not its unit's entry.
struct V { float4 pos : SV_Position; float4 c : COLOR; };
struct G { float4 pos : SV_Position; float4 c : COLOR; uint layer : SV_RenderTargetArrayIndex; };
V VS(float4 p : POSITION) { V o; o.pos = p; o.c = p; return o; }
[maxvertexcount(18)]
void GS(triangle V input[3], inout TriangleStream<G> s) {
  for (int f = 0; f < 6; ++f) { G g; g.layer = f; for (int i = 0; i < 3; ++i) { g.pos = input[i].pos; g.c = input[i].c; s.Append(g); } s.RestartStrip(); }
}
[maxvertexcount(1)]
[instance(4)]
void GSI(point V input[1], uint id : SV_GSInstanceID, inout PointStream<V> s) { V v = input[0]; v.c.x = id; s.Append(v); }
[maxvertexcount(2)]
void GS2(point V input[1], inout PointStream<V> s0, inout PointStream<V> s1) { s0.Append(input[0]); s1.Append(input[0]); }
float4 PS(G g) : SV_Target { return g.c; }
technique11 T {
  pass A { SetVertexShader(CompileShader(vs_5_0, VS())); SetGeometryShader(CompileShader(gs_5_0, GS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
  pass B { SetVertexShader(CompileShader(vs_5_0, VS())); SetGeometryShader(ConstructGSWithSO(CompileShader(gs_5_0, GSI()), "SV_POSITION.xyzw", NULL, NULL, NULL, 0)); SetPixelShader(NULL); }
}
// Two streams compile; glslang writes one, so on a device the technique is refused.
technique11 TwoStreams {
  pass C { SetVertexShader(CompileShader(vs_5_0, VS())); SetGeometryShader(ConstructGSWithSO(CompileShader(gs_5_0, GS2()), "0:SV_POSITION.xyzw", "1:COLOR.xyzw", NULL, NULL, 0)); SetPixelShader(NULL); }
}
