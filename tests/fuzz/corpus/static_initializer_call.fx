// fxkit issue #32: a static initialised by a user function call (glslang crashed).
float3 f(float3 x) { return x * 2; }
float3 g(float3 x) { return x + 1; }
float a;
static const float3 K = f(float3(a, a, a));
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return float4(g(K), 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); } }
