// Forms that fxc accepts in real effect files (issue 17): each must preprocess, parse and
// check with no diagnostic, and come out as the syntax tree says.
#include <gtest/gtest.h>

#include <string>

#include "front_end_helpers.h"

namespace fx {
namespace {

using fxtest::run_front_end;

#define EXPECT_CLEAN(f) EXPECT_EQ((f)->text(), "") << "unexpected diagnostics"

TEST(EffectForms, SharedConstantBuffer) {
  auto f = run_front_end(
      "shared cbuffer Pool { float4 Shared; };\n"
      "cbuffer Own { float4 Mine; }\n"
      "technique10 T { pass P { } }\n");
  EXPECT_CLEAN(f);
  ASSERT_EQ(f->decl(0).kind, ast::DeclKind::constant_buffer);
  const ast::ConstantBuffer& pool = *f->decl(0).constant_buffer;
  EXPECT_TRUE(pool.shared);
  EXPECT_EQ(pool.name, "Pool");
  // The shader compiler's tokens start at `cbuffer`; the range covers `shared`.
  EXPECT_EQ(f->parsed.ast.tokens.at(pool.tokens.first).text(), "cbuffer");
  EXPECT_EQ(f->sm.presumed(pool.range.begin).column, 1u);
  EXPECT_FALSE(f->decl(1).constant_buffer->shared);
}

TEST(EffectForms, NormalisedResourceElements) {
  auto f = run_front_end(
      "struct S { snorm float a; unorm float4 b; };\n"
      "Buffer<unorm float4> Colours;\n"
      "technique10 T { pass P { } }\n");
  EXPECT_CLEAN(f);
  const ast::Struct& s = *f->decl(0).structure;
  EXPECT_EQ(s.members[0].storage, uint32_t(ast::kSnorm));
  EXPECT_EQ(s.members[1].storage, uint32_t(ast::kUnorm));
  EXPECT_EQ(s.members[1].type.name, "float4");
}

TEST(EffectForms, IndexedParameterReference) {
  auto f = run_front_end(
      "float4 g_vLightPos[2]; float4x4 m[2];\n"
      "technique T { pass P { LightPosition[0] = <g_vLightPos[1]>;\n"
      "  VertexShaderConstant4[0] = <m[0]>; } }\n");
  EXPECT_CLEAN(f);
  const ast::Expr& value = *f->decl(2).technique->passes[0].states[0].value;
  ASSERT_EQ(value.kind, ast::ExprKind::index);
  ASSERT_EQ(value.args.size(), 2u);
  EXPECT_EQ(value.args[0]->kind, ast::ExprKind::reference);
  EXPECT_EQ(value.args[0]->text, "g_vLightPos");
  EXPECT_EQ(value.args[1]->number, 1);
  auto g = run_front_end("technique T { pass P { LightPosition[0] = <missing[0]>; } }\n");
  ASSERT_EQ(g->ids(), std::vector<std::string>{"undefined-reference"}) << g->text();
}

TEST(EffectForms, StateBlockInAPass) {
  auto f = run_front_end(
      "stateblock Opaque = stateblock_state { CullMode = None; ZWriteEnable = false; };\n"
      "technique T { pass { StateBlock = <Opaque>; } }\n");
  EXPECT_CLEAN(f);
  // Only a stateblock variable will do.
  auto g = run_front_end("float4 c;\ntechnique T { pass { StateBlock = <c>; } }\n");
  ASSERT_EQ(g->ids(), std::vector<std::string>{"state-type-mismatch"}) << g->text();
}

// An array of state objects with one initializer per element, each checked on its own:
// the same state in two elements is no duplicate, a wrong value in one still is an error.
TEST(EffectForms, StateObjectArrayWithElementInitializers) {
  auto f = run_front_end(
      "int i;\n"
      "BlendState Blends[3] { { BlendOp = Add; }, { BlendOp = Subtract; }, { BlendOp = Rev_Subtract; } };\n"
      "DepthStencilState Depths[2] { { DepthFunc = 1; }, { DepthFunc = i + 2; }, };\n"
      "technique10 T { pass P { SetBlendState(Blends[i * 2 + 1], float4(0, 0, 0, 0), 0xFFFFFFFF);\n"
      "  SetDepthStencilState(Depths[i], 0); } }\n");
  EXPECT_CLEAN(f);
  const ast::StateObject& blends = *f->decl(1).state_object;
  EXPECT_TRUE(blends.states.empty());
  ASSERT_EQ(blends.element_states.size(), 3u);
  EXPECT_EQ(blends.element_states[2][0].name, "BlendOp");
  EXPECT_EQ(blends.element_states[2][0].value->text, "Rev_Subtract");
  EXPECT_EQ(f->decl(2).state_object->element_states.size(), 2u);
  auto g = run_front_end(
      "BlendState B[2] { { BlendOp = Add; }, { BlendOp = Sum; } };\n"
      "technique10 T { pass P { } }\n");
  ASSERT_EQ(g->ids(), std::vector<std::string>{"unknown-state-value"}) << g->text();
  auto h = run_front_end("BlendState B[2] { { BlendOp = Add; } { BlendOp = Add; } };\nfloat after;\n");
  EXPECT_EQ(h->diags.diagnostics().at(0).id, "expected-token") << h->text();
}

// Structs written in place as a member's type, named or anonymous, nested, in a struct or
// a cbuffer; and the C spelling `struct Name` of a struct type.
TEST(EffectForms, StructsDefinedInPlace) {
  auto f = run_front_end(
      "struct Inner { float a; };\n"
      "struct Outer {\n"
      "  struct { float foo; float bar; } anonymous;\n"
      "  struct Named { float baz; struct Inner deeper; } named[2];\n"
      "};\n"
      "cbuffer B { struct { float2 v1; float2 v2; } block; float after; };\n"
      "struct Inner top;\n"
      "technique10 T { pass P { } }\n");
  EXPECT_CLEAN(f);
  const ast::Struct& outer = *f->decl(1).structure;
  ASSERT_EQ(outer.members.size(), 2u);
  const ast::TypeRef& anonymous = outer.members[0].type;
  EXPECT_EQ(anonymous.name, "");
  ASSERT_NE(anonymous.definition, nullptr);
  EXPECT_EQ(anonymous.definition->members.size(), 2u);
  const ast::Variable& named = outer.members[1];
  EXPECT_EQ(named.name, "named");
  EXPECT_EQ(named.type.name, "Named");
  EXPECT_EQ(named.array_dims.size(), 1u);
  EXPECT_EQ(named.type.definition->members[1].type.name, "Inner");
  EXPECT_EQ(f->decl(2).constant_buffer->members.size(), 2u);
  ASSERT_EQ(f->decl(3).kind, ast::DeclKind::variable);
  EXPECT_EQ(f->decl(3).variable->type.name, "Inner");
}

TEST(EffectForms, ArrayCasts) {
  auto f = run_front_end(
      "float4 source[16];\n"
      "static float2 packed[32] = (float2[32])source;\n"
      "float2 two[2] = (float2[2])float4(1, 2, 3, 4);\n"
      "technique T { pass P { } }\n");
  EXPECT_CLEAN(f);
  const ast::Expr& cast = *f->decl(1).variable->initializer;
  ASSERT_EQ(cast.kind, ast::ExprKind::cast);
  EXPECT_EQ(cast.text, "float2[32]");
  EXPECT_EQ(cast.args[0]->text, "source");
  // A parenthesised index is still no cast.
  auto g = run_front_end("float a[2]; float b = (a[1]) + 1;\ntechnique T { pass P { } }\n");
  EXPECT_CLEAN(g);
  EXPECT_EQ(g->decl(1).variable->initializer->kind, ast::ExprKind::binary);
}

// fx_5_0 dynamic linkage: interfaces, classes implementing them, and their instances.
TEST(EffectForms, InterfacesAndClasses) {
  auto f = run_front_end(
      "interface ILight { float4 Shade(float4 c); float4 Tint(float4 c); };\n"
      "interface IScale { float Scale(); };\n"
      "class Ambient : ILight, IScale {\n"
      "  float4 a;\n"
      "  float4 Shade(float4 c) { return a; }\n"
      "  float4 Tint(float4 c) { return c * a; }\n"
      "  float Scale() { return 2; }\n"
      "};\n"
      "ILight slots[4];\n"
      "Ambient instance;\n"
      "technique11 T { pass P { } }\n");
  EXPECT_CLEAN(f);
  const ast::Struct& light = *f->decl(0).structure;
  EXPECT_EQ(light.kind, ast::StructKind::interface_type);
  ASSERT_EQ(light.methods.size(), 2u);
  EXPECT_TRUE(light.methods[0].body.empty());  // prototypes
  const ast::Struct& ambient = *f->decl(2).structure;
  EXPECT_EQ(ambient.kind, ast::StructKind::class_type);
  ASSERT_EQ(ambient.bases.size(), 2u);
  EXPECT_EQ(ambient.bases[1], "IScale");
  ASSERT_EQ(ambient.members.size(), 1u);
  EXPECT_EQ(ambient.members[0].name, "a");
  ASSERT_EQ(ambient.methods.size(), 3u);
  EXPECT_EQ(ambient.methods[1].name, "Tint");
  EXPECT_FALSE(ambient.methods[1].body.empty());
  EXPECT_EQ(infer_profile(f->parsed.ast), EffectProfile::fx_5_0);
  // Older profiles have no dynamic linkage.
  auto g = run_front_end("interface I { float4 F(float4 c); };\ntechnique10 T { pass P { } }\n", EffectProfile::fx_4_0);
  ASSERT_EQ(g->ids(), std::vector<std::string>{"profile-mismatch"}) << g->text();
}

// A method defined after its class (`float3 Ambient::Shade(...) { }`) completes the
// class's prototype: the class's method gets the body and says where it was defined.
TEST(EffectForms, MethodsDefinedOutsideTheirClass) {
  auto f = run_front_end(
      "interface ILight { float3 Shade(float3 n); };\n"
      "class Ambient : ILight {\n"
      "  float3 color;\n"
      "  float3 Shade(float3 n);\n"
      "  float3 Shade(float4 n);\n"
      "};\n"
      "float3 Ambient::Shade(float4 n) { return color * n.w; }\n"
      "float3 Ambient::Shade(float3 n) { return color * n.x; }\n"
      "technique11 T { pass P { } }\n");
  EXPECT_CLEAN(f);
  ASSERT_EQ(f->parsed.ast.decls.size(), 3u) << "the definitions are no file-scope declarations";
  const ast::Struct& ambient = *f->decl(1).structure;
  ASSERT_EQ(ambient.methods.size(), 2u);
  for (const ast::Function& m : ambient.methods) {
    EXPECT_EQ(m.owner, "Ambient");
    EXPECT_FALSE(m.body.empty());
    EXPECT_FALSE(m.prototype.empty());
    EXPECT_EQ(f->parsed.ast.tokens.at(m.prototype.first).text(), "float3");
  }
  EXPECT_EQ(f->sm.presumed(ambient.methods[0].name_range.begin).line, 8u) << "matched by parameter types";
  EXPECT_EQ(f->sm.presumed(ambient.methods[1].name_range.begin).line, 7u);

  auto g = run_front_end(
      "struct S { float a; };\n"
      "class C { float a; float F(); };\n"
      "float S::F() { return 1; }\n"
      "float C::G() { return 1; }\n"
      "float C::F(float x) { return x; }\n"
      "float4 Fine() : SV_Target { return 1; }\n"
      "technique11 T { pass P { SetPixelShader(CompileShader(ps_5_0, Fine())); } }\n");
  EXPECT_EQ(g->ids(),
            (std::vector<std::string>{"method-outside-class", "method-outside-class", "method-outside-class"}))
      << g->text();
  const std::string text = g->text();
  EXPECT_NE(text.find("t.fx:3:7: error: 'S' is not a class declared before the definition of 'S::F'"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("t.fx:4:10: error: class 'C' declares no method 'G' with 0 parameters left to define"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("t.fx:2:7: note: class 'C' declared here"), std::string::npos) << text;
  EXPECT_EQ(g->parsed.ast.decls.size(), 4u) << "parsing goes on after each";
}

// fxc reads a `sampler_state { }` initializer with the profile's sampler states: D3D9's
// under fx_2_0, the D3D10 SamplerState fields under fx_4_0 and later. A state of the other
// API is unknown, with a note naming the profile that reads it; except that a file whose
// inferred fx_4_0+ profile sits beside a D3D9 technique targets both, and takes both.
TEST(EffectForms, SamplerStateFollowsTheProfile) {
  auto f = run_front_end(
      "Texture2D Tex;\n"
      "sampler2D S = sampler_state { Texture = <Tex>; Filter = MIN_MAG_MIP_LINEAR; AddressU = WRAP; };\n"
      "technique10 T { pass P { } }\n");
  EXPECT_CLEAN(f);
  auto g = run_front_end("sampler2D S = sampler_state { MinFilter = Linear; };\ntechnique10 T { pass P { } }\n",
                         EffectProfile::fx_4_0);
  EXPECT_EQ(g->text(),
            "t.fx:1:31: error: unknown state 'MinFilter' in a SamplerState; did you mean "
            "'Filter'? [unknown-state]\n"
            "sampler2D S = sampler_state { MinFilter = Linear; };\n"
            "                              ^~~~~~~~~\n"
            "t.fx:1:31: note: fix-it: replace with 'Filter'\n"
            "t.fx:1:31: note: a Direct3D 9 sampler state, read in fx_2_0 only; this effect is fx_4_0\n");
  auto h = run_front_end(
      "sampler2D S = sampler_state { Filter = MIN_MAG_MIP_LINEAR; };\n"
      "technique T { pass P { } }\n");
  ASSERT_EQ(h->diags.diagnostics().size(), 1u) << h->text();
  EXPECT_EQ(h->diags.diagnostics()[0].notes.at(0).message,
            "a Direct3D 10 sampler state, read in fx_4_0 and later; this effect is fx_2_0");
  auto both = run_front_end(
      "sampler2D S = sampler_state { MinFilter = Linear; Filter = MIN_MAG_MIP_POINT; };\n"
      "technique T9 { pass P { } }\ntechnique10 T10 { pass P { } }\n");
  EXPECT_CLEAN(both);
  auto d3d10_only = run_front_end(
      "sampler2D S = sampler_state { MinFilter = Linear; };\n"
      "technique10 T10 { pass P { } }\n");
  EXPECT_EQ(d3d10_only->diags.diagnostics().size(), 1u) << d3d10_only->text();
}

}  // namespace
}  // namespace fx
