// The semantic model on small effects: what each identifier of a body resolves to, the
// types of members and swizzles, scopes, and the located findings with their did-you-mean.
#include "fx/semantic_model.h"

#include <gtest/gtest.h>

#include "fx/diagnostic_render.h"
#include "model_helpers.h"

namespace {

using fx::semantic::SymbolKind;
using fx::semantic::TypeClass;

constexpr const char* kLight = R"(
struct Light { float3 direction; float4 colour; };
cbuffer PerFrame { float4x4 ViewProj; Light Sun; };
float Gloss : SPECULARPOWER < float UIMin = 1; > = 20;
texture Diffuse;
sampler2D DiffuseSampler = sampler_state { Texture = <Diffuse>; };
float3 shade(float3 n, Light l) {
  float d = saturate(dot(n, -l.direction));
  float3 c = l.colour.rgb * d;
  for (int i = 0; i < 2; ++i) { float3 extra = c * i; c += extra; }
  return c + pow(d, Gloss) + tex2D(DiffuseSampler, n.xy).rgb;
}
)";

TEST(SemanticModel, ResolvesParametersLocalsGlobalsAndIntrinsics) {
  auto m = fxtest::model_of(kLight);
  ASSERT_TRUE(m->front_end.diagnostics().empty()) << fx::render_text(m->front_end.diagnostics(), m->sm);
  EXPECT_TRUE(m->model->diagnostics().empty());
  const auto* l = m->reference("l", 1);  // `-l.direction`
  ASSERT_NE(l, nullptr);
  ASSERT_NE(l->symbol, nullptr);
  EXPECT_EQ(l->symbol->kind, SymbolKind::function_parameter);
  EXPECT_EQ(l->type.name, "Light");
  const auto* direction = m->reference("direction", 1);
  ASSERT_NE(direction, nullptr);
  EXPECT_EQ(direction->symbol->kind, SymbolKind::member);
  EXPECT_EQ(direction->type.name, "float3");
  const auto* gloss = m->reference("Gloss", 1);
  ASSERT_NE(gloss, nullptr);
  EXPECT_EQ(gloss->symbol->kind, SymbolKind::parameter);
  const auto* saturate = m->reference("saturate");
  ASSERT_NE(saturate, nullptr);
  ASSERT_NE(saturate->intrinsic, nullptr);
  EXPECT_EQ(saturate->intrinsic->name, "saturate");
  const auto* d = m->reference("d", 1);  // `l.colour.rgb * d`
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->symbol->kind, SymbolKind::local);
  EXPECT_EQ(d->symbol->type.name, "float");
  const auto* rgb = m->reference("rgb");
  ASSERT_NE(rgb, nullptr);
  EXPECT_EQ(rgb->type.name, "float3");
  const auto* sun = m->model->global("Sun");
  ASSERT_NE(sun, nullptr);
  EXPECT_EQ(sun->kind, SymbolKind::cbuffer_member);
  EXPECT_EQ(sun->container, "PerFrame");
}

TEST(SemanticModel, LocalsAreVisibleInTheirBlockOnly) {
  auto m = fxtest::model_of(kLight);
  const int64_t extra = m->token("extra", 1);  // `c += extra` inside the loop
  const int64_t ret = m->token("return");
  ASSERT_GT(extra, 0);
  auto names = [&](int64_t at) {
    std::vector<std::string_view> out;
    for (const auto* s : m->model->visible_at(static_cast<uint32_t>(at))) out.push_back(s->name);
    return out;
  };
  auto inside = names(extra), after = names(ret);
  EXPECT_NE(std::find(inside.begin(), inside.end(), "extra"), inside.end());
  EXPECT_EQ(std::find(after.begin(), after.end(), "extra"), after.end());
  EXPECT_NE(std::find(after.begin(), after.end(), "c"), after.end());
  EXPECT_NE(std::find(after.begin(), after.end(), "n"), after.end());
  EXPECT_EQ(m->model->function_at(static_cast<uint32_t>(ret))->name, "shade");
}

