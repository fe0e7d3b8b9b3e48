// Parses the effect files written from the seed documents (tests/parser/data/).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "parse_helpers.h"

using namespace fx;

namespace {

std::unique_ptr<fxtest::Parsed> parse_file(const std::string& name) {
  std::ifstream in(std::string(FXKIT_SOURCE_DIR) + "/tests/parser/data/" + name);
  EXPECT_TRUE(in) << name;
  std::stringstream text;
  text << in.rdbuf();
  return fxtest::parse(text.str(), name.c_str());
}

const ast::Technique& technique(const fxtest::Parsed& p, std::string_view name) {
  for (const ast::Decl& d : p.effect.decls)
    if (d.kind == ast::DeclKind::technique && d.technique->name == name) return *d.technique;
  ADD_FAILURE() << "no technique " << name;
  static const ast::Technique none;
  return none;
}

}  // namespace

TEST(Seeds, BrdfEffectWithDeclAndAsm) {
  auto p = parse_file("brdf.fx");
  EXPECT_EQ(p->text(), "");
  const ast::Technique& t = technique(*p, "tec0");
  ASSERT_EQ(t.passes.size(), 1u);
  const auto& states = t.passes[0].states;
  // 4 constants + 4 textures, 2 ops, 11 addressing states, VertexShader, pixelshader.
  ASSERT_EQ(states.size(), 23u);
  EXPECT_EQ(states[0].name, "VertexShaderConstant");
  EXPECT_EQ(states[0].value->kind, ast::ExprKind::reference);
  EXPECT_EQ(states[0].value->text, "mWld");
  EXPECT_EQ(states[8].value->text, "Disable");
  const ast::StateAssignment& vs = states[21];
  EXPECT_EQ(vs.name, "VertexShader");
  ASSERT_EQ(vs.value->kind, ast::ExprKind::asm_block);
  EXPECT_EQ(p->spelled(vs.value->decl_code).substr(0, 9), "stream 0 ");
  EXPECT_EQ(p->spelled(vs.value->code).substr(0, 8), "vs .1.1 ");
  EXPECT_EQ(states[22].name, "pixelshader");
  EXPECT_EQ(p->spelled(states[22].value->code).substr(0, 8), "ps .1.1 ");
  size_t strings = 0;
  for (const ast::Decl& d : p->effect.decls)
    if (d.kind == ast::DeclKind::variable && d.variable->type.name == "string") ++strings;
  EXPECT_EQ(strings, 2u);
}

TEST(Seeds, WoodEffectKeepsItsQuirks) {
  auto p = parse_file("wood.fx");
  EXPECT_EQ(p->text(), "");
  EXPECT_EQ(p->effect.profile_header, "fx.2.0");
  size_t variables = 0, functions = 0, structs = 0;
  for (const ast::Decl& d : p->effect.decls) {
    variables += d.kind == ast::DeclKind::variable;
    functions += d.kind == ast::DeclKind::function;
    structs += d.kind == ast::DeclKind::structure;
  }
  EXPECT_EQ(variables, 15u);  // point_scale and turbulence share one declaration
  EXPECT_EQ(functions, 4u);
  EXPECT_EQ(structs, 2u);
  const ast::Decl& lightwood = p->effect.decls.at(3);
  ASSERT_EQ(lightwood.kind, ast::DeclKind::variable);
  EXPECT_EQ(lightwood.variable->type.name, "vec3");
  EXPECT_EQ(lightwood.variable->initializer->text, "vec3");
  const ast::Function& wood = *p->effect.decls.back().function;
  EXPECT_EQ(wood.name, "Wood");
  ASSERT_EQ(wood.params.size(), 1u);
  EXPECT_EQ(wood.params[0].storage, uint32_t(ast::kConst));
}

TEST(Seeds, StateSnippetsWrappedInPasses) {
  auto p = parse_file("state_snippets.fx");
  EXPECT_EQ(p->text(), "");
  EXPECT_EQ(technique(*p, "DiffusePixelShader").passes.at(0).states.size(), 6u);
  const auto& fixed = technique(*p, "DiffuseDotProduct3").passes.at(0).states;
  ASSERT_EQ(fixed.size(), 11u);
  EXPECT_EQ(fixed[0].value->text, "DotProduct3");
  const auto& emboss = technique(*p, "DiffuseEmboss").passes.at(0).states;
  ASSERT_EQ(emboss.size(), 11u);
  EXPECT_EQ(emboss[3].value->kind, ast::ExprKind::binary);
  EXPECT_EQ(emboss[3].value->text, "|");
  const auto& spec = technique(*p, "SpecularPixelShader").passes.at(0).states;
  ASSERT_EQ(spec.size(), 7u);
  EXPECT_EQ(spec[4].value->text, ",");  // `(.5f, .5f, .5f, .5f)` as printed
}

TEST(Seeds, SdkSampleStyleEffect) {
  auto p = parse_file("sdk_sample.fx");
  EXPECT_EQ(p->text(), "");
  const ast::Variable& script = *p->effect.decls.at(0).variable;
  EXPECT_EQ(script.semantic, "STANDARDSGLOBAL");
  EXPECT_EQ(script.annotations.size(), 5u);
  EXPECT_EQ(p->effect.decls.at(1).variable->storage, uint32_t(ast::kShared));
  const ast::Technique& d3d9 = technique(*p, "RenderSceneWithTexture1Light");
  EXPECT_EQ(d3d9.passes.at(0).annotations.size(), 1u);
  EXPECT_EQ(d3d9.passes.at(0).states.at(0).value->kind, ast::ExprKind::compile);
  const ast::Technique& d3d10 = technique(*p, "Render10");
  EXPECT_EQ(d3d10.version, 10);
  ASSERT_EQ(d3d10.passes.at(0).states.size(), 6u);
  for (const ast::StateAssignment& s : d3d10.passes[0].states) EXPECT_TRUE(s.call_style);
  size_t state_objects = 0, buffers = 0;
  for (const ast::Decl& d : p->effect.decls) {
    state_objects += d.kind == ast::DeclKind::state_object;
    buffers += d.kind == ast::DeclKind::constant_buffer;
  }
  EXPECT_EQ(state_objects, 4u);
  EXPECT_EQ(buffers, 1u);
}
