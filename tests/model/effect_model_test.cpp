// The effect model: textures, samplers, techniques, passes, shader bindings.
#include <gtest/gtest.h>

#include "model_test_util.h"

namespace fx {
namespace {

TEST(EffectModel, SamplerStateD3D9) {
  auto b = test::build(R"(
    texture Diffuse < string ResourceName = "wood.png"; >;
    sampler2D DiffuseSampler = sampler_state {
      Texture = <Diffuse>; AddressU = Clamp; AddressV = Mirror; AddressW = Border;
      MinFilter = Anisotropic; MagFilter = Linear; MipFilter = Point; MaxAnisotropy = 8;
      MipMapLodBias = -0.5; MaxMipLevel = 2; BorderColor = 0xFF00FF00; SRGBTexture = TRUE;
    };
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  ASSERT_EQ(b->model.samplers.size(), 1u);
  const SamplerInfo& s = b->model.samplers[0];
  EXPECT_EQ(s.name, "DiffuseSampler");
  EXPECT_EQ(s.parameter, b->model.find_parameter("DiffuseSampler"));
  EXPECT_EQ(s.texture, b->model.find_parameter("Diffuse"));
  EXPECT_EQ(s.desc.address[0], AddressMode3::clamp_to_edge);
  EXPECT_EQ(s.desc.address[1], AddressMode3::mirrored_repeat);
  EXPECT_EQ(s.desc.address[2], AddressMode3::clamp_to_border);
  EXPECT_EQ(s.desc.min_filter, TexelFilter::linear);
  EXPECT_TRUE(s.desc.anisotropic);
  EXPECT_EQ(s.desc.max_anisotropy, 8u);
  EXPECT_EQ(s.desc.mip_filter, MipFilter::nearest);
  EXPECT_FLOAT_EQ(s.desc.lod_bias, -0.5f);
  EXPECT_EQ(s.desc.max_mip_level, 2u);
  EXPECT_TRUE(s.desc.srgb);
  EXPECT_FLOAT_EQ(s.desc.border_color[1], 1.0f);  // 0xFF00FF00: a=1, r=0, g=1, b=0
  EXPECT_FLOAT_EQ(s.desc.border_color[0], 0.0f);
  EXPECT_FLOAT_EQ(s.desc.border_color[3], 1.0f);
  EXPECT_EQ(b->model.texture_of(s.texture)->resource_name, "wood.png");
}

TEST(EffectModel, SamplerStateObjectD3D11) {
  auto b = test::build(R"(
    Texture2D Tex;
    SamplerState Lin { Filter = MIN_MAG_MIP_LINEAR; AddressU = Clamp; AddressV = Wrap; MaxLOD = 4; };
    SamplerComparisonState Shadow { Filter = COMPARISON_MIN_MAG_LINEAR_MIP_POINT; ComparisonFunc = LESS_EQUAL; };
    SamplerState Aniso { Filter = ANISOTROPIC; MaxAnisotropy = 16; };
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  ASSERT_EQ(b->model.samplers.size(), 3u);
  const SamplerDesc& lin = b->model.samplers[0].desc;
  EXPECT_EQ(lin.min_filter, TexelFilter::linear);
  EXPECT_EQ(lin.mag_filter, TexelFilter::linear);
  EXPECT_EQ(lin.mip_filter, MipFilter::linear);
  EXPECT_EQ(lin.address[0], AddressMode3::clamp_to_edge);
  EXPECT_EQ(lin.address[1], AddressMode3::repeat);
  EXPECT_EQ(lin.address[2], AddressMode3::clamp_to_edge);  // D3D11 default
  EXPECT_FLOAT_EQ(lin.max_lod, 4.0f);
  EXPECT_EQ(b->model.samplers[0].state_object, b->model.find_state_object("Lin"));
  const SamplerDesc& shadow = b->model.samplers[1].desc;
  EXPECT_TRUE(shadow.compare_enable);
  EXPECT_EQ(shadow.compare, CompareOp::less_or_equal);
  EXPECT_EQ(shadow.mip_filter, MipFilter::nearest);
  const SamplerDesc& aniso = b->model.samplers[2].desc;
  EXPECT_TRUE(aniso.anisotropic);
  EXPECT_EQ(aniso.max_anisotropy, 16u);
}

TEST(EffectModel, ProceduralTexture) {
  auto b = test::build(R"(
    texture StrandLUT < string Generator = "strand"; int Width = 256; float Exponent = 32; string UIName = "lut"; >;
    texture Bad < string Generator = "strnad"; >;
  )");
  const TextureInfo* t = b->model.texture_of(b->model.find_parameter("StrandLUT"));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->generator, "strand");
  ASSERT_TRUE(t->generator_params.find("width"));
  EXPECT_EQ(std::get<double>(*t->generator_params.find("Width")), 256);
  EXPECT_EQ(std::get<double>(*t->generator_params.find("exponent")), 32);
  EXPECT_TRUE(b->has("unknown-generator")) << b->text();
}

// fx_4_0 takes 0 for NULL in a shader state (SharpDX's MiniTri: `SetGeometryShader( 0 );`); any
// other number is still no shader.
TEST(EffectModel, ZeroIsANullShader) {
  auto b = test::build(R"(
    float4 VS(float4 p : POSITION) : SV_Position { return p; }
    float4 PS() : SV_Target { return 1; }
    technique10 T { pass { SetGeometryShader( 0 ); SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
  )",
                       true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(b->model.find_technique("T")->passes[0].shader(PassStage::geometry)->source, ShaderSource::null);
  auto one = test::build(R"(
    technique10 T { pass { SetGeometryShader( 1 ); } }
  )",
                         true);
  EXPECT_TRUE(one->diags.has_errors());
}

TEST(EffectModel, TechniquesPassesAndShaders) {
  auto b = test::build(R"(
    float4x4 WorldViewProj : WorldViewProjection;
    float4 VS(float4 p : POSITION, uniform bool skin, uniform int lights) : POSITION { return mul(p, WorldViewProj); }
    float4 PS() : COLOR { return 1; }
    VertexShader vsArray[2] = { compile vs_2_0 VS(false, 1), compile vs_2_0 VS(true, 2) };
    PixelShader ps = compile ps_2_0 PS();
    technique Lit < string Scheme = "quality"; > {
      pass P0 < int Order = 1; > { VertexShader = (vsArray[1]); PixelShader = (ps); CullMode = None; }
      pass P1 { VertexShader = compile vs_1_1 VS(true, 3); PixelShader = asm { ps_1_1 tex t0 mov r0, t0 }; ColorOp[0] = Modulate; }
    }
    technique10 T10 { pass { SetVertexShader(CompileShader(vs_4_0, VS(false, 0))); SetGeometryShader(NULL); SetPixelShader(CompileShader(ps_4_0, PS())); } }
  )",
                       true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  ASSERT_EQ(b->model.techniques.size(), 2u);
  const TechniqueInfo& lit = *b->model.find_technique("Lit");
  EXPECT_EQ(find_annotation(lit.annotations, "Scheme")->value.text, "quality");
  ASSERT_EQ(lit.passes.size(), 2u);
  const PassInfo& p0 = lit.passes[0];
  EXPECT_EQ(find_annotation(p0.annotations, "Order")->value.number(), 1);
  const ShaderBinding* vs = p0.shader(PassStage::vertex);
  ASSERT_TRUE(vs);
  EXPECT_EQ(vs->source, ShaderSource::hlsl_compile);
  EXPECT_EQ(vs->profile, "vs_2_0");
  EXPECT_EQ(vs->entry, "VS");
  EXPECT_EQ(vs->variable, "vsArray");
  ASSERT_EQ(vs->args.size(), 2u);
  EXPECT_EQ(vs->args[0].number(), 1);
  EXPECT_EQ(vs->args[1].number(), 2);
  EXPECT_EQ(p0.shader(PassStage::pixel)->entry, "PS");
  EXPECT_EQ(p0.summary.cull, CullMode::none);
  EXPECT_TRUE(p0.unsupported.empty());
  const PassInfo& p1 = lit.passes[1];
  EXPECT_EQ(p1.shader(PassStage::vertex)->args[1].number(), 3);
  EXPECT_EQ(p1.shader(PassStage::pixel)->source, ShaderSource::asm_block);
  EXPECT_FALSE(p1.shader(PassStage::pixel)->asm_code.empty());
  // ColorOp beside a pixel shader: D3D9 ignores it, so it is no reason the pass cannot run.
  EXPECT_TRUE(p1.unsupported.empty());
  const TechniqueInfo& t10 = *b->model.find_technique("T10");
  EXPECT_EQ(t10.version, 10);
  const PassInfo& q = t10.passes[0];
  EXPECT_EQ(q.shader(PassStage::vertex)->profile, "vs_4_0");
  EXPECT_EQ(q.shader(PassStage::vertex)->args.size(), 2u);
  EXPECT_EQ(q.shader(PassStage::geometry)->source, ShaderSource::null);
  EXPECT_EQ(q.shader(PassStage::pixel)->entry, "PS");
  EXPECT_EQ(test::param(*b, "WorldViewProj").semantic, "WorldViewProjection");
}

TEST(EffectModel, GlslBlocks) {
  auto b = test::build(R"(
    GLSLShader Common { vec3 shade(vec3 n) { return n * 0.5 + 0.5; } }
    GLSLShader FS { layout(location = 0) out vec4 color; void main() { color = vec4(shade(vec3(1)), 1); } }
    technique Glsl { pass { PixelShader = { Common, FS }; } }
  )",
                       true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const ShaderBinding* ps = b->model.techniques[0].passes[0].shader(PassStage::pixel);
  ASSERT_TRUE(ps);
  EXPECT_EQ(ps->source, ShaderSource::glsl_blocks);
  EXPECT_EQ(ps->glsl_blocks, (std::vector<std::string>{"Common", "FS"}));
}

TEST(EffectModel, StateReferencesAndConstants) {
  auto b = test::build(R"(
    float4x4 mWorldT; float4 vLight = {0, 1, 0, 0}; texture NormalMap; int RefValue = 128;
    technique T { pass P {
      VertexShaderConstant[0] = <mWorldT>;
      VertexShaderConstant[20] = (.5f, .5f, .5f, .5f);
      Texture[1] = <NormalMap>;
      AlphaRef = <RefValue>;
      AlphaTestEnable = TRUE; AlphaFunc = Greater;
    } }
  )",
                       true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const PassInfo& p = b->model.techniques[0].passes[0];
  ASSERT_EQ(p.states.size(), 6u);
  EXPECT_EQ(p.states[0].kind, StateValueKind::parameter);
  EXPECT_EQ(p.states[0].target, b->model.find_parameter("mWorldT"));
  EXPECT_EQ(p.states[1].index, 20u);
  EXPECT_EQ(p.states[1].kind, StateValueKind::vector);
  EXPECT_FLOAT_EQ(p.states[1].vector[3], 0.5f);
  EXPECT_EQ(p.states[2].index, 1u);
  EXPECT_EQ(p.states[2].target, b->model.find_parameter("NormalMap"));
  EXPECT_EQ(p.states[3].kind, StateValueKind::parameter);
  EXPECT_TRUE(p.summary.alpha_test);
  EXPECT_EQ(p.summary.alpha_ref, 128u);
  EXPECT_EQ(p.summary.alpha_compare, CompareOp::greater);
}

TEST(EffectModel, BadStateReferences) {
  auto b = test::build(R"(
    float4 v; texture tex;
    technique T { pass P { Texture[0] = <v>; } }
    technique10 U { pass Q { SetBlendState(Missing, float4(0,0,0,0), 0xFFFFFFFF); } }
  )",
                       true);
  EXPECT_TRUE(b->has("state-type-mismatch") || b->has("undefined-reference")) << b->text();
  EXPECT_TRUE(b->diags.has_errors());
}

}  // namespace
}  // namespace fx
