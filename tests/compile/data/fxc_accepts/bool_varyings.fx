// Rule: a bool may pass between stages (a struct member or a parameter with a semantic, as
// vvvv's Softedge.fx passes `bool dosoft : TEXCOORD1`): fxc carries it as a 32-bit integer.
// glslang makes it a bool input or output, which Vulkan forbids.
float4x4 WorldViewProjection;

struct V {
  float4 pos : SV_Position;
  float2 uv : TEXCOORD0;
  bool inside : TEXCOORD1;
  nointerpolation bool2 flags : TEXCOORD2;
};

struct G {
  float4 pos : SV_Position;
  float4 color : COLOR0;
};

V VS(float4 pos : POSITION, float2 uv : TEXCOORD0) {
  V o;
  o.pos = mul(pos, WorldViewProjection);
  o.uv = uv;
  o.inside = length(pos.xy) < 0.5;
  o.flags = bool2(pos.x > 0, pos.y > 0);
  return o;
}

float4 PS(V i) : SV_Target { return i.inside ? float4(i.flags, 0, 1) : float4(i.uv, 1, 1); }

// Plain parameters: a vertex shader's output, a pixel shader's input.
void VSPlain(float4 pos : POSITION, out float4 position : SV_Position, out float2 uv : TEXCOORD0,
             out bool inside : TEXCOORD1) {
  position = mul(pos, WorldViewProjection);
  uv = pos.xy;
  inside = pos.x > 0;
}

float4 PSPlain(float4 position : SV_Position, float2 uv : TEXCOORD0, bool inside : TEXCOORD1) : SV_Target {
  return inside ? 1 : float4(uv, 0, 1);
}

// A geometry shader's input vertices.
[maxvertexcount(3)]
void GS(triangle V input[3], inout TriangleStream<G> stream) {
  for (int k = 0; k < 3; ++k) {
    G g;
    g.pos = input[k].pos;
    g.color = input[k].inside && input[k].flags.y ? float4(1, 0, 0, 1) : float4(0, 0, 1, 1);
    stream.Append(g);
  }
}

float4 PSColor(G g) : SV_Target { return g.color; }

technique11 T {
  pass Struct { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); }
  pass Plain { SetVertexShader(CompileShader(vs_4_0, VSPlain())); SetPixelShader(CompileShader(ps_4_0, PSPlain())); }
  pass Geometry {
    SetVertexShader(CompileShader(vs_4_0, VS()));
    SetGeometryShader(CompileShader(gs_4_0, GS()));
    SetPixelShader(CompileShader(ps_4_0, PSColor()));
  }
}
