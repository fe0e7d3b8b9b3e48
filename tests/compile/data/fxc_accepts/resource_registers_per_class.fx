// Rule: D3D counts registers per class, so t0, s0, b0 and u0 are four different slots; in
// Vulkan they must become four bindings (a texture and a sampler sharing binding 0 crashed
// the driver at pipeline creation).
cbuffer PerFrame : register(b0) { float4 Tint; };
Texture2D Albedo : register(t0);
Texture2D Detail : register(t1);
SamplerState Linear : register(s0);
SamplerState Point : register(s1);
RWTexture2D<float4> Output : register(u0);

struct V { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
V VS(uint id : SV_VertexID) { V v; v.uv = float2((id << 1) & 2, id & 2); v.pos = float4(v.uv * 2 - 1, 0, 1); return v; }
float4 PS(V v) : SV_Target { return Albedo.Sample(Linear, v.uv) * Detail.Sample(Point, v.uv) * Tint; }
[numthreads(8, 8, 1)] void CS(uint3 id : SV_DispatchThreadID) { Output[id.xy] = Albedo.Load(int3(id.xy, 0)) * Tint; }

technique11 Draw { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
technique11 Compute { pass P { SetComputeShader(CompileShader(cs_5_0, CS())); } }
