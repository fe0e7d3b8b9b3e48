// Texture stand-ins on the validated device: with the preview's stand-ins a colour texture no
// file fills samples as the test pattern's texels, a bump map as a flat normal, a depth input
// as a ramp and a cube map as sky above ground; without them (an engine's), white.
#include <gtest/gtest.h>

#include "effect_folder.h"
#include "effect_test_util.h"
#include "fx/binding/texture_stand_in.h"

namespace fx::vk::testing {
namespace {

constexpr const char* kSampling = R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float2 At = {0.5, 0.5};
float3 Dir = {0, 1, 0};
texture Diffuse;
texture BumpMap;
texture SceneDepth;
textureCUBE EnvMap;
sampler DiffuseSamp = sampler_state { Texture = <Diffuse>; MinFilter = POINT; MagFilter = POINT; };
sampler BumpSamp = sampler_state { Texture = <BumpMap>; MinFilter = POINT; MagFilter = POINT; };
sampler DepthSamp = sampler_state { Texture = <SceneDepth>; MinFilter = POINT; MagFilter = POINT; };
samplerCUBE EnvSamp = sampler_state { Texture = <EnvMap>; MinFilter = POINT; MagFilter = POINT; };
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 Colour() : COLOR0 { return tex2D(DiffuseSamp, At); }
float4 Bump() : COLOR0 { return tex2D(BumpSamp, At); }
float4 Depth() : COLOR0 { return tex2D(DepthSamp, At); }
float4 Env() : COLOR0 { return texCUBE(EnvSamp, Dir); }
technique TColour { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Colour(); } }
technique TBump { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Bump(); } }
technique TDepth { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Depth(); } }
technique TEnv { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Env(); } }
)";

constexpr uint32_t kSize = 16;

class StandInRenderTest : public VulkanTest {
 protected:
  void SetUp() override {
    VulkanTest::SetUp();
    folder_.write("sampling.fx", kSampling);
  }
  // The colour `technique` draws at the centre of the sphere with `param` set to `value`.
  std::array<int, 4> centre(const std::string& technique, bool preview, const std::string& param = "",
                            std::vector<float> value = {}) {
    auto e = bind_effect(ctx(), folder_.path("sampling.fx"), technique, "sphere", kSize, std::nullopt,
                         VK_FORMAT_R8G8B8A8_UNORM, preview);
    if (!e) return {};
    if (!param.empty()) {
      EXPECT_TRUE(e->effect->params->set(e->effect->params->find(param), std::span<const float>(value)));
    }
    auto image = e->render();
    if (!image) return {};
    const uint8_t* p = image->at(kSize / 2, kSize / 2);
    return {p[0], p[1], p[2], p[3]};
  }
  fx::testing::EffectFolder folder_{"stand_in_render"};
};

// The texel (x, y) of a 64x64 RGBA8 stand-in.
std::array<int, 4> texel(const fx::DdsTexture& t, uint32_t x, uint32_t y) {
  const uint8_t* p = t.data.data() + (size_t(y) * t.width + x) * 4;
  return {p[0], p[1], p[2], p[3]};
}

void expect_near(const std::array<int, 4>& got, const std::array<int, 4>& want, const char* what) {
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1) << what << " channel " << c;
}

TEST_F(StandInRenderTest, AColourTextureSamplesAsTheTestPatternsTexels) {
  const fx::DdsTexture pattern = stand_in_texels(StandIn::test_pattern, ImageDim::dim_2d);
  ASSERT_EQ(pattern.width, 64u);
  // Hues along u: red at the left, cyan-ish in the middle; a dark grid line at texel 8.
  const auto left = texel(pattern, 4, 4), middle = texel(pattern, 36, 4), line = texel(pattern, 8, 4);
  EXPECT_GT(left[0], 200);
  EXPECT_LT(left[2], 30);
  EXPECT_LT(middle[0], 30);
  EXPECT_GT(middle[2], 150);
  EXPECT_LT(line[0] + line[1] + line[2], 100);
  expect_near(centre("TColour", true, "At", {4.5f / 64, 4.5f / 64}), left, "left texel");
  expect_near(centre("TColour", true, "At", {36.5f / 64, 4.5f / 64}), middle, "middle texel");
  expect_near(centre("TColour", true, "At", {8.5f / 64, 4.5f / 64}), line, "grid line");
  // Rows darken downwards.
  const auto low = texel(pattern, 4, 60);
  EXPECT_LT(low[0], left[0] - 80);
  expect_near(centre("TColour", true, "At", {4.5f / 64, 60.5f / 64}), low, "bottom row");
}

TEST_F(StandInRenderTest, WithoutPreviewStandInsAColourTextureIsWhite) {
  expect_near(centre("TColour", false, "At", {4.5f / 64, 4.5f / 64}), {255, 255, 255, 255}, "white");
}

TEST_F(StandInRenderTest, ABumpMapIsAFlatNormalInBothStyles) {
  expect_near(centre("TBump", true), {128, 128, 255, 255}, "preview");
  expect_near(centre("TBump", false), {128, 128, 255, 255}, "neutral");
}

TEST_F(StandInRenderTest, ADepthInputIsARampFromNearToFar) {
  const auto near = centre("TDepth", true, "At", {0.5f / 64, 0.5f / 64});
  const auto far = centre("TDepth", true, "At", {63.5f / 64, 63.5f / 64});
  const auto middle = centre("TDepth", true, "At", {31.5f / 64, 32.5f / 64});
  expect_near(near, {0, 0, 0, 255}, "top left");
  expect_near(far, {255, 255, 255, 255}, "bottom right");
  expect_near(middle, {128, 128, 128, 255}, "middle");
}

TEST_F(StandInRenderTest, ACubeMapIsSkyAboveGround) {
  const auto up = centre("TEnv", true, "Dir", {0, 1, 0});
  const auto down = centre("TEnv", true, "Dir", {0, -1, 0});
  EXPECT_GT(up[2], up[0] + 60) << "blue sky above";
  EXPECT_GT(down[0], down[2] + 30) << "brown ground below";
  EXPECT_LT(down[0] + down[1] + down[2], up[0] + up[1] + up[2]);
  // The compass tint tells east from west on the horizon.
  const auto east = centre("TEnv", true, "Dir", {1, 0, 0});
  const auto west = centre("TEnv", true, "Dir", {-1, 0, 0});
  EXPECT_GT(std::abs(east[0] - west[0]) + std::abs(east[1] - west[1]) + std::abs(east[2] - west[2]), 30);
}

}  // namespace
}  // namespace fx::vk::testing