TEST(SemanticModel, UnknownIdentifierHasALocatedDidYouMean) {
  auto m = fxtest::model_of(R"(float Gloss = 2;
float4 PS(float2 uv : TEXCOORD0) : COLOR {
  float glow = 1;
  return glw * Glosss * uv.x;
}
)");
  ASSERT_EQ(m->ids(), (std::vector<std::string>{"unknown-identifier", "unknown-identifier"}));
  fx::DiagnosticSink sink;
  m->model->report(sink);
  const std::string text = fx::render_text(sink.diagnostics(), m->sm);
  EXPECT_NE(text.find("t.fx:4:10: error: use of undeclared identifier 'glw'; did you mean 'glow'?"), std::string::npos)
      << text;
  EXPECT_NE(text.find("t.fx:3:9: note: 'glow' is declared here"), std::string::npos) << text;
  EXPECT_NE(text.find("did you mean 'Gloss'?"), std::string::npos) << text;
  ASSERT_EQ(m->model->diagnostics()[0].fixits.size(), 1u);
  EXPECT_EQ(m->model->diagnostics()[0].fixits[0].replacement, "glow");
}

TEST(SemanticModel, WrongMemberNamesAndSwizzlesAreReported) {
  auto m = fxtest::model_of(R"(struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; };
VSOut VS(float4 p : POSITION) {
  VSOut o = (VSOut)0;
  o.pos = p;
  o.vu = p.xy;
  o.uv = p.xq;
  return o;
}
)");
  ASSERT_EQ(m->ids(), (std::vector<std::string>{"unknown-member", "unknown-member"}));
  EXPECT_EQ(m->model->diagnostics()[0].message, "no member named 'vu' in 'VSOut'; did you mean 'uv'?");
  EXPECT_NE(m->model->diagnostics()[1].message.find("'xq' is no swizzle of 'float4'"), std::string::npos);
}

TEST(SemanticModel, StaysSilentOnCodeItDoesNotModel) {
  auto m = fxtest::model_of(R"(#define MAKE(x) x * undefined_in_macro
float4 PS(float4 c : COLOR0) : COLOR {
  struct Local { float a; } l;
  l.a = 1;
  return MAKE(c) * mystery;
}
float4 PS2(float4 c : COLOR0) : COLOR { return MAKE(c); }
)");
  EXPECT_TRUE(m->model->diagnostics().empty());
  EXPECT_GT(m->model->counts().unresolved, 0u);
}

TEST(SemanticModel, MethodsSeeTheirClassMembers) {
  auto m = fxtest::model_of(R"(interface ILight { float3 Shade(float3 n); };
class Ambient : ILight { float3 colour; float3 Shade(float3 n) { return colour * n; } };
Ambient g_ambient;
float4 PS(float3 n : NORMAL) : SV_Target { return float4(g_ambient.Shade(n), 1); }
)");
  EXPECT_TRUE(m->model->diagnostics().empty()) << m->model->diagnostics()[0].message;
  const auto* colour = m->reference("colour", 1);
  ASSERT_NE(colour, nullptr);
  EXPECT_EQ(colour->symbol->kind, SymbolKind::member);
  const auto* shade = m->reference("Shade", 2);
  ASSERT_NE(shade, nullptr);
  EXPECT_EQ(shade->symbol->kind, SymbolKind::function);
}

TEST(SemanticModel, TypesFollowTypedefsArraysAndTemplates) {
  auto m = fxtest::model_of(R"(typedef float3 colour3;
static const float weights[3] = { 0.25, 0.5, 0.25 };
Texture2D<float4> tex;
SamplerState smp;
float4 PS(float2 uv : TEXCOORD0) : SV_Target {
  colour3 c = weights[1].xxx;
  float4 m[2] = { tex.Sample(smp, uv), tex.Sample(smp, uv) };
  return float4(c, 1) + m[0].wzyx;
}
)");
  EXPECT_TRUE(m->model->diagnostics().empty()) << m->model->diagnostics()[0].message;
  const auto* c = m->reference("c", 1);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->type.name, "float3");
  const auto* xxx = m->reference("xxx");
  ASSERT_NE(xxx, nullptr);
  EXPECT_EQ(xxx->type.name, "float3");
  const auto* wzyx = m->reference("wzyx");
  ASSERT_NE(wzyx, nullptr);
  EXPECT_EQ(wzyx->type.name, "float4");
  EXPECT_EQ(m->model->global("tex")->type.kind, TypeClass::object);
}

