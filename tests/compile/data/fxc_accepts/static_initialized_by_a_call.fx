// Rule: fxc runs a static global's initializer at the start of the shader, calls to the
// effect's functions included (fxkit issue #32: glslang crashed, or reported a false
// "Recursion detected", when the initializer called a user function).
float3 f(float3 x) { return x * 2; }
float3 g(float3 x) { return x + 1; }
float a;
static const float3 K = f(float3(a, a, a));
static const float3 L = K * 2, M = f(L);     // after K, and two declarators
static const float W[2] = { f(a).x, 3 };      // an array
float3 Tint = f(float3(1, 1, 1));             // a parameter: its default is the model's
float4 VS(float4 p : POSITION) : POSITION { return p * W[0] + float4(M, 0); }
float4 PS() : COLOR { return float4(g(K) + Tint, 1); }
float4 PS2() : COLOR { return float4(g(L), 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); } }
technique U { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS2(); } }
