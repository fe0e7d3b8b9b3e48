// Rule: a struct type may be anonymous where a type is written: a global of an anonymous
// struct type, and the C idiom `typedef struct { ... } Name;`.
struct { float4 color; float scale; } Material;
typedef struct { float3 dir; float intensity; } Light;
Light Sun;

float4x4 WorldViewProj;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProj); }
float4 PS() : SV_Target { return Material.color * Material.scale * Sun.intensity + Sun.dir.x; }

technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
