// Effect-level rules of the native compiler where a lax front end would accept what fxc
// rejects (issue 17): annotation declarations, techniques in fx_2_0, objects in struct
// parameters, fxgroup's profile. Each finding is located and has a stable id.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "front_end_helpers.h"

namespace fx {
namespace {

using fxtest::run_front_end;

using Ids = std::vector<std::string>;
constexpr const char* kTechnique = "technique T { pass P { } }\n";

TEST(FxcRules, AnnotationsTakeCommaSeparatedDeclarators) {
  auto f = run_front_end(std::string("float x < int a = 1, b = 2; string s = \"x\", t = \"y\"; >;\n") + kTechnique);
  EXPECT_EQ(f->text(), "");
  const ast::List<ast::Annotation>& a = f->parsed.ast.decls.at(0).variable->annotations;
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[1].name, "b");
  EXPECT_EQ(a[1].type.name, "int");
  EXPECT_EQ(a[1].value->number, 2);
  EXPECT_EQ(a[3].type.name, "string");
  EXPECT_EQ(f->sm.presumed(a[1].range.begin).column, 22u);  // `b`, not `int`
}

TEST(FxcRules, AnnotationsAreLiteralsOfNumericBoolOrStringType) {
  auto f = run_front_end(std::string("float x < static int a = 1; >;\n") + kTechnique);
  EXPECT_EQ(f->text(),
            "t.fx:1:11: error: annotation 'a' cannot be 'static' [annotation-static]\n"
            "float x < static int a = 1; >;\n"
            "          ^~~~~~~~~~~~~~~~\n");
  auto g = run_front_end(std::string("float x < int a = 1; int b = a + 1; >;\n") + kTechnique);
  EXPECT_EQ(g->text(),
            "t.fx:1:30: error: annotation 'b' refers to annotation 'a'; an annotation's value "
            "cannot use another annotation [annotation-reference]\n"
            "float x < int a = 1; int b = a + 1; >;\n"
            "                             ^\n");
  auto h = run_front_end(std::string("float x < texture t = 0; float4x4 m = 0; bool b = true; vector v = 1; >;\n") +
                         kTechnique);
  EXPECT_EQ(h->ids(), Ids{"annotation-type"}) << h->text();
  EXPECT_EQ(h->diags.diagnostics()[0].message,
            "annotation 't' has type 'texture'; annotations take numeric, bool and string types");
}

TEST(FxcRules, Fx20EffectNeedsATechnique) {
  auto f = run_front_end("float4 c;\n", EffectProfile::fx_2_0);
  ASSERT_EQ(f->ids(), Ids{"no-technique"});
  EXPECT_EQ(f->diags.diagnostics()[0].severity, Severity::error);
  // An inferred profile does not say the file is compiled as an effect (shader files and
  // libraries have no technique), and FX10/11 pools need none.
  EXPECT_EQ(run_front_end("float4 c;\n")->diags.diagnostics().at(0).severity, Severity::warning);
  EXPECT_EQ(run_front_end("cbuffer B { float4 c; };\n", EffectProfile::fx_4_0)->diags.diagnostics().at(0).severity,
            Severity::warning);
}

TEST(FxcRules, StructParametersHoldNoObjects) {
  auto f = run_front_end(std::string("struct Material { float4 colour; texture diffuse; };\n"
                                     "struct Surface { float gloss; Material layers[2]; };\n"
                                     "Material m;\nSurface s;\nstatic Material local;\n"
                                     "struct Plain { float4 a; };\nPlain p;\n") +
                         kTechnique);
  ASSERT_EQ(f->ids(), (Ids{"object-in-struct", "object-in-struct"})) << f->text();
  EXPECT_EQ(f->diags.diagnostics()[0].message,
            "parameter 'm' is a struct holding the object member diffuse (texture); an effect "
            "parameter's struct cannot hold objects");
  EXPECT_EQ(f->diags.diagnostics()[1].message,
            "parameter 's' is a struct holding the object member layers.diffuse (texture); an "
            "effect parameter's struct cannot hold objects");
}

// fxc refuses an fxgroup without techniques (vkd3d's effect-technique-fx_5 tests: "Group
// can't be empty").
TEST(FxcRules, FxGroupHoldsATechnique) {
  auto f = run_front_end("fxgroup G { }\ntechnique11 T { pass P { } }\n", EffectProfile::fx_5_0);
  EXPECT_EQ(f->ids(), (Ids{"empty-fxgroup"})) << f->text();
  EXPECT_EQ(f->diags.diagnostics()[0].message, "fxgroup 'G' holds no technique; fxc refuses an empty group");
}

// Direct3D 10.0's blend state has one factor and operation for every target: fxc's fx_4_0
// refuses `SrcBlend[0]`, fx_4_1 and fx_5_0 take it (vkd3d's effect-variables-fx_4/fx_4_1
// tests); BlendEnable and RenderTargetWriteMask are per target in every profile.
TEST(FxcRules, PerTargetBlendFactorsFromFx41) {
  const char* source =
      "BlendState B { BlendEnable[1] = TRUE; SrcBlend[1] = One; RenderTargetWriteMask[2] = 15; };\n"
      "technique10 T { pass P { } }\n";
  auto f = run_front_end(source, EffectProfile::fx_4_0);
  EXPECT_EQ(f->ids(), (Ids{"state-not-indexable"})) << f->text();
  EXPECT_EQ(run_front_end(source, EffectProfile::fx_4_1)->text(), "");
  EXPECT_EQ(run_front_end(source, EffectProfile::fx_5_0)->text(), "");
}

// fxc folds a literal index into a parameter array in a state value and refuses one past
// its end (vkd3d's effect-assignments-fx_5 tests).
TEST(FxcRules, LiteralIndexIntoAParameterArrayInRange) {
  auto f = run_front_end(
      "uint refs[2];\ntechnique11 T { pass P { SetDepthStencilState(NULL, refs[10]); } }\n"
      "technique11 U { pass P { SetDepthStencilState(NULL, refs[1]); } }\n",
      EffectProfile::fx_5_0);
  EXPECT_EQ(f->ids(), (Ids{"array-index-out-of-range"})) << f->text();
  EXPECT_EQ(f->diags.diagnostics()[0].message, "index 10 is out of range for 'refs' (2 elements)");
}

// fxc takes annotations on globals only (vkd3d's effect-annotations tests); a comparison
// in a function is no annotation.
TEST(FxcRules, NoAnnotationsOnLocals) {
  auto f = run_front_end(
      "float4 g < int a = 1; >;\nfloat4 F(float x) { float v < int a = 1; > = 0; bool b = x < v; return b; }\n"
      "technique T { pass P { } }\n");
  EXPECT_EQ(f->ids(), (Ids{"annotation-on-local"})) << f->text();
  EXPECT_EQ(f->diags.diagnostics()[0].message,
            "annotations are allowed on global variables only; fxc refuses them on the local 'v'");
}

// A constant expression that folds to 0 stands for NULL where an object is expected, as
// the literal 0 does (vkd3d's effect-pass-states-fx_5 tests: `SetRasterizerState(1-1)`).
TEST(FxcRules, ZeroExpressionIsNull) {
  auto f = run_front_end(
      "technique11 T { pass P { SetRasterizerState(1-1); SetHullShader(1-1); SetGeometryShader(0u); } }\n"
      "technique11 U { pass P { SetRasterizerState(2-1); } }\n",
      EffectProfile::fx_5_0);
  EXPECT_EQ(f->ids(), (Ids{"state-type-mismatch"})) << f->text();
}

TEST(FxcRules, FxGroupNeedsFx50) {
  auto f = run_front_end("fxgroup G { technique11 T { pass P { } } }\n", EffectProfile::fx_4_0);
  EXPECT_EQ(f->ids(), (Ids{"profile-mismatch"})) << f->text();
  EXPECT_EQ(run_front_end("fxgroup G { technique11 T { pass P { } } }\n")->text(), "");
}

}  // namespace
}  // namespace fx
