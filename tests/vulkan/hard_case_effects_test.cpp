// Every drawable technique of every effect in effects/, rendered with its light directions
// and positions and its exponents set to the hard cases (zero vectors, the light exactly at
// and exactly opposite the camera, along each axis, a zero exponent) into a half-float
// target: no channel of any output is NaN or Inf. The 8-bit pictures would hide both (the unorm store clamps
// Inf and turns NaN into an arbitrary level).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "effect_test_util.h"
#include "fx/ascii_case.h"

namespace fx::vk {
namespace {

using namespace testing;

class HardCaseEffects : public VulkanTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
    VulkanTest::TearDown();
  }
};

bool contains(std::string_view text, std::string_view word) {
  return ascii_lower(text).find(ascii_lower(word)) != std::string::npos;
}

// A light direction: a float3/float4 whose semantic is DIRECTION or whose name says so.
bool is_direction(const Parameter& p) {
  const Type& t = p.type;
  return t.is_numeric() && !t.is_array() && t.rows == 1 && (t.cols == 3 || t.cols == 4) &&
         (iequals(p.semantic, "DIRECTION") || contains(p.name, "direction") || contains(p.name, "lightdir"));
}

// A point light's position: a float3/float4 light parameter with POSITION in its semantic or name.
bool is_light_position(const Parameter& p) {
  const Type& t = p.type;
  return t.is_numeric() && !t.is_array() && t.rows == 1 && (t.cols == 3 || t.cols == 4) && contains(p.name, "light") &&
         (iequals(p.semantic, "POSITION") || contains(p.name, "position"));
}

// A specular exponent: a float scalar named so, or with the SPECULARPOWER semantic.
bool is_exponent(const Parameter& p) {
  const Type& t = p.type;
  return t.is_numeric() && !t.is_array() && t.rows == 1 && t.cols == 1 &&
         (iequals(p.semantic, "SPECULARPOWER") || contains(p.name, "exponent") || contains(p.name, "shininess"));
}

struct HardCase {
  std::string name;
  // Every light direction set to this; point lights go to -direction x |eye| (the light
  // where a directional light with this direction would come from, at the camera's
  // distance), the origin for the zero vector.
  std::optional<glm::vec3> direction;
  bool zero_exponent = false;
};

std::vector<HardCase> hard_cases(const glm::vec3& eye) {
  const glm::vec3 to_eye = glm::normalize(eye);
  return {
      {"defaults", std::nullopt},
      {"zero direction", glm::vec3(0.f)},
      // Directions point from the light into the scene: -to_eye puts the light at the camera
      // (L = V at the centre), +to_eye behind the object (L = -V: the half vector vanishes).
      {"light at the camera", -to_eye},
      {"light opposite the camera", to_eye},
      {"+x", glm::vec3(1, 0, 0)},
      {"-x", glm::vec3(-1, 0, 0)},
      {"+y", glm::vec3(0, 1, 0)},
      {"-y", glm::vec3(0, -1, 0)},
      {"+z", glm::vec3(0, 0, 1)},
      {"-z", glm::vec3(0, 0, -1)},
      {"zero exponent", std::nullopt, true},
      {"zero exponent, light opposite the camera", to_eye, true},
  };
}

// Sets the case on every matching parameter (defaults first, so cases do not accumulate).
void apply(const HardCase& c, RenderedEffect& r) {
  ParameterStore& params = *r.effect->params;
  const float distance = glm::length(r.preview->scene().eye);
  for (const Parameter& p : r.effect->model->parameters) {
    Param h = params.find(p.name);
    if (!h.valid() || !(is_direction(p) || is_light_position(p) || is_exponent(p))) continue;
    ASSERT_TRUE(params.reset(h)) << p.name;
    if (is_direction(p) && c.direction) {
      const float v[4] = {c.direction->x, c.direction->y, c.direction->z, 0.f};
      ASSERT_TRUE(params.set(h, std::span<const float>(v, p.type.cols))) << p.name;
    }
    if (is_light_position(p) && c.direction) {
      const glm::vec3 at = -*c.direction * distance;
      const float v[4] = {at.x, at.y, at.z, 1.f};
      ASSERT_TRUE(params.set(h, std::span<const float>(v, p.type.cols))) << p.name;
    }
    if (is_exponent(p) && c.zero_exponent) {
      ASSERT_TRUE(params.set(h, 0.f)) << p.name;
    }
  }
}

// Renders the bound technique with `c` applied; the number of non-finite channels.
size_t non_finite_channels(RenderedEffect& r, const HardCase& c) {
  apply(c, r);
  auto image = r.render_floats();
  size_t bad = 0;
  if (image)
    for (float v : image->pixels) bad += !std::isfinite(v);
  return bad;
}

// The check can fail: an unguarded normalize of a zero light direction is NaN on the device.
TEST_F(HardCaseEffects, AnUnguardedNormalizeIsCaught) {
  const std::string path = write_effect("unguarded.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float3 LightDirection : DIRECTION = {0.0, -1.0, 0.0};
struct VSOut { float4 pos : POSITION; float3 n : TEXCOORD0; };
VSOut VS(float4 pos : POSITION, float3 n : NORMAL) { VSOut o; o.pos = mul(pos, WorldViewProjection); o.n = n; return o; }
float4 PS(float3 n : TEXCOORD0) : COLOR0 { return float4(dot(normalize(n), -normalize(LightDirection)).xxx, 1.0); }
technique t { pass p { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  auto r = bind_effect(ctx(), path, "", "sphere", 16, std::nullopt, VK_FORMAT_R16G16B16A16_SFLOAT);
  ASSERT_TRUE(r);
  EXPECT_EQ(non_finite_channels(*r, {"defaults", std::nullopt}), 0u);
  EXPECT_GT(non_finite_channels(*r, {"zero direction", glm::vec3(0.f)}), 0u);
}

TEST_F(HardCaseEffects, NoTechniqueOutputsNanOrInfOnHardCaseParameters) {
  size_t renders = 0, techniques = 0, directions = 0, exponents = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(effects_dir())) {
    if (entry.path().extension() != ".fx") continue;
    SCOPED_TRACE(entry.path().string());
    auto r = bind_effect(ctx(), entry.path().string(), "", "sphere", 32, std::nullopt, VK_FORMAT_R16G16B16A16_SFLOAT);
    ASSERT_TRUE(r);
    for (const Parameter& p : r->effect->model->parameters)
      directions += is_direction(p) || is_light_position(p), exponents += is_exponent(p);
    for (uint32_t t = 0; t < r->binding->technique_count(); ++t) {
      if (!r->binding->technique_ok(t)) continue;  // asm / fixed function: not drawn on Vulkan
      SCOPED_TRACE(r->effect->model->techniques[t].name);
      ++techniques;
      r->use_technique(t);
      for (const HardCase& c : hard_cases(r->preview->scene().eye)) {
        SCOPED_TRACE(c.name);
        EXPECT_EQ(non_finite_channels(*r, c), 0u) << "non-finite channels in the output";
        ++renders;
      }
    }
  }
  std::printf("hard-case effects: %zu techniques, %zu renders, %zu light and %zu exponent parameters\n", techniques,
              renders, directions, exponents);
  EXPECT_GE(techniques, 25u);
  EXPECT_GE(directions, 6u);
  EXPECT_GE(exponents, 2u);
}

}  // namespace
}  // namespace fx::vk
