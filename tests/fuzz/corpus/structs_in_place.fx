struct Inner { float a; };
struct Outer { struct { float foo; } anonymous; struct Named { float baz; struct Inner deeper; } named[2]; };
cbuffer B { struct { float2 v1; } block; };
struct Inner top;
float4 source[4];
static float2 packed[8] = (float2[8])source;
technique10 T { pass P { } }
