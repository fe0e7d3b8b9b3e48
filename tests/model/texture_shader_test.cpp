// Texture shaders (D3DX `function` annotations): shape, size, arguments, and the located
// errors for a function that does not exist or cannot fill the texture.
#include <gtest/gtest.h>

#include <array>

#include "model_test_util.h"

namespace fx {
namespace {

const TextureShader* shader_of(const test::Built& b, std::string_view texture) {
  const TextureInfo* t = b.model.texture_of(b.model.find_parameter(texture));
  return t && t->shader ? &*t->shader : nullptr;
}

// Engine-Nine's cage.fx: a `Dimensions` float2 sizes it, the sampler2D makes it 2D, and the
// parameters are fed in their order.
TEST(TextureShader, EngineNineStripe) {
  auto b = test::build(
      R"(texture stripeTex < string function = "MakeStripe"; string UIWidget = "None"; float2 Dimensions = { 32, 16 }; >;
sampler2D stripeTexSampler = sampler_state { Texture = <stripeTex>; };
float4 MakeStripe(float2 Pos : POSITION, float ps : PSIZE) : COLOR {
   float v = 0; float nx = Pos.x+ps; v = nx > Pos.y; return float4(v.xxxx); }
)");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const TextureShader* s = shader_of(*b, "stripeTex");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->function, "MakeStripe");
  EXPECT_EQ(s->shape, TextureShape::tex2d);
  EXPECT_EQ(s->width, 32u);
  EXPECT_EQ(s->height, 16u);
  EXPECT_EQ(s->depth, 1u);
  ASSERT_EQ(s->arguments.size(), 2u);
  EXPECT_EQ(s->arguments[0].input, TexelInput::position);
  EXPECT_EQ(s->arguments[0].components, 2);
  EXPECT_EQ(s->arguments[1].input, TexelInput::texel_size);
  EXPECT_EQ(s->arguments[1].components, 1);
}

// FX Composer's form: `width`/`height`/`depth` (any case), `target`, a volume by its
// annotation or its sampler, a cube by its type; the default edge is 64.
TEST(TextureShader, ShapeAndSizeFromAnnotationsTypesAndSamplers) {
  auto b = test::build(R"(
float4 Noise(float3 p : POSITION, float3 s : PSIZE) : COLOR { return float4(p, 1); }
float4 Flat(float2 p : POSITION) : COLOR { return float4(p, 0, 1); }
texture Vol < string function = "Noise"; string target = "tx_1_0"; int Width = 16; int height = 8; int DEPTH = 4; string TextureType = "VOLUME"; >;
texture BySampler < string function = "Noise"; >;
sampler3D S3 = sampler_state { Texture = <BySampler>; };
textureCUBE Sky < string function = "Noise"; int width = 32; >;
texture Default < string function = "Flat"; >;
)");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const uint32_t edge = kTextureShaderDefaultSize;
  const struct {
    const char* texture;
    TextureShape shape;
    uint32_t width, height, depth;
  } expected[] = {
      {"Vol", TextureShape::tex3d, 16, 8, 4},
      {"BySampler", TextureShape::tex3d, edge, edge, edge},
      {"Sky", TextureShape::cube, 32, 32, 1},
      {"Default", TextureShape::tex2d, edge, edge, 1},
  };
  for (const auto& e : expected) {
    const TextureShader* s = shader_of(*b, e.texture);
    ASSERT_TRUE(s) << e.texture;
    EXPECT_EQ(s->shape, e.shape) << e.texture;
    const std::array<uint32_t, 3> size{s->width, s->height, s->depth}, want{e.width, e.height, e.depth};
    EXPECT_EQ(size, want) << e.texture;
  }
  EXPECT_EQ(shader_of(*b, "Vol")->target, "tx_1_0");
}

// A function that does not exist: an error at the annotation's string, with a did-you-mean.
TEST(TextureShader, UnknownFunctionIsLocatedAtTheAnnotation) {
  auto b = test::build(R"(float4 MakeStripe(float2 Pos : POSITION) : COLOR { return 1; }
texture stripeTex < string function = "MakeStrip"; >;
)");
  EXPECT_TRUE(b->has("unknown-texture-function")) << b->text();
  EXPECT_NE(b->text().find("test.fx:2:39: error: texture 'stripeTex' names no function 'MakeStrip'; did you mean "
                           "'MakeStripe'? [unknown-texture-function]"),
            std::string::npos)
      << b->text();
  EXPECT_FALSE(shader_of(*b, "stripeTex"));
}

// Functions that cannot fill the texture say why, at the annotation.
TEST(TextureShader, FunctionsThatCannotFillTheTextureSayWhy) {
  struct Case {
    const char* code;
    const char* why;
  };
  const Case cases[] = {
      {"float4 F(float2 uv : TEXCOORD0) : COLOR { return 1; }\ntexture T < string function = \"F\"; >;",
       "its parameter 'uv' is not a float input with the semantic POSITION or PSIZE"},
      {"float3 F(float2 p : POSITION) : COLOR { return 1; }\ntexture T < string function = \"F\"; >;",
       "'F' returns float3; a texture shader returns a float4 colour"},
      {"float4 F(float s : PSIZE) : COLOR { return 1; }\ntexture T < string function = \"F\"; >;",
       "'F' has no POSITION parameter"},
      {"float4 F(float2 p : POSITION) : COLOR { return 1; }\ntexture3D T < string function = \"F\"; >;",
       "its POSITION parameter 'p' has 2 components; a 3D texture's texels have 3"},
      {"float4 F(float2 p : POSITION) : COLOR { return 1; }\ntexture T < string function = \"F\"; int width = 0; >;",
       "its width must be a whole number from 1 to 4096"},
      {"float4 F(float2 p : POSITION) : COLOR { return 1; }\ntexture1D T < string function = \"F\"; >;",
       "a texture shader fills 2D, 3D and cube textures"},
  };
  for (const Case& c : cases) {
    auto b = test::build(c.code);
    EXPECT_TRUE(b->has("bad-texture-function")) << c.code << "\n" << b->text();
    EXPECT_NE(b->text().find("test.fx:2:"), std::string::npos) << b->text();
    EXPECT_NE(b->text().find(c.why), std::string::npos) << c.code << "\n" << b->text();
  }
}

}  // namespace
}  // namespace fx
