// Rule: ConstructGSWithSO of a vertex shader is stream output with no geometry stage; the
// pass draws with its vertex shader, and a pass that sets none uses that one.
struct V { float4 pos : SV_Position; float3 n : NORMAL; };
V VS(float4 p : POSITION, float3 n : NORMAL) { V v; v.pos = p; v.n = n; return v; }
VertexShader vs = CompileShader(vs_4_0, VS());
GeometryShader captureVS = ConstructGSWithSO(vs, "SV_POSITION.xyzw; NORMAL.xyz");
technique10 Capture {
  pass WithVertexShader { SetVertexShader(vs); SetGeometryShader(captureVS); SetPixelShader(NULL); }
  pass Inline {
    SetVertexShader(vs);
    SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), "SV_POSITION.xyzw"));
    SetPixelShader(NULL);
  }
  pass OnlyTheStreamOutput { SetGeometryShader(captureVS); SetPixelShader(NULL); }
}
