struct { float4 c; } g;
typedef struct { float3 d; struct { float e; } f; } T;
T t;
float4 PS() : SV_Target { return g.c * t.f.e; }
technique10 X { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }
