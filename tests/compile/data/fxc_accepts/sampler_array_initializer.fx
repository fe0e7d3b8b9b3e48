// Rule: an array of D3D9 samplers is initialized with one sampler_state per element; the
// states are the effect's, so the shader declaration keeps only the array.
texture Tex0;
texture Tex1;
sampler Samplers[2] = {
  sampler_state { Texture = <Tex0>; MinFilter = Linear; },
  sampler_state { Texture = <Tex1>; MinFilter = Point; },
};

float4 VS(float4 p : POSITION, inout float2 uv : TEXCOORD0) : POSITION { return p; }

float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(Samplers[0], uv) + tex2D(Samplers[1], uv); }

technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
