// Rule: fxc takes geometry primitive, interpolation and precision words as names where
// they are not modifiers; glslang reserves them. Globals, locals, parameters and struct
// members all keep working, and a geometry shader still reads `point` as its modifier.
float3 point = float3(0, 1, 0);
float linear;
struct Segment { float3 line; float centroid; };
Segment segment;

struct V { float4 pos : SV_Position; float3 n : NORMAL; };

float Distance(float3 triangle, float3 precise) { return length(triangle - precise); }

V VS(float4 pos : POSITION, float3 noperspective : NORMAL, uniform float unorm) {
  V v;
  float snorm = Distance(point, segment.line) * linear + segment.centroid * unorm;
  v.pos = pos * snorm;
  v.n = noperspective;
  return v;
}

[maxvertexcount(1)]
void GS(point V input[1], inout PointStream<V> stream) { stream.Append(input[0]); }

float4 PS(V v) : SV_Target { float lineadj = 0.5, triangleadj = 0.25; return float4(v.n * lineadj + triangleadj, 1); }

technique10 T {
  pass P {
    SetVertexShader(CompileShader(vs_4_0, VS(2.0)));
    SetGeometryShader(CompileShader(gs_4_0, GS()));
    SetPixelShader(CompileShader(ps_4_0, PS()));
  }
}