// `matrix` and `vector` are keywords that name types (HLSL's float4x4 and float4), and
// `unsigned int` is fxc's uint: locals declared with them are locals (the DirectX SDK's
// skinning samples, `matrix m = g_mBoneWorld[iBone];`, and NBodyGravity's loop counter).
TEST(SemanticModel, LocalsOfMatrixVectorAndUnsignedTypes) {
  auto m = fxtest::model_of(R"(float4x4 g_bones[4];
float4 VS(float4 p : POSITION, uint bone : BLENDINDICES) : POSITION {
  matrix m = g_bones[bone];
  vector v = mul(p, m);
  for (unsigned int index = 0; index < 4; index++) v += (float)index;
  return v;
}
)");
  EXPECT_TRUE(m->model->diagnostics().empty()) << m->model->diagnostics()[0].message;
  const auto* mat = m->reference("m", 1);  // `mul(p, m)`
  ASSERT_NE(mat, nullptr);
  ASSERT_NE(mat->symbol, nullptr);
  EXPECT_EQ(mat->symbol->kind, SymbolKind::local);
  EXPECT_EQ(mat->type.name, "float4x4");
  const auto* v = m->reference("v", 1);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->type.name, "float4");
  const auto* index = m->reference("index", 1);
  ASSERT_NE(index, nullptr);
  ASSERT_NE(index->symbol, nullptr);
  EXPECT_EQ(index->symbol->kind, SymbolKind::local);
}

TEST(SemanticModel, LocalsWithAnnotationBlocksAreDeclarations) {
  // fxc takes an empty annotation block on a local (vkd3d's effect-annotations tests); the
  // front end reports a non-empty one, and its entries are no identifiers of the code.
  auto m = fxtest::model_of(R"(float4 PS(float4 c : COLOR0) : COLOR {
  float var < > = 0;
  float pair[2] < >, other < > = 1;
  float named < int a = 1; > = 2;
  return c * var * pair[0] * other * named;
}
)");
  EXPECT_TRUE(m->model->diagnostics().empty()) << m->model->diagnostics()[0].message;
  for (const char* name : {"var", "pair", "other", "named"}) {
    const auto* use = m->reference(name, 1);
    ASSERT_NE(use, nullptr) << name;
    ASSERT_NE(use->symbol, nullptr) << name;
    EXPECT_EQ(use->symbol->kind, SymbolKind::local) << name;
  }
  EXPECT_EQ(m->reference("pair", 1)->symbol->type.array_rank, 1u);
  EXPECT_EQ(m->reference("a"), nullptr);
  std::vector<std::string> front_end;
  for (const fx::Diagnostic& d : m->front_end.diagnostics()) front_end.push_back(d.id);
  EXPECT_EQ(front_end, std::vector<std::string>{"annotation-on-local"});
}

TEST(SemanticModel, AttributesAfterAControlHeaderAndBaseClassMembers) {
  // From the widened corpus: `[unroll]` on a loop that is the body of another loop, a
  // method reading a member its class inherits (fxc takes both), hull-shader intrinsics.
  auto m = fxtest::model_of(R"(class Base { int power; };
class Rough : Base { int Power() { return power; } };
Rough g_rough;
float4 PS(float4 c : COLOR0) : COLOR {
  int x, y;
  [unroll]
  for (x = 0; x < 2; x++)
    [unroll]
    for (y = 0; y < 2; y++)
      c += x * y;
  if (c.x > 0) [branch] if (c.y > 0) c *= 2;
  return c * g_rough.Power();
}
)");
  EXPECT_TRUE(m->model->diagnostics().empty()) << m->model->diagnostics()[0].message;
  const auto* power = m->reference("power", 1);
  ASSERT_NE(power, nullptr);
  ASSERT_NE(power->symbol, nullptr);
  EXPECT_EQ(power->symbol->kind, SymbolKind::member);
  EXPECT_EQ(power->symbol->container, "Base");
  for (const char* hull : {"ProcessTriTessFactorsMax", "ProcessQuadTessFactorsAvg", "ProcessIsolineTessFactors"})
    EXPECT_NE(fx::semantic::find_intrinsic(hull), nullptr) << hull;
}

}  // namespace
