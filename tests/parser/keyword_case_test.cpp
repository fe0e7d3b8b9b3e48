// Effect keywords in any case (the D3DX effect lexer matches them so; the XNA stock
// effects write `Technique` and `Pass`), and the rule that such a keyword names nothing.
#include <gtest/gtest.h>

#include <string>

#include "parse_helpers.h"

using namespace fx;
using fxtest::parse;
using fxtest::var;

namespace {

TEST(KeywordCase, EffectKeywordsInAnyCase) {
  auto p = parse(
      "VertexShader vs = COMPILE vs_2_0 VS();\n"
      "sampler s = Sampler_State { MinFilter = Linear; };\n"
      "Technique T { Pass { VertexShader = Compile vs_2_0 VS(); } PASS P1 { } }\n"
      "technique10 T10 { pass { } }\n"
      "technique11 T11 { pass { } }\n");
  EXPECT_EQ(p->text(), "");
  ASSERT_EQ(p->effect.decls.size(), 5u);
  EXPECT_EQ(var(*p, 0).initializer->kind, ast::ExprKind::compile);
  EXPECT_EQ(var(*p, 1).initializer->kind, ast::ExprKind::state_block);
  const ast::Technique& t = *p->decl(2).technique;
  EXPECT_EQ(t.version, 9);
  ASSERT_EQ(t.passes.size(), 2u);
  EXPECT_EQ(t.passes[0].name, "");  // a pass without a name is allowed
  EXPECT_EQ(t.passes[0].states[0].value->kind, ast::ExprKind::compile);
  EXPECT_EQ(t.passes[1].name, "P1");
  EXPECT_EQ(p->decl(3).technique->version, 10);
  EXPECT_EQ(p->decl(4).technique->version, 11);
}

// HLSL's own keywords are case-sensitive: `Float` and `Struct` are ordinary names.
TEST(KeywordCase, HlslKeywordsStayCaseSensitive) {
  auto p = parse("float Float; int Struct; float4 Return(float4 If) { return If; }\n");
  EXPECT_EQ(p->text(), "");
  EXPECT_EQ(var(*p, 0).name, "Float");
}

TEST(KeywordCase, KeywordCannotNameAnything) {
  auto p = parse("float Pass;\n");
  EXPECT_EQ(p->text(),
            "test.fx:1:7: error: 'Pass' is an effect keyword (in any case) and cannot name a "
            "variable [keyword-as-name]\n"
            "float Pass;\n"
            "      ^~~~\n");
  const char* cases[] = {"float4 a, COMPILE;",
                         "technique technique11 { }",
                         "technique T { pass Pass { } }",
                         "float4 VertexShader(float4 p) { return p; }",
                         "float4 F(float sampler_state) { return 0; }",
                         "struct Stateblock { float a; };",
                         "float x < int PixelShader = 1; >;",
                         "struct S { float4 stateblock_state; };",
                         "typedef float technique10;"};
  for (const char* source : cases) {
    auto q = parse(std::string(source) + "\nfloat after;\n");
    ASSERT_EQ(q->diags.diagnostics().size(), 1u) << source << "\n" << q->text();
    EXPECT_EQ(q->diags.diagnostics()[0].id, "keyword-as-name") << source;
    // Recovery goes on with the next declaration.
    EXPECT_EQ(q->effect.decls.back().kind, ast::DeclKind::variable) << source;
  }
}

// technique10 and technique11 are keywords in lower case only: fxc rejects `tEchnique10 { }`
// and takes `float4 technIque10;` and `typedef float4 Technique11;` (vkd3d's
// effect-technique-fx_4/fx_5 tests, which record what the native compiler does).
TEST(KeywordCase, TechniqueTenAndElevenOnlyInLowerCase) {
  auto p = parse("float4 technIque10; typedef float4 Technique11;\ntechnique10 T { pass { } }\n");
  EXPECT_EQ(p->text(), "");
  EXPECT_EQ(var(*p, 0).name, "technIque10");
  EXPECT_EQ(p->decl(2).technique->version, 10);
  auto q = parse("tEchnique10 T { pass { } }\n");
  EXPECT_TRUE(q->diags.has_errors()) << q->text();
}

}  // namespace
