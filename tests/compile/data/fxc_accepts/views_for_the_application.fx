// Rule: a Direct3D 10/11 effect may declare RenderTargetView and DepthStencilView variables
// for the application to set (FX11 exposes them as effect variables); no shader reads them,
// and the rest of the effect compiles as if they were not there.
RenderTargetView SceneTarget;
DepthStencilView SceneDepth;
float4 Tint = float4(1, 0.5, 0.25, 1);

struct V { float4 pos : SV_Position; };
V VS(float4 p : POSITION) { V v; v.pos = p; return v; }
float4 PS(V v) : SV_Target { return Tint; }

technique10 Draw { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
