// Rule: a hull shader names its patch-constant function in an attribute, not a call; the
// hull shader's unit must hold it (and the domain shader reads the constants it writes).
struct VS_OUT { float3 pos : POSITION; };
struct HS_CONST { float edges[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
struct DS_OUT { float4 pos : SV_Position; };
float g_tess = 4;
float4x4 g_mVP;
VS_OUT VS(float3 p : POSITION) { VS_OUT o; o.pos = p; return o; }
HS_CONST HSConstant(InputPatch<VS_OUT, 3> patch, uint id : SV_PrimitiveID) {
  HS_CONST c; c.edges[0] = c.edges[1] = c.edges[2] = g_tess; c.inside = g_tess; return c;
}
[domain("tri")]
[partitioning("fractional_odd")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("HSConstant")]
VS_OUT HS(InputPatch<VS_OUT, 3> patch, uint i : SV_OutputControlPointID) { return patch[i]; }
[domain("tri")]
DS_OUT DS(HS_CONST c, float3 uvw : SV_DomainLocation, const OutputPatch<VS_OUT, 3> patch) {
  DS_OUT o; o.pos = mul(float4(patch[0].pos * uvw.x + patch[1].pos * uvw.y + patch[2].pos * uvw.z, 1), g_mVP); return o;
}
float4 PS(DS_OUT i) : SV_Target { return 1; }
technique11 Tess { pass P {
  SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(CompileShader(hs_5_0, HS())); SetDomainShader(CompileShader(ds_5_0, DS()));
  SetPixelShader(CompileShader(ps_5_0, PS())); } }
