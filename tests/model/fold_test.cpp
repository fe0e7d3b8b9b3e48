// Constant folding of initializers, annotations and state values, and its errors.
#include <gtest/gtest.h>

#include "model_test_util.h"

namespace fx {
namespace {

std::vector<double> def(const test::Built& b, std::string_view name) {
  const Parameter& p = test::param(b, name);
  return p.default_value ? p.default_value->components : std::vector<double>{};
}

TEST(ModelFold, LiteralsConstructorsLists) {
  auto b = test::build(R"(
    float f = 0.5; int i = 7; bool t = true; uint u = 3u;
    float4 c = float4(0, 0, 0, 1); float3 splat = 0.25; float4 l = {1, 2, 3, 4};
    float4x4 ident = {1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1};
    float2 arr[2] = {1, 2, 3, 4};
    float4 nested = float4(float2(1, 2), 3, 4);
    int fromf = 2.9; float fromi = 3; bool fromn = 5;
    string name = "wood";
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(def(*b, "f"), std::vector<double>{0.5});
  EXPECT_EQ(def(*b, "i"), std::vector<double>{7});
  EXPECT_EQ(def(*b, "t"), std::vector<double>{1});
  EXPECT_EQ(def(*b, "u"), std::vector<double>{3});
  EXPECT_EQ(def(*b, "c"), (std::vector<double>{0, 0, 0, 1}));
  EXPECT_EQ(def(*b, "splat"), (std::vector<double>{0.25, 0.25, 0.25}));
  EXPECT_EQ(def(*b, "l"), (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(def(*b, "ident").size(), 16u);
  EXPECT_EQ(def(*b, "ident")[5], 1);
  EXPECT_EQ(def(*b, "arr"), (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(def(*b, "nested"), (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(def(*b, "fromf"), std::vector<double>{2});
  EXPECT_EQ(def(*b, "fromi"), std::vector<double>{3});
  EXPECT_EQ(def(*b, "fromn"), std::vector<double>{1});
  EXPECT_EQ(test::param(*b, "name").default_value->text, "wood");
}

TEST(ModelFold, ArithmeticSwizzlesAndStaticConsts) {
  auto b = test::build(R"(
    static const float PI = 3.0 + 0.25 * 2;
    static const float3 Base = float3(1, 2, 3);
    float a = PI * 2 - 1;
    float3 b3 = Base.zyx;
    float2 rg = float4(5, 6, 7, 8).rg;
    float t = 1 < 2 ? 10 : 20;
    int bits = (1 << 4) | 3;
    int m = 7 % 3;
    int divi = 7 / 2;
    bool cmp = 2 >= 3;
    float neg = -Base.y;
    float e = Base[2];
    float3 v = Base * 2 + 1;
    float s = saturate(1.5) + max(1, 2) + abs(-1);
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(def(*b, "a"), std::vector<double>{6});
  EXPECT_EQ(def(*b, "b3"), (std::vector<double>{3, 2, 1}));
  EXPECT_EQ(def(*b, "rg"), (std::vector<double>{5, 6}));
  EXPECT_EQ(def(*b, "t"), std::vector<double>{10});
  EXPECT_EQ(def(*b, "bits"), std::vector<double>{19});
  EXPECT_EQ(def(*b, "m"), std::vector<double>{1});
  EXPECT_EQ(def(*b, "divi"), std::vector<double>{3});
  EXPECT_EQ(def(*b, "cmp"), std::vector<double>{0});
  EXPECT_EQ(def(*b, "neg"), std::vector<double>{-2});
  EXPECT_EQ(def(*b, "e"), std::vector<double>{3});
  EXPECT_EQ(def(*b, "v"), (std::vector<double>{3, 5, 7}));
  EXPECT_EQ(def(*b, "s"), std::vector<double>{4});
}

TEST(ModelFold, AnnotationsAreTyped) {
  auto b = test::build(R"(
    float Gloss < string UIName = "Gloss"; float UIMin = 0; float UIMax = 1.0 / 4; int Steps = 8; bool Hidden = false; > = 0.5;
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const Parameter& p = test::param(*b, "Gloss");
  ASSERT_EQ(p.annotations.size(), 5u);
  EXPECT_EQ(find_annotation(p.annotations, "UIName")->value.text, "Gloss");
  EXPECT_EQ(find_annotation(p.annotations, "UIMax")->value.number(), 0.25);
  EXPECT_EQ(find_annotation(p.annotations, "Steps")->value.type.base, BaseType::int32);
  EXPECT_EQ(find_annotation(p.annotations, "Hidden")->value.type.base, BaseType::boolean);
}

TEST(ModelFold, Errors) {
  auto div = test::build("int d = 1 / 0;");
  EXPECT_TRUE(div->has("division-by-zero")) << div->text();
  EXPECT_TRUE(div->diags.has_errors());
  auto fdiv = test::build("float d = 1.0 / 0;");
  EXPECT_TRUE(fdiv->has("division-by-zero"));
  EXPECT_FALSE(fdiv->diags.has_errors()) << "float division by zero is a warning, as fxc";
  auto swz = test::build("float2 s = float2(1, 2).xz;");
  EXPECT_TRUE(swz->has("bad-swizzle")) << swz->text();
  auto ctor = test::build("float4 c = float4(1, 2, 3);");
  EXPECT_TRUE(ctor->has("bad-constructor")) << ctor->text();
  auto count = test::build("float4 c = {1, 2, 3};");
  EXPECT_TRUE(count->has("initializer-mismatch")) << count->text();
  auto trunc = test::build("float2 c = float4(1, 2, 3, 4);");
  EXPECT_TRUE(trunc->has("truncated-initializer")) << trunc->text();
  EXPECT_EQ(def(*trunc, "c"), (std::vector<double>{1, 2}));
  auto idx = test::build("static const float3 A = 1; float x = A[3];");
  EXPECT_TRUE(idx->has("index-out-of-range")) << idx->text();
  // A uniform's default is not a constant another initializer may use (D3D allows only
  // static/const ones); a function call is left for the shader and warned about.
  auto nc = test::build("float u = 1; float w = u * 2; float n = Foo(1);");
  EXPECT_TRUE(nc->has("unfolded-initializer")) << nc->text();
  EXPECT_FALSE(test::param(*nc, "w").default_value);
}

TEST(ModelFold, DirectFolderApi) {
  SourceManager sm;
  DiagnosticSink diags;
  auto parsed = parse_effect_text("x.fx", "float x = (2 + 3) * 4;", sm, diags,
                                  {.preprocessor = {}, .parse = {}, .check = {.require_technique = false}});
  ASSERT_EQ(parsed.ast.decls.size(), 1u);
  const ast::Expr& e = *parsed.ast.decls[0].variable->initializer;
  auto v = fold_constant(e, {}, diags);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->number(), 20);
  EXPECT_EQ(v->type.base, BaseType::int32);
  EXPECT_EQ(v->to_string(), "20");
  auto as_float = convert_value(*v, make_numeric(BaseType::float32, 1, 2), {}, diags);
  ASSERT_TRUE(as_float);
  EXPECT_EQ(as_float->to_string(), "float2(20, 20)");
}

// Values print as the shortest text that reads back as the value held: a float's 0.8 is
// 0.800000011920929 in a double and still prints 0.8. A double prints all the digits its
// value needs: `0.1 + 0.2` adds two float literals (HLSL's unsuffixed literals are float),
// so the double holds the float sum exactly.
TEST(ModelFold, ValuesPrintTheirShortestRoundTripSpelling) {
  auto b = test::build(
      "float f = 0.8; float3 d = {0.577, -0.577, 1e-7}; double x = 0.1 + 0.2; "
      "half h = 0.1; int i = 7.9; bool t = 2; float big = 3e38;");
  EXPECT_EQ(test::param(*b, "f").default_value->to_string(), "0.8");
  EXPECT_EQ(test::param(*b, "d").default_value->to_string(), "float3(0.577, -0.577, 1e-07)");
  EXPECT_EQ(test::param(*b, "x").default_value->to_string(), "0.30000001192092896");
  EXPECT_EQ(test::param(*b, "i").default_value->to_string(), "7");
  EXPECT_EQ(test::param(*b, "t").default_value->to_string(), "true");
  EXPECT_EQ(test::param(*b, "big").default_value->to_string(), "3e+38");
  // Every spelling reads back as the value held, in the parameter's own precision.
  for (const char* name : {"f", "h", "big"}) {
    const Value& v = *test::param(*b, name).default_value;
    EXPECT_EQ(std::stof(v.to_string()), static_cast<float>(v.number())) << name;
  }
  const Value& x = *test::param(*b, "x").default_value;
  EXPECT_EQ(std::stod(x.to_string()), x.number());
}

}  // namespace
}  // namespace fx
