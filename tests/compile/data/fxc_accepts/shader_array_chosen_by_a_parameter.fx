// Rule: a pass may take its shaders from shader arrays indexed by parameters (the XNA stock
// effects choose their permutations so). Every element is a shader of the effect; the pass
// compiles the one the index selects with the parameters' initial values.
float4x4 WorldViewProj;
float4 DiffuseColor = 1;
float3 FogColor;

struct VSOut { float4 pos : POSITION; float4 color : COLOR0; float fog : TEXCOORD0; };

VSOut VSBasic(float4 pos : POSITION) { VSOut o; o.pos = mul(pos, WorldViewProj); o.color = DiffuseColor; o.fog = 0; return o; }
VSOut VSFog(float4 pos : POSITION) { VSOut o = VSBasic(pos); o.fog = saturate(o.pos.z / 100); return o; }
VSOut VSVertexColor(float4 pos : POSITION, float4 color : COLOR0) { VSOut o = VSBasic(pos); o.color *= color; return o; }

float4 PSBasic(VSOut i) : COLOR0 { return i.color; }
float4 PSFog(VSOut i) : COLOR0 { return float4(lerp(i.color.rgb, FogColor, i.fog), i.color.a); }

VertexShader VSArray[3] = { compile vs_2_0 VSBasic(), compile vs_2_0 VSFog(), compile vs_2_0 VSVertexColor() };
PixelShader PSArray[2] = { compile ps_2_0 PSBasic(), compile ps_2_0 PSFog() };

int VSIndices[4] = { 0, 1, 2, 1 };
int PSIndices[4] = { 0, 1, 0, 1 };
int ShaderIndex = 3;

technique Permutations {
  pass {
    VertexShader = (VSArray[VSIndices[ShaderIndex]]);
    PixelShader = (PSArray[PSIndices[ShaderIndex]]);
  }
}
