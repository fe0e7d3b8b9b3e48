// Rule: texture offsets must be immediates once fxc has inlined functions and unrolled
// [unroll] loops; an offset passed through a function or stepped by an unrolled loop is one.
// Vulkan allows a variable Offset only for gathers, so the SPIR-V must say ConstOffset.
Texture2D T; SamplerState S; Texture2D Ts[2];
float4 Fetch(Texture2D t, SamplerState s, float2 uv) { return t.Sample(s, uv); }
float4 FetchOff(Texture2D t, SamplerState s, float2 uv, int2 o) { return t.Sample(s, uv, o); }
float4 Blur(Texture2D t, float2 uv) { float4 c = 0; [unroll] for (int i = -1; i <= 1; ++i) c += t.Sample(S, uv, int2(i, 0)); return c; }
float4 Load3(Texture2D t, int2 p) { return t.Load(int3(p, 0), int2(1, 1)); }
struct V { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V v; v.pos = p; v.uv = uv; return v; }
float4 PS(V v) : SV_Target { return Fetch(T, S, v.uv) + FetchOff(T, S, v.uv, int2(1, 0)) + Blur(Ts[1], v.uv) + Load3(T, int2(v.pos.xy)) + T.SampleLevel(S, v.uv, 0, int2(-1, 1)); }
technique10 X { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
