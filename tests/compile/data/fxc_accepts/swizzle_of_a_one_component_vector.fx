// Rule: a one-component vector (float1, int1, ...) is scalar-like: its `.x` or `.r` may be
// written as well as read, by `=`, `+=`, `++` or as an `out` argument (vvvv's Softedge.fx
// writes its float1 texture coordinate `Out.TexCd.x = ...`); glslang reads such a swizzle
// as a constructor, no l-value.
float4x4 WorldViewProjection;

struct V {
  float4 pos : SV_Position;
  float1 u : TEXCOORD0;
  int1 id : TEXCOORD1;
};

void half_of(float x, out float h) { h = x * 0.5; }

V VS(float4 pos : POSITION, uint vid : SV_VertexID) {
  V o = (V)0;
  o.pos = mul(pos, WorldViewProjection);
  o.u.x = 0.5 + pos.x;
  o.u.r += 0.25;
  o.id.x = vid;
  o.id.x++;
  return o;
}

float4 PS(V i) : SV_Target {
  float1 a = i.u.x, b;
  b.x = a.x * 2;
  half_of(b.r, a.x);
  float2 both = a.xx;
  return float4(both, b.x, i.id.x);
}

technique11 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
