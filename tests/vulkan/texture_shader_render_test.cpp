// D3DX texture shaders on the validated device: the `function` a texture names fills it on
// the GPU when the binding first binds its textures, so a full-screen pass that samples it
// shows the function's texels (never the white stand-in): a 2D stripe as Engine-Nine's
// cage.fx makes it, the effect's globals at their values, a volume and a cube.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "effect_folder.h"
#include "effect_test_util.h"

namespace fx::vk::testing {
namespace {

constexpr uint32_t kSize = 32;

// A quad over the whole target whose pixel (x, y) samples `Sampled` at texel (x, y) of a
// kSize x kSize texture; the texture and the pixel shader are the test's.
std::string full_screen(const std::string& texture_and_pixel_shader) {
  return texture_and_pixel_shader + R"(
void VS(float4 p : POSITION, float2 uv : TEXCOORD0, out float4 o : POSITION, out float2 t : TEXCOORD0) {
  o = float4(p.xy * 2, 0.5, 1); t = uv; }
technique T { pass P { CullMode = None; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";
}

// Engine-Nine's cage.fx texture shader, at the test's size.
constexpr const char* kStripe = R"(
texture stripeTex < string function = "MakeStripe"; string UIWidget = "None"; float2 Dimensions = { 32, 32 }; >;
sampler2D stripeTexSampler = sampler_state { Texture = <stripeTex>; };
float4 MakeStripe(float2 Pos : POSITION, float ps : PSIZE) : COLOR {
   float v = 0; float nx = Pos.x+ps; v = nx > Pos.y; return float4(v.xxxx); }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(stripeTexSampler, uv); }
)";

class TextureShaderRenderTest : public VulkanTest {
 protected:
  // The image of `text` drawn on a quad; `set` runs before the first frame (parameters).
  std::optional<fx::Image> draw(const std::string& name, const std::string& text,
                                const std::function<void(ParameterStore&)>& set = {}) {
    DiagnosticSink sink;
    folder_.write(name, text);
    auto e =
        bind_effect(ctx(), folder_.path(name), "", "quad", kSize, std::nullopt, VK_FORMAT_R8G8B8A8_UNORM, false, &sink);
    if (!e) return std::nullopt;
    if (set) set(*e->effect->params);
    auto image = e->preview->render(*e->binding, e->technique, e->layout, sink);
    for (const Diagnostic& d : sink.diagnostics())
      EXPECT_EQ(d.id.find("texture-shader"), std::string::npos) << describe(sink);
    EXPECT_TRUE(image) << describe(sink);
    return image;
  }
  fx::testing::EffectFolder folder_{"texture_shader_render"};
};

std::array<int, 4> pixel(const fx::Image& image, uint32_t x, uint32_t y) {
  const uint8_t* p = image.at(x, y);
  return {p[0], p[1], p[2], p[3]};
}

void expect_near(const std::array<int, 4>& got, const std::array<int, 4>& want, const std::string& what) {
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1) << what << " channel " << c;
}

// The stripe is white where x + 1 > y (the texel centre plus one texel's size passes the
// diagonal), black below it: the stand-in would be white everywhere.
TEST_F(TextureShaderRenderTest, TheStripeOfEngineNinesCageFillsTheTexture) {
  auto image = draw("stripe.fx", full_screen(kStripe));
  ASSERT_TRUE(image);
  for (uint32_t y = 0; y < kSize; y += 3)
    for (uint32_t x = 0; x < kSize; x += 3) {
      const int want = x + 1 > y ? 255 : 0;
      if (x + 1 == y) continue;  // the diagonal: the comparison rounds either way
      expect_near(pixel(*image, x, y), {want, want, want, want},
                  "texel " + std::to_string(x) + "," + std::to_string(y));
    }
}

// The globals a texture shader reads are the effect's values when the texture is filled.
TEST_F(TextureShaderRenderTest, GlobalsAreReadAtTheirValuesWhenTheTextureIsFilled) {
  const std::string text = full_screen(R"(
float Threshold = 0.5;
float4 Tint = {1, 0.5, 0.25, 1};
texture Ramp < string function = "Step"; int width = 32; int height = 32; >;
sampler2D RampSampler = sampler_state { Texture = <Ramp>; MinFilter = Point; MagFilter = Point; };
float4 Step(float2 p : POSITION) : COLOR { return p.x > Threshold ? Tint : float4(0, 0, 0, 1); }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(RampSampler, uv); }
)");
  auto image = draw("globals.fx", text,
                    [](ParameterStore& params) { EXPECT_TRUE(params.set(params.find("Threshold"), 0.25f)); });
  ASSERT_TRUE(image);
  expect_near(pixel(*image, 4, 16), {0, 0, 0, 255}, "left of the threshold");
  expect_near(pixel(*image, 12, 16), {255, 128, 64, 255}, "right of 0.25, left of the default 0.5");
  expect_near(pixel(*image, 28, 16), {255, 128, 64, 255}, "right of both");
}

