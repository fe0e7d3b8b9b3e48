#if defined(FOO) && FOO > 2
#error too big
#endif
cbuffer PerFrame : register(b0) { float4x4 View; float Time; };
Texture2D Tex; SamplerState Lin { Filter = MIN_MAG_MIP_LINEAR; AddressU = Clamp; };
BlendState Add { BlendEnable[0] = TRUE; SrcBlend = ONE; DestBlend = ONE; };
DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, View); }
float4 PS(float4 p : SV_Position) : SV_Target { return Tex.Sample(Lin, p.xy); }
technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(NULL);
  SetPixelShader(CompileShader(ps_4_0, PS())); SetBlendState(Add, float4(0,0,0,0), 0xFFFFFFFF);
  SetDepthStencilState(NoDepth, 0); } }
