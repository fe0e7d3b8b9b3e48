interface ILight { float4 Shade(float4 c); };
class Ambient : ILight { float4 a; float4 Shade(float4 c) { return a; } };
ILight slots[4];
Ambient instance;
technique11 T { pass P { } }
