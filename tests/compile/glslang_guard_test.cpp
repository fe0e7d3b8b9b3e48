// What the effect compiler keeps from glslang (fxkit issue #32): nothing of an effect whose
// front end failed, no #define, and a static initialised by a function call run in each
// entry point's prologue instead of at global scope, where glslang crashed.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "fx/compile/effect_units.h"
#include "fx/frontend.h"

namespace fx {
namespace {

struct Units {
  SourceManager sm;
  DiagnosticSink diags;
  ParsedEffect parsed;
  std::unique_ptr<EffectUnits> units;
};

std::unique_ptr<Units> build(std::string text) {
  auto u = std::make_unique<Units>();
  FrontEndOptions options;
  options.preprocessor.defines = {parse_define("SCALE=2")};
  u->parsed = parse_effect_text("g.fx", std::move(text), u->sm, u->diags, options);
  u->units = std::make_unique<EffectUnits>(u->parsed.ast, u->sm, u->diags);
  return u;
}

constexpr const char* kIssue32 = R"(float3 f(float3 x) { return x * SCALE; }
float3 g(float3 x) { return x + 1; }
float a;
static const float3 K = f(float3(a, a, a));
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return float4(g(K), 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

TEST(GlslangGuard, StaticInitializedByACallRunsInTheEntryPrologue) {
  auto u = build(kIssue32);
  ASSERT_FALSE(u->diags.has_errors());
  const EffectPass& pass = u->units->passes().at(0);
  std::optional<TranslationUnit> ps = u->units->unit(*pass.find(ShaderStage::fragment));
  ASSERT_TRUE(ps);
  const std::string& s = ps->source;
  EXPECT_TRUE(ps->defines.empty());
  EXPECT_EQ(s.find("#define"), std::string::npos) << s;
  // Declared without const and initializer; assigned first thing in PS, from a local.
  const size_t at = s.find("static");
  ASSERT_NE(at, std::string::npos) << s;
  const std::string declaration = s.substr(at, s.find('\n', at) - at);
  EXPECT_NE(declaration.find("float3 K"), std::string::npos) << declaration;
  EXPECT_EQ(declaration.find("const"), std::string::npos) << declaration;
  EXPECT_EQ(declaration.find('='), std::string::npos) << declaration;
  const size_t body = s.find("float4 PS()"), init = s.find("K__fx_init = f(float3(a, a, a));");
  const size_t assign = s.find("K = K__fx_init;"), use = s.find("g(K)");
  ASSERT_NE(init, std::string::npos) << s;
  EXPECT_LT(body, init);
  EXPECT_LT(init, assign);
  EXPECT_LT(assign, use);
  // The vertex shader does not reach K: no initialization there.
  std::optional<TranslationUnit> vs = u->units->unit(*pass.find(ShaderStage::vertex));
  ASSERT_TRUE(vs);
  EXPECT_EQ(vs->source.find("K__fx_init"), std::string::npos) << vs->source;
}

TEST(GlslangGuard, UncalledCheckUnitRunsTheInitializations) {
  std::string text = kIssue32;
  const std::string pixel_shader = " PixelShader = compile ps_3_0 PS();";
  text.replace(text.find(pixel_shader), pixel_shader.size(), "");
  auto u = build(text);
  const StageUnit* check = u->units->uncalled_check();
  ASSERT_NE(check, nullptr);
  std::optional<TranslationUnit> unit = u->units->unit(*check);
  ASSERT_TRUE(unit);
  const size_t entry = unit->source.find("void uncalled__fx() {");
  ASSERT_NE(entry, std::string::npos) << unit->source;
  EXPECT_NE(unit->source.find("K = K__fx_init;", entry), std::string::npos) << unit->source;
}

TEST(GlslangGuard, NothingOfAFailedFrontEndIsCompiled) {
  std::string text = kIssue32;
  text.replace(text.find("return p;"), 8, "return p ## p");
  auto u = build(text);
  ASSERT_TRUE(u->parsed.ast.front_end_failed);
  for (const EffectPass& pass : u->units->passes())
    for (const StageUnit& stage : pass.stages) {
      EXPECT_FALSE(u->units->unit(stage)) << to_string(stage.stage);
      EXPECT_EQ(stage.unsupported, "the effect has front-end errors");
    }
  EXPECT_EQ(u->units->uncalled_check(), nullptr);
}

}  // namespace
}  // namespace fx
