// One case per grammar feature of the effect parser on valid input (invalid input:
// parser_errors_test.cpp).
#include <gtest/gtest.h>

#include <iterator>
#include <string>
#include <vector>

#include "fx/lexer.h"
#include "parse_helpers.h"

using namespace fx;
using fxtest::parse;
using fxtest::var;

namespace {

#define EXPECT_CLEAN(p) EXPECT_EQ((p)->text(), "") << "unexpected diagnostics"

TEST(Parser, StorageClasses) {
  auto p = parse(
      "shared static uniform const extern volatile row_major float4x4 m;\n"
      "column_major groupshared nointerpolation precise float x;\n");
  EXPECT_CLEAN(p);
  ASSERT_EQ(p->effect.decls.size(), 2u);
  EXPECT_EQ(var(*p, 0).storage, uint32_t(ast::kShared | ast::kStatic | ast::kUniform | ast::kConst | ast::kExtern |
                                         ast::kVolatile | ast::kRowMajor));
  EXPECT_EQ(var(*p, 0).type.name, "float4x4");
  EXPECT_EQ(var(*p, 1).storage,
            uint32_t(ast::kColumnMajor | ast::kGroupShared | ast::kNoInterpolation | ast::kPrecise));
}

TEST(Parser, Types) {
  auto p = parse(
      "half3 a; matrix b; vector c; DWORD d; bool e; int f; string g; texture h;\n"
      "texture2D i; texture3D j; textureCUBE k; volumetexture l; sampler m; sampler2D n;\n"
      "sampler3D o; samplerCUBE q; Texture2D<float4> r; matrix<float,4,4> s;\n"
      "unsigned int u;\n");
  EXPECT_CLEAN(p);
  const char* names[] = {"half3",       "matrix",        "vector",  "DWORD",       "bool",
                         "int",         "string",        "texture", "texture2D",   "texture3D",
                         "textureCUBE", "volumetexture", "sampler", "sampler2D",   "sampler3D",
                         "samplerCUBE", "Texture2D",     "matrix",  "unsigned int"};
  ASSERT_EQ(p->effect.decls.size(), std::size(names));
  for (size_t i = 0; i < std::size(names); ++i) EXPECT_EQ(var(*p, i).type.name, names[i]);
  EXPECT_EQ(var(*p, 16).type.template_arg, "float4");
  EXPECT_EQ(var(*p, 17).type.template_arg, "float,4,4");
}

TEST(Parser, NestedTemplateArgumentsSplitShift) {
  auto p = parse("Texture2D<vector<float,4>> t;\nfloat after;");
  EXPECT_CLEAN(p);
  ASSERT_EQ(p->effect.decls.size(), 2u);
  EXPECT_EQ(var(*p, 0).type.template_arg, "vector<float,4>");
  // The `>>` became two `>` tokens in Effect::tokens, so spans still spell the source.
  EXPECT_EQ(p->spelled(var(*p, 0).tokens), "Texture2D < vector < float , 4 > > t ;");
  EXPECT_EQ(p->spelled(var(*p, 1).tokens), "float after ;");
}

TEST(Parser, ArraysAndMultipleDeclarators) {
  auto p = parse("float a[4], b = 1, c[2][3], d[] = {1, 2};");
  EXPECT_CLEAN(p);
  ASSERT_EQ(p->effect.decls.size(), 4u);
  EXPECT_EQ(var(*p, 0).name, "a");
  ASSERT_EQ(var(*p, 0).array_dims.size(), 1u);
  EXPECT_EQ(var(*p, 0).array_dims[0]->number, 4);
  EXPECT_EQ(var(*p, 1).initializer->number, 1);
  EXPECT_EQ(var(*p, 2).array_dims.size(), 2u);
  ASSERT_EQ(var(*p, 3).array_dims.size(), 1u);
  EXPECT_EQ(var(*p, 3).array_dims[0], nullptr);
  EXPECT_EQ(var(*p, 3).initializer->args.size(), 2u);
  // Declarators of one declaration share the declaration's token span.
  EXPECT_EQ(var(*p, 0).tokens.first, var(*p, 3).tokens.first);
  EXPECT_EQ(var(*p, 3).type.name, "float");
}

TEST(Parser, SemanticsRegistersPackoffset) {
  auto p = parse(
      "float4x4 W : WORLD : register(c0);\n"
      "sampler s : register(ps_3_0, s2);\n"
      "float y : packoffset(c1.y);\n");
  EXPECT_CLEAN(p);
  EXPECT_EQ(var(*p, 0).semantic, "WORLD");
  EXPECT_EQ(var(*p, 0).register_binding, "c0");
  EXPECT_EQ(var(*p, 1).register_binding, "ps_3_0,s2");
  EXPECT_EQ(var(*p, 2).packoffset, "c1.y");
}

TEST(Parser, Annotations) {
  auto p = parse(
      "float g : SPECULARPOWER < string UIName = \"Gloss\"; float UIMin = 0; float UIMax = 1;\n"
      "  float2 R = {0, 1}; int A[2] = {1, 2}; bool B = true; > = 0.5;\n"
      "texture t < string ResourceName = \"wood.dds\"; >;\n");
  EXPECT_CLEAN(p);
  const ast::Variable& g = var(*p, 0);
  ASSERT_EQ(g.annotations.size(), 6u);
  EXPECT_EQ(g.annotations[0].type.name, "string");
  EXPECT_EQ(g.annotations[0].name, "UIName");
  EXPECT_EQ(g.annotations[0].value->kind, ast::ExprKind::string_literal);
  EXPECT_EQ(g.annotations[0].value->text, "Gloss");
  EXPECT_EQ(g.annotations[3].value->kind, ast::ExprKind::init_list);
  EXPECT_EQ(g.annotations[4].array_dims.size(), 1u);
  EXPECT_EQ(g.annotations[5].value->kind, ast::ExprKind::bool_literal);
  EXPECT_EQ(g.initializer->number, 0.5);
  EXPECT_EQ(var(*p, 1).annotations.at(0).value->text, "wood.dds");
}

TEST(Parser, InitializerExpressions) {
  auto p = parse(
      "float a = 1 + 2 * 3;\n"
      "float4 b = float4(0, 0, 0, 1);\n"
      "float c = (float)2 > 1 ? -1 : ~2;\n"
      "string d = \"ab\" \"cd\";\n"
      "float e = m[2].x;\n"
      "DWORD f = 0xff0000ff;\n");
  EXPECT_CLEAN(p);
  const ast::Expr& a = *var(*p, 0).initializer;
  ASSERT_EQ(a.kind, ast::ExprKind::binary);
  EXPECT_EQ(a.text, "+");
  EXPECT_EQ(a.args[1]->text, "*");
  const ast::Expr& b = *var(*p, 1).initializer;
  EXPECT_EQ(b.kind, ast::ExprKind::call);
  EXPECT_EQ(b.text, "float4");
  EXPECT_EQ(b.args.size(), 4u);
  const ast::Expr& c = *var(*p, 2).initializer;
  ASSERT_EQ(c.kind, ast::ExprKind::ternary);
  EXPECT_EQ(c.args[0]->args[0]->kind, ast::ExprKind::cast);
  EXPECT_EQ(c.args[1]->kind, ast::ExprKind::unary);
  EXPECT_EQ(var(*p, 3).initializer->text, "abcd");
  const ast::Expr& e = *var(*p, 4).initializer;
  EXPECT_EQ(e.kind, ast::ExprKind::member);
  EXPECT_EQ(e.args[0]->kind, ast::ExprKind::index);
  EXPECT_EQ(var(*p, 5).initializer->number, double(0xff0000ffu));
}

TEST(Parser, SamplerState) {
  auto p = parse(
      "texture tex;\n"
      "sampler2D s = sampler_state { Texture = <tex>; AddressU = Clamp; MinFilter = Linear; };\n");
  EXPECT_CLEAN(p);
  const ast::Expr& init = *var(*p, 1).initializer;
  ASSERT_EQ(init.kind, ast::ExprKind::state_block);
  EXPECT_EQ(init.text, "sampler_state");
  ASSERT_EQ(init.states.size(), 3u);
  EXPECT_EQ(init.states[0].name, "Texture");
  EXPECT_EQ(init.states[0].value->kind, ast::ExprKind::reference);
  EXPECT_EQ(init.states[0].value->text, "tex");
  EXPECT_EQ(init.states[1].value->text, "Clamp");
}

TEST(Parser, StructsAndTypedefs) {
  auto p = parse(
      "struct VSOut { float4 pos : POSITION; linear float2 uv[2] : TEXCOORD0; float a, b; };\n"
      "typedef float4 color, colors[2];\n");
  EXPECT_CLEAN(p);
  ASSERT_EQ(p->decl(0).kind, ast::DeclKind::structure);
  const ast::Struct& s = *p->decl(0).structure;
  EXPECT_EQ(s.name, "VSOut");
  ASSERT_EQ(s.members.size(), 4u);
  EXPECT_EQ(s.members[0].semantic, "POSITION");
  EXPECT_EQ(s.members[1].storage, uint32_t(ast::kLinear));
  EXPECT_EQ(s.members[3].name, "b");
  EXPECT_EQ(p->spelled(s.tokens).substr(0, 13), "struct VSOut ");
  ASSERT_EQ(p->decl(1).kind, ast::DeclKind::type_alias);
  EXPECT_EQ(p->decl(1).type_alias->name, "color");
  EXPECT_EQ(p->decl(2).type_alias->array_dims.size(), 1u);
}

TEST(Parser, Functions) {
  auto p = parse(
      "float4 VS(in float4 pos : POSITION, out float2 uv : TEXCOORD0, inout float x,\n"
      "          uniform float scale = 2.0) : POSITION\n"
      "{ if (x > 0) { return pos * scale }\n"
      "};\n"
      "float3 proto(float3 n);\n"
      "[numthreads(8, 8, 1)] void CS(uint3 id : SV_DispatchThreadID) {}\n"
      "inline float f(void) { return 1; }\n");
  EXPECT_CLEAN(p);
  ASSERT_EQ(p->effect.decls.size(), 4u);
  const ast::Function& vs = *p->decl(0).function;
  EXPECT_EQ(vs.name, "VS");
  ASSERT_EQ(vs.params.size(), 4u);
  EXPECT_EQ(vs.params[0].storage, uint32_t(ast::kIn));
  EXPECT_EQ(vs.params[1].storage, uint32_t(ast::kOut));
  EXPECT_EQ(vs.params[1].semantic, "TEXCOORD0");
  EXPECT_EQ(vs.params[2].storage, uint32_t(ast::kInOut));
  EXPECT_EQ(vs.params[3].initializer->number, 2.0);
  EXPECT_EQ(vs.semantic, "POSITION");
  // The body is shader code: kept verbatim, even without the ';' HLSL would need.
  EXPECT_EQ(p->spelled(vs.body), "if ( x > 0 ) { return pos * scale }");
  EXPECT_TRUE(p->decl(1).function->body.empty());
  const auto& attributes = p->decl(2).function->attributes;
  EXPECT_EQ(std::vector<std::string>(attributes.begin(), attributes.end()),
            std::vector<std::string>{"numthreads(8,8,1)"});
  EXPECT_EQ(p->decl(3).function->storage, uint32_t(ast::kInline));
  EXPECT_TRUE(p->decl(3).function->params.empty());
}

TEST(Parser, Technique9) {
  auto p = parse(
      "technique T0 < string Name = \"x\"; > {\n"
      "  pass p0 < int Order = 1; > {\n"
      "    VertexShaderConstant[4] = <mTot>;\n"
      "    ZEnable = TRUE; AlphaBlendEnable = false;\n"
      "    ColorArg1[1] = Texture | Complement;\n"
      "    VertexShader = compile vs_2_0 VS(1, true);\n"
      "    PixelShader = NULL;\n"
      "  }\n"
      "  pass { FillMode = Wireframe; }\n"
      "}\n"
      "technique { pass {} }\n");
  EXPECT_CLEAN(p);
  ASSERT_EQ(p->effect.decls.size(), 2u);
  const ast::Technique& t = *p->decl(0).technique;
  EXPECT_EQ(t.version, 9);
  EXPECT_EQ(t.name, "T0");
  EXPECT_EQ(t.annotations.size(), 1u);
  ASSERT_EQ(t.passes.size(), 2u);
  const ast::Pass& p0 = t.passes[0];
  EXPECT_EQ(p0.name, "p0");
  EXPECT_EQ(p0.annotations.size(), 1u);
  ASSERT_EQ(p0.states.size(), 6u);
  EXPECT_EQ(p0.states[0].name, "VertexShaderConstant");
  EXPECT_EQ(p0.states[0].index->number, 4);
  EXPECT_EQ(p0.states[0].value->kind, ast::ExprKind::reference);
  EXPECT_EQ(p0.states[1].value->kind, ast::ExprKind::bool_literal);
  EXPECT_EQ(p0.states[3].value->text, "|");
  const ast::Expr& compile = *p0.states[4].value;
  EXPECT_EQ(compile.kind, ast::ExprKind::compile);
  EXPECT_EQ(compile.text, "vs_2_0");
  EXPECT_EQ(compile.callee, "VS");
  EXPECT_EQ(compile.args.size(), 2u);
  EXPECT_EQ(p0.states[5].value->kind, ast::ExprKind::null);
  EXPECT_TRUE(t.passes[1].name.empty());
  EXPECT_TRUE(p->decl(1).technique->name.empty());
}

TEST(Parser, AsmAndDeclBlocks) {
  auto p = parse(
      "technique t { pass p {\n"
      "  VertexShader = decl { stream 0; float v0[3]; } asm { vs.1.1 m4x4 oPos, v0, c4 };\n"
      "  pixelshader = asm { ps.1.1 tex t0 mov r0, t0 };\n"
      "} }\n");
  EXPECT_CLEAN(p);
  const ast::Pass& pass = p->decl(0).technique->passes.at(0);
  ASSERT_EQ(pass.states.size(), 2u);
  const ast::Expr& vs = *pass.states[0].value;
  EXPECT_EQ(vs.kind, ast::ExprKind::asm_block);
  EXPECT_EQ(p->spelled(vs.decl_code), "stream 0 ; float v0 [ 3 ] ;");
  EXPECT_EQ(p->spelled(vs.code), "vs .1.1 m4x4 oPos , v0 , c4");
  EXPECT_EQ(pass.states[1].name, "pixelshader");
  EXPECT_TRUE(pass.states[1].value->decl_code.empty());
}

TEST(Parser, CallStyleStates) {
  auto p = parse(
      "technique11 t { pass p {\n"
      "  SetVertexShader(CompileShader(vs_4_0, VS()));\n"
      "  SetBlendState(b, float4(0, 0, 0, 0), 0xFFFFFFFF);\n"
      "  SetGeometryShader(ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"POSITION.xyz\"));\n"
      "} }\n");
  EXPECT_CLEAN(p);
  const ast::Technique& t = *p->decl(0).technique;
  EXPECT_EQ(t.version, 11);
  const auto& states = t.passes.at(0).states;
  ASSERT_EQ(states.size(), 3u);
  EXPECT_TRUE(states[0].call_style);
  EXPECT_EQ(states[0].name, "SetVertexShader");
  EXPECT_EQ(states[0].value->kind, ast::ExprKind::call);
  ASSERT_EQ(states[0].value->args.size(), 1u);
  EXPECT_EQ(states[0].value->args[0]->text, "CompileShader");
  EXPECT_EQ(states[1].value->args.size(), 3u);
  ASSERT_FALSE(states[2].value->args.empty());
  ASSERT_EQ(states[2].value->args[0]->args.size(), 2u);
  EXPECT_EQ(states[2].value->args[0]->args[1]->text, "POSITION.xyz");
}

TEST(Parser, StateObjects) {
  auto p = parse(
      "BlendState b { BlendEnable[0] = TRUE; SrcBlend = ONE; };\n"
      "DepthStencilState ds { DepthEnable = FALSE; }\n"
      "RasterizerState rs < string n = \"r\"; > { CullMode = None; };\n"
      "SamplerState ss[2] : register(s1) { Filter = MIN_MAG_MIP_LINEAR; };\n"
      "SamplerState plain;\n");
  EXPECT_CLEAN(p);
  ASSERT_EQ(p->effect.decls.size(), 5u);
  const ast::StateObject& b = *p->decl(0).state_object;
  EXPECT_EQ(b.kind, "BlendState");
  EXPECT_EQ(b.name, "b");
  ASSERT_EQ(b.states.size(), 2u);
  EXPECT_EQ(b.states[0].index->number, 0);
  EXPECT_EQ(p->decl(1).state_object->kind, "DepthStencilState");
  EXPECT_EQ(p->decl(2).state_object->annotations.size(), 1u);
  const ast::StateObject& ss = *p->decl(3).state_object;
  EXPECT_EQ(ss.array_dims.size(), 1u);
  EXPECT_EQ(ss.register_binding, "s1");
  EXPECT_EQ(p->decl(4).kind, ast::DeclKind::variable);
}

TEST(Parser, ConstantBuffers) {
  auto p = parse(
      "cbuffer PerFrame : register(b0) { float4x4 View; float Time < string UIName = \"t\"; > "
      "= 0; };\n"
      "tbuffer Bones { float4x3 B[64]; }\n");
  EXPECT_CLEAN(p);
  const ast::ConstantBuffer& cb = *p->decl(0).constant_buffer;
  EXPECT_FALSE(cb.texture_buffer);
  EXPECT_EQ(cb.name, "PerFrame");
  EXPECT_EQ(cb.register_binding, "b0");
  ASSERT_EQ(cb.members.size(), 2u);
  EXPECT_EQ(cb.members[1].annotations.size(), 1u);
  EXPECT_TRUE(p->decl(1).constant_buffer->texture_buffer);
}

TEST(Parser, FxGroup) {
  auto p = parse(
      "fxgroup g < int x = 1; > {\n"
      "  technique11 a { pass { SetPixelShader(NULL); } }\n"
      "  technique11 b { pass {} }\n"
      "}\n");
  EXPECT_CLEAN(p);
  const ast::FxGroup& g = *p->decl(0).group;
  EXPECT_EQ(g.name, "g");
  EXPECT_EQ(g.annotations.size(), 1u);
  ASSERT_EQ(g.techniques.size(), 2u);
  EXPECT_EQ(g.techniques[1].name, "b");
}

TEST(Parser, GlslBlocksAndLists) {
  auto p = parse(
      "GLSLShader Common { uniform vec3 L; }\n"
      "GLSLShader Hair { void main() { gl_FragColor = vec4(L, 1.0); } };\n"
      "technique glsl { pass { VertexShader = Common; FragmentShader = { Common, Hair }; "
      "BlendColor = {0, 0, 0, 0}; } }\n");
  EXPECT_CLEAN(p);
  ASSERT_EQ(p->effect.decls.size(), 3u);
  const ast::GlslBlock& hair = *p->decl(1).glsl_block;
  EXPECT_EQ(hair.name, "Hair");
  EXPECT_EQ(p->spelled(hair.code), "void main ( ) { gl_FragColor = vec4 ( L , 1.0 ) ; }");
  const auto& states = p->decl(2).technique->passes.at(0).states;
  EXPECT_EQ(states[0].value->kind, ast::ExprKind::identifier);
  EXPECT_EQ(states[1].value->kind, ast::ExprKind::glsl_list);
  EXPECT_EQ(states[1].value->args.size(), 2u);
  EXPECT_EQ(states[2].value->kind, ast::ExprKind::init_list);  // not a shader stage
}

TEST(Parser, ProfileHeaderAndDirectives) {
  auto p = parse("fx.2.0\n\nfloat a;\n");
  EXPECT_CLEAN(p);
  EXPECT_EQ(p->effect.profile_header, "fx.2.0");
  EXPECT_EQ(p->effect.decls.size(), 1u);

  // Directive tokens come from the preprocessor; build the stream by hand.
  SourceManager sm;
  DiagnosticSink diags;
  BufferId b = sm.add_buffer("d.fx", "#pragma pack_matrix(row_major)\nfloat a;\n");
  std::vector<Token> tokens;
  Token directive;
  directive.kind = TokenKind::directive;
  directive.loc = sm.location(b, 0);
  directive.set_short_text(sm.buffer_text(b).substr(0, 30));
  tokens.push_back(directive);
  Lexer lexer(sm, b, diags);
  lexer.rest_of_line();
  for (Token t = lexer.next();; t = lexer.next()) {
    tokens.push_back(t);
    if (t.is(TokenKind::eof)) break;
  }
  ast::Effect e = parse_effect(std::move(tokens), sm, diags);
  EXPECT_EQ(render_text(diags.diagnostics(), sm), "");
  ASSERT_EQ(e.decls.size(), 2u);
  ASSERT_EQ(e.decls[0].kind, ast::DeclKind::directive);
  EXPECT_EQ(e.decls[0].directive->text, "#pragma pack_matrix(row_major)");
  EXPECT_EQ(e.decls[1].kind, ast::DeclKind::variable);
}

TEST(Parser, RangesPointIntoTheSource) {
  auto p = parse("float  Gloss = 0.5;\ntechnique t { pass p { ZEnable = TRUE; } }\n");
  EXPECT_CLEAN(p);
  const ast::Variable& v = var(*p, 0);
  EXPECT_EQ(p->sm.presumed(v.name_range.begin).column, 8u);
  EXPECT_EQ(p->sm.presumed(v.range.end).column, 19u);
  const ast::StateAssignment& s = p->decl(1).technique->passes.at(0).states.at(0);
  EXPECT_EQ(p->sm.presumed(s.name_range.begin).line, 2u);
  EXPECT_EQ(p->sm.presumed(s.name_range.begin).column, 24u);
  EXPECT_EQ(p->sm.presumed(s.value->range.begin).column, 34u);
  EXPECT_EQ(p->sm.presumed(p->decl(1).technique->range.end).column, 43u);
}

}  // namespace
