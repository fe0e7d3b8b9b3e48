// Texture shaders' compute units: what the function reaches plus the generated entry,
// compiled through EffectPrograms (glslang in the compile workers' path), with the effect's
// globals in a uniform block and errors located in the function.
#include <gtest/gtest.h>

#include "fx/compile/effect_programs.h"
#include "fx/compile/texture_fill_unit.h"
#include "fx/compile/uniform_layout.h"
#include "fx/diagnostic_render.h"
#include "fx/frontend.h"
#include "fx/model/effect_model.h"

namespace fx {
namespace {

// An effect parsed, modelled and split into units, with a compiler for its programs.
struct Built {
  SourceManager sm;
  DiagnosticSink diags;
  ParsedEffect parsed;
  EffectModel model;
  std::unique_ptr<EffectUnits> units;
  ShaderCompiler compiler;
  std::unique_ptr<EffectPrograms> programs;
  const TextureShader& shader(std::string_view texture) const {
    return *model.texture_of(model.find_parameter(texture))->shader;
  }
};

std::unique_ptr<Built> build(std::string text) {
  auto b = std::make_unique<Built>();
  b->parsed = parse_effect_text("fill.fx", std::move(text), b->sm, b->diags);
  b->model = build_effect_model(b->parsed, b->sm, b->diags);
  b->units = std::make_unique<EffectUnits>(b->parsed.ast, b->sm, b->diags);
  b->programs = std::make_unique<EffectPrograms>(*b->units, b->compiler, b->sm);
  return b;
}

TEST(TextureFillUnit, TheStripeCompilesToAComputeProgramWritingItsTexels) {
  auto b = build(R"(texture stripeTex < string function = "MakeStripe"; float2 Dimensions = { 64, 32 }; >;
float4 MakeStripe(float2 Pos : POSITION, float ps : PSIZE) : COLOR {
   float v = 0; float nx = Pos.x+ps; v = nx > Pos.y; return float4(v.xxxx); }
)");
  ASSERT_FALSE(b->diags.has_errors()) << render_text(b->diags.diagnostics(), b->sm);
  const PassProgram& p = b->programs->texture_fill(b->shader("stripeTex"));
  ASSERT_EQ(p.stages.size(), 1u);
  EXPECT_TRUE(p.compiled) << render_text(p.stages[0].diagnostics, b->sm) << p.stages[0].unit.source;
  EXPECT_EQ(p.stages[0].stage, ShaderStage::compute);
  EXPECT_NE(p.stages[0].unit.source.find("MakeStripe(position.xy, texel_size.x)"), std::string::npos)
      << p.stages[0].unit.source;
  ASSERT_EQ(p.layout.bindings.size(), 1u);
  EXPECT_EQ(p.layout.bindings[0].kind, DescriptorKind::storage_buffer);
  EXPECT_EQ(p.layout.bindings[0].name, kTextureFillTexels);
  EXPECT_EQ(&b->programs->texture_fill(b->shader("stripeTex")), &p) << "compiled once";
}

TEST(TextureFillUnit, GlobalsItReadsAreAUniformBlockOverTheParameters) {
  auto b = build(R"(float Threshold = 0.5;
texture Ramp < string function = "Step"; >;
float4 Step(float2 p : POSITION) : COLOR { return p.x > Threshold ? 1 : 0; }
)");
  ASSERT_FALSE(b->diags.has_errors()) << render_text(b->diags.diagnostics(), b->sm);
  const PassProgram& p = b->programs->texture_fill(b->shader("Ramp"));
  ASSERT_TRUE(p.compiled) << render_text(p.stages[0].diagnostics, b->sm);
  const std::vector<UniformBlockLayout> blocks = uniform_layouts(b->model, p);
  ASSERT_EQ(blocks.size(), 1u);
  ASSERT_EQ(blocks[0].members.size(), 1u);
  EXPECT_EQ(blocks[0].members[0].slice.parameter, b->model.find_parameter("Threshold"));
  EXPECT_TRUE(blocks[0].unplaced.empty());
}

TEST(TextureFillUnit, ErrorsAreLocatedInTheFunction) {
  auto b = build(R"(texture Broken < string function = "Paint"; >;
float4 Paint(float2 p : POSITION) : COLOR {
  return float4(p, undeclared_name, 1); }
)");
  const PassProgram& p = b->programs->texture_fill(b->shader("Broken"));
  ASSERT_EQ(p.stages.size(), 1u);
  EXPECT_FALSE(p.compiled);
  const std::string text = render_text(p.stages[0].diagnostics, b->sm);
  EXPECT_NE(text.find("fill.fx:3:"), std::string::npos) << text;
  EXPECT_NE(text.find("undeclared_name"), std::string::npos) << text;
}

// tx_1_0's noise() (glslang 12 crashes on a call to `noise`) is fxkit's gradient noise in a
// texture shader's unit; a pass stage that calls it gets an error at the call, not a crash.
TEST(TextureFillUnit, NoiseIsDefinedForTextureShadersAndAnErrorElsewhere) {
  auto b = build(R"(texture Clouds < string function = "MakeClouds"; >;
float4 MakeClouds(float2 p : POSITION) : COLOR { return noise(p * 8) * 0.5 + 0.5 + noise(float3(p, 1)) * 0; }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return noise(uv); }
technique T { pass P { PixelShader = compile ps_3_0 PS(); } }
)");
  ASSERT_FALSE(b->diags.has_errors()) << render_text(b->diags.diagnostics(), b->sm);
  const PassProgram& fill = b->programs->texture_fill(b->shader("Clouds"));
  EXPECT_TRUE(fill.compiled) << render_text(fill.stages[0].diagnostics, b->sm) << fill.stages[0].unit.source;
  const PassProgram* pass = b->programs->program("T", "P");
  ASSERT_TRUE(pass);
  const StageProgram* pixel = pass->find(ShaderStage::fragment);
  ASSERT_TRUE(pixel);
  EXPECT_FALSE(pixel->shader.ok);
  const std::string text = render_text(pixel->diagnostics, b->sm);
  EXPECT_NE(text.find("fill.fx:3:"), std::string::npos) << text;
  EXPECT_NE(text.find("noise__tx_1_0"), std::string::npos) << text;
}

}  // namespace
}  // namespace fx
