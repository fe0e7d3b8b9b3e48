// Type resolution: every kind of type an effect declares.
#include <gtest/gtest.h>

#include "model_test_util.h"

namespace fx {
namespace {

TEST(ModelType, ScalarsVectorsMatrices) {
  auto b = test::build(R"(
    bool b; int i; uint u; DWORD d; half h; float f; double g;
    float3 v3; half4 h4; bool2 b2; int4 i4; vector v; vector<float, 3> vt;
    float4x4 m; float3x4 m34; matrix mm; matrix<float, 2, 3> mt;
    row_major float4x4 rm; column_major float4x3 cm;
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(test::param(*b, "b").type.to_string(), "bool");
  EXPECT_EQ(test::param(*b, "d").type.base, BaseType::uint32);
  EXPECT_EQ(test::param(*b, "h").type.base, BaseType::half);
  EXPECT_EQ(test::param(*b, "g").type.base, BaseType::float64);
  EXPECT_EQ(test::param(*b, "v3").type.to_string(), "float3");
  EXPECT_EQ(test::param(*b, "h4").type.to_string(), "half4");
  EXPECT_EQ(test::param(*b, "b2").type.to_string(), "bool2");
  EXPECT_EQ(test::param(*b, "v").type.to_string(), "float4");
  EXPECT_EQ(test::param(*b, "vt").type.to_string(), "float3");
  EXPECT_EQ(test::param(*b, "m").type.to_string(), "float4x4");
  const Type& m34 = test::param(*b, "m34").type;
  EXPECT_EQ(m34.rows, 3);
  EXPECT_EQ(m34.cols, 4);
  EXPECT_EQ(test::param(*b, "mm").type.to_string(), "float4x4");
  EXPECT_EQ(test::param(*b, "mt").type.to_string(), "float2x3");
  EXPECT_EQ(test::param(*b, "rm").type.order, MatrixPacking::row_major);
  EXPECT_EQ(test::param(*b, "cm").type.order, MatrixPacking::column_major);
  EXPECT_EQ(test::param(*b, "m").type.order, MatrixPacking::column_major);
}

TEST(ModelType, ArraysStructsTypedefs) {
  auto b = test::build(R"(
    static const int N = 3;
    struct Light { float3 dir; float4 color; int kind; };
    typedef float4 Quad[2];
    float4 a[4]; float2 grid[2][3]; float k[N + 1];
    Light lights[2]; Quad q; Quad qs[3];
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(test::param(*b, "a").type.to_string(), "float4[4]");
  EXPECT_EQ(test::param(*b, "grid").type.component_count(), 12u);
  EXPECT_EQ(test::param(*b, "k").type.array_dims, std::vector<uint32_t>{4});
  const Type& lights = test::param(*b, "lights").type;
  ASSERT_EQ(lights.cls, TypeClass::structure);
  EXPECT_EQ(lights.structure->components, 8u);
  EXPECT_EQ(lights.component_count(), 16u);
  EXPECT_EQ(lights.structure->members[2].type.base, BaseType::int32);
  EXPECT_EQ(test::param(*b, "q").type.to_string(), "float4[2]");
  EXPECT_EQ(test::param(*b, "qs").type.to_string(), "float4[3][2]");
}

// Structs defined in place as member types: an anonymous one is the member's own type, a
// named one is also a type from there on.
TEST(ModelType, StructsDefinedInPlace) {
  auto b = test::build(R"(
    struct Light { struct { float3 dir; float pad; } d; struct Tint { float4 rgba; } tint; float4 color; };
    Light light; Tint tint;
    struct { float4 color; float scale; } material;
    typedef struct { float3 dir; } Ray; Ray ray;
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const Type& light = test::param(*b, "light").type;
  ASSERT_EQ(light.cls, TypeClass::structure);
  EXPECT_EQ(light.structure->components, 12u);
  ASSERT_EQ(light.structure->members.size(), 3u);
  ASSERT_EQ(light.structure->members[0].type.cls, TypeClass::structure);
  EXPECT_EQ(light.structure->members[0].type.structure->members[0].type.to_string(), "float3");
  EXPECT_EQ(test::param(*b, "tint").type.structure->members[0].name, "rgba");
  // At file scope too, and in a typedef.
  ASSERT_EQ(test::param(*b, "material").type.cls, TypeClass::structure);
  EXPECT_EQ(test::param(*b, "material").type.structure->components, 5u);
  ASSERT_EQ(test::param(*b, "ray").type.cls, TypeClass::structure);
  EXPECT_EQ(test::param(*b, "ray").type.structure->members[0].type.to_string(), "float3");
}

TEST(ModelType, ResourcesShadersStateObjects) {
  auto b = test::build(R"(
    string s; texture t; texture1D t1; texture2D t2; texture3D t3; textureCUBE tc; volumetexture vt;
    Texture2D<float4> tt; TextureCube tcube; Texture2DArray tarr;
    sampler sm; sampler1D s1; sampler2D s2; sampler3D s3; samplerCUBE scube;
    SamplerState ss; SamplerComparisonState scs;
    BlendState bs { BlendEnable[0] = FALSE; };
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(test::param(*b, "s").type.cls, TypeClass::string);
  EXPECT_EQ(test::param(*b, "t").type.texture, TextureShape::any);
  EXPECT_EQ(test::param(*b, "t1").type.texture, TextureShape::tex1d);
  EXPECT_EQ(test::param(*b, "t2").type.texture, TextureShape::tex2d);
  EXPECT_EQ(test::param(*b, "t3").type.texture, TextureShape::tex3d);
  EXPECT_EQ(test::param(*b, "tc").type.texture, TextureShape::cube);
  EXPECT_EQ(test::param(*b, "vt").type.texture, TextureShape::tex3d);
  EXPECT_EQ(test::param(*b, "tt").type.to_string(), "Texture2D<float4>");
  EXPECT_EQ(test::param(*b, "tarr").type.texture, TextureShape::tex2d_array);
  EXPECT_EQ(test::param(*b, "sm").type.sampler, SamplerShape::any);
  EXPECT_EQ(test::param(*b, "s2").type.sampler, SamplerShape::s2d);
  EXPECT_EQ(test::param(*b, "scube").type.sampler, SamplerShape::cube);
  EXPECT_EQ(test::param(*b, "ss").type.sampler, SamplerShape::sampler_object);
  EXPECT_EQ(test::param(*b, "scs").type.sampler, SamplerShape::comparison);
  EXPECT_TRUE(test::param(*b, "t2").shader_visible);
  EXPECT_FALSE(test::param(*b, "s").shader_visible);
  EXPECT_EQ(b->model.textures.size(), 9u);
  ASSERT_EQ(b->model.state_objects.size(), 1u);
  EXPECT_EQ(b->model.state_objects[0].block, StateBlock::blend_state);
}

// D3D11 buffers and unordered-access views are resource parameters (shader visible, no
// texture to load), each with its element type, not unknown types.
TEST(ModelType, BuffersAndUnorderedAccessViews) {
  auto b = test::build(R"(
    struct Particle { float3 pos; float size; };
    StructuredBuffer<Particle> sb; RWStructuredBuffer<float4> rwsb; AppendStructuredBuffer<Particle> asb;
    ConsumeStructuredBuffer<Particle> csb; ByteAddressBuffer bab; RWByteAddressBuffer rwbab; RWBuffer<float> rwb;
    RWTexture1D<float> rw1; RWTexture2D<float4> rw2; RWTexture2DArray<uint> rw2a; RWTexture3D<int> rw3;
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(test::param(*b, "sb").type.view, ViewKind::structured_buffer);
  EXPECT_EQ(test::param(*b, "sb").type.element, "Particle");
  EXPECT_EQ(test::param(*b, "rwsb").type.to_string(), "RWStructuredBuffer<float4>");
  EXPECT_EQ(test::param(*b, "asb").type.view, ViewKind::append_structured_buffer);
  EXPECT_EQ(test::param(*b, "csb").type.view, ViewKind::consume_structured_buffer);
  EXPECT_EQ(test::param(*b, "bab").type.to_string(), "ByteAddressBuffer");
  EXPECT_EQ(test::param(*b, "rwbab").type.view, ViewKind::rw_byte_address_buffer);
  EXPECT_EQ(test::param(*b, "rwb").type.view, ViewKind::rw_buffer);
  EXPECT_EQ(test::param(*b, "rw1").type.view, ViewKind::rw_texture1d);
  EXPECT_EQ(test::param(*b, "rw2").type.to_string(), "RWTexture2D<float4>");
  EXPECT_EQ(test::param(*b, "rw2a").type.view, ViewKind::rw_texture2d_array);
  EXPECT_EQ(test::param(*b, "rw3").type.view, ViewKind::rw_texture3d);
  EXPECT_EQ(test::param(*b, "rw2").type.cls, TypeClass::view);
  EXPECT_TRUE(test::param(*b, "rw2").shader_visible);
  EXPECT_TRUE(b->model.textures.empty());
}

// `float2 Offsets[] = { ... };` is sized by its initializer, in elements of the element
// type; values that do not fill whole elements, or no initializer, are bad-array-size.
TEST(ModelType, UnsizedArraysTakeTheirInitializersSize) {
  auto b = test::build("float2 Offsets[] = { float2(1, 2), float2(3, 4), float2(5, 6) }; float Flat[] = { 1, 2 };");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(test::param(*b, "Offsets").type.to_string(), "float2[3]");
  EXPECT_EQ(test::param(*b, "Flat").type.to_string(), "float[2]");
  ASSERT_TRUE(test::param(*b, "Offsets").default_value);
  EXPECT_EQ(test::param(*b, "Offsets").default_value->number(5), 6.0);
  EXPECT_TRUE(test::build("float2 Odd[] = { 1, 2, 3 };")->has("bad-array-size"));
  EXPECT_TRUE(test::build("float2 None[];")->has("bad-array-size"));
  auto annotated = test::build("float x < float Weights[] = {1, 2, 3}; >;");
  ASSERT_FALSE(annotated->diags.has_errors()) << annotated->text();
  EXPECT_EQ(test::param(*annotated, "x").annotations.at(0).value.components.size(), 3u);
}

// Annotation type names in any case, as D3DX reads them (`String UIName`), on parameters,
// textures, techniques and passes.
TEST(ModelType, AnnotationTypeNamesInAnyCase) {
  auto b = test::build(R"(
    float4 Tint < String UIName = "Tint"; STRING UIWidget = "Color"; FLOAT UIMax = 2; > = 1;
    texture2D Tex < String ResourceName = "x.png"; >;
  )");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const Parameter& tint = test::param(*b, "Tint");
  ASSERT_EQ(tint.annotations.size(), 3u);
  EXPECT_EQ(tint.annotations[0].value.text, "Tint");
  EXPECT_EQ(tint.annotations[1].value.text, "Color");
  EXPECT_EQ(tint.annotations[2].value.number(), 2.0);
  ASSERT_EQ(b->model.textures.size(), 1u);
  EXPECT_EQ(b->model.textures[0].resource_name, "x.png");
}

TEST(ModelType, PreReleaseNames) {
  auto b = test::build("vec3 c = vec3(0.3f, 0.12f, 0.03f); vec4 p; vec2 uv;");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(test::param(*b, "c").type.to_string(), "float3");
  ASSERT_TRUE(test::param(*b, "c").default_value);
  EXPECT_FLOAT_EQ(static_cast<float>(test::param(*b, "c").default_value->number(1)), 0.12f);
  EXPECT_EQ(test::param(*b, "p").type.to_string(), "float4");
}

TEST(ModelType, UnknownTypeHasDidYouMean) {
  auto b = test::build("flaot4 x;");
  ASSERT_TRUE(b->has("unknown-type")) << b->text();
  bool suggested = false;
  for (const Diagnostic& d : b->diags.diagnostics())
    if (d.id == "unknown-type") suggested = d.message.find("float4") != std::string::npos;
  EXPECT_TRUE(suggested) << b->text();
  EXPECT_EQ(test::param(*b, "x").type.cls, TypeClass::error);
}

TEST(ModelType, BadArraySize) {
  auto b = test::build("float a[0]; float c[-2];");
  EXPECT_TRUE(b->has("bad-array-size")) << b->text();
}

}  // namespace
}  // namespace fx