// A volume: each texel holds its centre, sampled at three known texels.
TEST_F(TextureShaderRenderTest, AVolumeTextureHoldsEachTexelsCentre) {
  const std::string text = full_screen(R"(
texture3D Vol < string function = "Centre"; int width = 4; int height = 4; int depth = 4; >;
sampler3D VolSampler = sampler_state { Texture = <Vol>; MinFilter = Point; MagFilter = Point; };
float4 Centre(float3 p : POSITION, float3 s : PSIZE) : COLOR { return float4(p, s.z * 4); }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex3D(VolSampler, float3(uv, uv.x * 0.5 + 0.25)); }
)");
  auto image = draw("volume.fx", text);
  ASSERT_TRUE(image);
  // Pixel (x, y) samples texel (x / 8, y / 8, (x / 32 * 0.5 + 0.25) * 4).
  for (const auto& [x, y] : {std::pair{2u, 2u}, {12u, 27u}, {30u, 20u}}) {
    const float u = (x + 0.5f) / kSize, v = (y + 0.5f) / kSize, w = u * 0.5f + 0.25f;
    const auto centre = [](float c) { return int(std::lround((std::floor(c * 4) + 0.5f) / 4 * 255)); };
    expect_near(pixel(*image, x, y), {centre(u), centre(v), centre(w), 255},
                "pixel " + std::to_string(x) + "," + std::to_string(y));
  }
}

// A cube: each texel holds the direction through its centre (D3DX's -1..1 face coordinates),
// so a direction sampled at a texel centre of two faces reads that direction back.
TEST_F(TextureShaderRenderTest, ACubeTextureHoldsEachTexelsDirection) {
  const std::string text = full_screen(R"(
textureCUBE Sky < string function = "Direction"; int width = 4; >;
samplerCUBE SkySampler = sampler_state { Texture = <Sky>; MinFilter = Point; MagFilter = Point; };
float4 Direction(float3 d : POSITION) : COLOR { return float4(d * 0.5 + 0.5, 1); }
float4 PS(float2 uv : TEXCOORD0) : COLOR {
  return uv.x < 0.5 ? texCUBE(SkySampler, float3(1, -0.25, -0.25)) : texCUBE(SkySampler, float3(0.25, -1, -0.25)); }
)");
  auto image = draw("cube.fx", text);
  ASSERT_TRUE(image);
  expect_near(pixel(*image, 8, 16), {255, 96, 96, 255}, "+X face, texel (2, 2)");
  expect_near(pixel(*image, 24, 16), {159, 0, 96, 255}, "-Y face, texel (2, 2)");
}

// tx_1_0's noise(): 0 at lattice points (red: 128 everywhere), varying between them (green),
// within -1..1.
TEST_F(TextureShaderRenderTest, NoiseIsZeroAtLatticePointsAndVariesBetweenThem) {
  const std::string text = full_screen(R"(
texture Clouds < string function = "MakeClouds"; int width = 32; int height = 32; >;
sampler2D CloudSampler = sampler_state { Texture = <Clouds>; MinFilter = Point; MagFilter = Point; };
float4 MakeClouds(float2 p : POSITION) : COLOR {
  return float4(noise(floor(p * 4)), noise(p * 4), 0, 0) * 0.5 + 0.5; }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(CloudSampler, uv); }
)");
  auto image = draw("noise.fx", text);
  ASSERT_TRUE(image);
  int lowest = 255, highest = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const std::array<int, 4> p = pixel(*image, x, y);
      EXPECT_NEAR(p[0], 128, 1) << x << "," << y;
      lowest = std::min(lowest, p[1]);
      highest = std::max(highest, p[1]);
    }
  EXPECT_GT(highest - lowest, 60) << "noise varies between lattice points";
}

// A function that cannot run as a compute shader (it samples a texture) leaves the stand-in
// bound and says why at the annotation.
TEST_F(TextureShaderRenderTest, AFunctionThatReadsATextureGetsTheStandInAndAWarning) {
  const std::string text = full_screen(R"(
texture Other;
sampler2D OtherSampler = sampler_state { Texture = <Other>; };
texture Copy < string function = "CopyOther"; >;
sampler2D CopySampler = sampler_state { Texture = <Copy>; };
float4 CopyOther(float2 p : POSITION) : COLOR { return tex2Dlod(OtherSampler, float4(p, 0, 0)); }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(CopySampler, uv); }
)");
  DiagnosticSink sink;
  folder_.write("reads.fx", text);
  auto e = bind_effect(ctx(), folder_.path("reads.fx"), "", "quad", kSize, std::nullopt, VK_FORMAT_R8G8B8A8_UNORM,
                       false, &sink);
  ASSERT_TRUE(e);
  const std::string said = describe(sink);
  EXPECT_NE(said.find("vk-texture-shader-failed"), std::string::npos) << said;
  EXPECT_NE(said.find("reads 'OtherSampler'"), std::string::npos) << said;
  auto image = e->preview->render(*e->binding, e->technique, e->layout, sink);
  ASSERT_TRUE(image) << describe(sink);
  expect_near(pixel(*image, 16, 16), {255, 255, 255, 255}, "the white stand-in");
}

}  // namespace
}  // namespace fx::vk::testing
