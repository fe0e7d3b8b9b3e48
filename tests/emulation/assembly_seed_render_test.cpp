// The seeds' shader model 1 techniques drawn on the validated device: each against its
// golden image, against its HLSL sibling in the same effect (differences in 8-bit levels,
// bounded per technique for the reasons in docs/legacy-assembly.md), and the x^16 squaring
// banding with the ps.1.x precision model against the CPU interpreter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "asm_interpreter.h"
#include "effect_test_util.h"

namespace fx::vk::testing {
namespace {

class AssemblySeedTest : public VulkanTest {};

// RGB difference over the pixels either image covers (not the clear colour of the corner).
struct SiblingDiff {
  double mean = 0;
  int p95 = 0, max = 0;
  size_t pixels = 0;
};

SiblingDiff sibling_diff(const fx::Image& a, const fx::Image& b) {
  SiblingDiff d;
  std::vector<int> all;
  const uint8_t* bg = a.at(0, 0);
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      const uint8_t *pa = a.at(x, y), *pb = b.at(x, y);
      if (std::equal(pa, pa + 3, bg) && std::equal(pb, pb + 3, bg)) continue;
      for (int k = 0; k < 3; ++k) all.push_back(std::abs(int(pa[k]) - int(pb[k])));
      ++d.pixels;
    }
  if (all.empty()) return d;
  std::sort(all.begin(), all.end());
  double sum = 0;
  for (int v : all) sum += v;
  d.mean = sum / double(all.size());
  d.p95 = all[all.size() * 95 / 100];
  d.max = all.back();
  return d;
}

struct SeedCase {
  const char* file;
  const char* technique;
  const char* sibling;  // the HLSL technique drawing the same look
  double mean_bound;    // mean RGB difference allowed, 8-bit levels
  int p95_bound;        // 95th percentile allowed
};

// Bounds: the figures measured on lavapipe (docs/legacy-assembly.md) plus about 15%. The
// listings are not their siblings' formulas, so the bounds are wide where they differ:
// D3D9's default point sampling where the HLSL samplers filter, interpolated vectors used
// without renormalisation (everywhere), the BRDF factors resampled as cube maps and the
// listing's lobe not cut off below the horizon, specular-only listings
// (specular_table_ps11, specular_squaring_ps11: no N.L term), the strand listings' sums
// without the HLSL model's Kd/Ks weights and ambient (ps.1.1 adds the base map's gloss alpha unweighted,
// the seed's `mad r0, t3, t1, t1.a`, so it saturates). The golden images guard the
// translation itself; these say how far each listing is from the HLSL model.
const SeedCase kSeeds[] = {
    {"brdf.fx", "tec0", "brdf_ps20", 3, 21},
    {"hemisphere.fx", "hemisphere_ps11", "hemisphere_two_term", 6, 27},
    {"per_pixel_lighting.fx", "diffuse_ps11", "diffuse_ps20", 18, 62},
    {"per_pixel_lighting.fx", "specular_table_ps11", "specular_table_ps20", 62, 150},
    {"per_pixel_lighting.fx", "specular_squaring_ps11", "specular_squaring_ps20", 77, 235},
    {"strand_aniso.fx", "strand_four_lights_ps14", "strand_four_lights", 79, 107},
    {"strand_aniso.fx", "strand_lut_ps11", "strand_lut_seed_wrap", 182, 214},
    // Assembly vertex shaders with generated fixed-function texture stages: per-vertex
    // lighting against per-pixel (hemisphere_vs11), the emboss techniques' grey relief
    // (no colour map in the seed's emboss passes) against the coloured HLSL lighting.
    {"hemisphere.fx", "hemisphere_vs11", "hemisphere_per_vertex", 64, 120},
    {"per_pixel_lighting.fx", "dot3_multitexture", "diffuse_ps20", 18, 62},
    {"per_pixel_lighting.fx", "emboss", "diffuse_ps20", 88, 142},
    {"per_pixel_lighting.fx", "specular_emboss", "specular_pow_ps20", 88, 143},
};

TEST_F(AssemblySeedTest, SeedTechniquesMatchGoldenImagesAndTheirHlslSiblings) {
  for (const SeedCase& c : kSeeds) {
    SCOPED_TRACE(c.technique);
    auto a = bind_effect(ctx(), effects_dir() + "/" + c.file, c.technique, "sphere", 128);
    auto h = bind_effect(ctx(), effects_dir() + "/" + c.file, c.sibling, "sphere", 128);
    ASSERT_TRUE(a && h);
    auto ia = a->render(), ih = h->render();
    ASSERT_TRUE(ia && ih);
    EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
    expect_golden(*ia, std::string("asm_") + c.technique + "_sphere");
    SiblingDiff d = sibling_diff(*ia, *ih);
    std::printf("[ measured ] %s vs %s: mean %.2f, p95 %d, max %d levels over %zu pixels\n", c.technique, c.sibling,
                d.mean, d.p95, d.max, d.pixels);
    EXPECT_GT(d.pixels, 128u * 128u / 6);
    EXPECT_LE(d.mean, c.mean_bound);
    EXPECT_LE(d.p95, c.p95_bound);
  }
}

// The seed's ps.1.4 four-light listing shows the highlight structure of its HLSL sibling (it
// drew a white disc of 6 colours while the vertex shader halved L and V that the listing's
// dp3_d2 halves again), and the translation computes the listing's own formula: against the
// sibling with the listing's weights (Kd = Ks = 1, no ambient) it differs only by the
// sibling's gloss factor, filtering and renormalisation (docs/effects.md).
TEST_F(AssemblySeedTest, TheFourLightListingShowsItsSiblingsHighlights) {
  const std::string file = effects_dir() + "/strand_aniso.fx";
  auto listing = bind_effect(ctx(), file, "strand_four_lights_ps14", "sphere", 256);
  auto sibling = bind_effect(ctx(), file, "strand_four_lights", "sphere", 256);
  ASSERT_TRUE(listing && sibling);
  for (const char* name : {"Kd", "Ks"})
    ASSERT_TRUE(sibling->effect->params->set(sibling->effect->params->find(name), 1.0f));
  const float no_ambient[4] = {0, 0, 0, 1};
  ASSERT_TRUE(
      sibling->effect->params->set(sibling->effect->params->find("AmbientColor"), std::span<const float>(no_ambient)));
  auto il = listing->render(), is = sibling->render();
  ASSERT_TRUE(il && is);
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
  std::set<uint32_t> colours;
  for (uint32_t y = 0; y < il->height; ++y)
    for (uint32_t x = 0; x < il->width; ++x) {
      const uint8_t* p = il->at(x, y);
      colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
    }
  const SiblingDiff d = sibling_diff(*il, *is);
  std::printf(
      "[ measured ] strand_four_lights_ps14: %zu colours; against strand_four_lights with Kd = Ks = 1 and no "
      "ambient: mean %.2f, p95 %d, max %d levels\n",
      colours.size(), d.mean, d.p95, d.max);
  EXPECT_GT(colours.size(), 1000u);
  EXPECT_LE(d.mean, 6.0);
  EXPECT_LE(d.p95, 20);
}

// D3DTOP_DOTPRODUCT3 then Modulate (dot3_multitexture, generated texture stages) is the
// same arithmetic as diffuse_ps11's `dp3_sat r1, t1_bx2, v0_bx2; mul r0, t0, r1`
// (translated assembly) with the same vertex shader: the two paths agree.
TEST_F(AssemblySeedTest, Dot3StagesAgreeWithTheirPs11Listing) {
  auto stages = bind_effect(ctx(), effects_dir() + "/per_pixel_lighting.fx", "dot3_multitexture", "sphere", 128);
  auto listing = bind_effect(ctx(), effects_dir() + "/per_pixel_lighting.fx", "diffuse_ps11", "sphere", 128);
  ASSERT_TRUE(stages && listing);
  auto a = stages->render(), b = listing->render();
  ASSERT_TRUE(a && b);
  SiblingDiff d = sibling_diff(*a, *b);
  std::printf("[ measured ] dot3_multitexture vs diffuse_ps11: mean %.3f, max %d levels\n", d.mean, d.max);
  EXPECT_LE(d.max, 1);
}

// x^16 by four squarings (the seed's specular exponent) of an 8-bit input ramp: with the
// precision model each pixel is the CPU model's value for its (quantized) input, carried in
// alpha, and the 8-bit registers leave far fewer distinct levels than float arithmetic.
TEST_F(AssemblySeedTest, SquaringBandingMatchesTheCpuModel) {
  auto technique = [](const std::string& header) {
    return header + R"( { pass p {
  VertexShaderConstant[0] = <WorldViewProjection>;
  VertexShader = asm { vs.1.1
    m4x4 oPos, v0, c0
    mov oD0, v7.xxxx };
  PixelShader = asm { ps.1.1
    mul r1, v0, v0
    mul r1, r1, r1
    mul r1, r1, r1
    mul r0.rgb, r1, r1
    +mov r0.a, v0 };
} }
)";
  };
  const std::string effect = "float4x4 WorldViewProjection : WORLDVIEWPROJECTION;\n" +
                             technique("technique banded < bool Ps1xPrecision = true; >") +
                             technique("technique smooth");
  const std::string path = write_effect("squaring.fx", effect);
  auto banded = bind_effect(ctx(), path, "banded", "quad", 256, std::nullopt, VK_FORMAT_R32G32B32A32_SFLOAT);
  auto smooth = bind_effect(ctx(), path, "smooth", "quad", 256, std::nullopt, VK_FORMAT_R32G32B32A32_SFLOAT);
  ASSERT_TRUE(banded && smooth);
  auto ib = banded->render_floats(), is = smooth->render_floats();
  ASSERT_TRUE(ib && is);
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());

  const PassInfo& pass = banded->effect->model->techniques[0].passes[0];
  DiagnosticSink sink;
  std::optional<emulation::AsmProgram> ps;
  for (const ShaderBinding& b : pass.shaders)
    if (b.stage == PassStage::pixel)
      ps = emulation::parse_assembly(*banded->effect->model->ast, b.asm_code, b.decl_code, sink);
  ASSERT_TRUE(ps) << describe(sink);

  std::set<int> banded_levels, smooth_levels, model_levels;
  size_t checked = 0, off = 0;
  for (uint32_t y = 0; y < ib->height; y += 4)
    for (uint32_t x = 0; x < ib->width; ++x) {
      const float* b = ib->at(x, y);
      const float* s = is->at(x, y);
      if (b[0] == 0.08f && b[1] == 0.08f && b[2] == 0.1f) continue;  // the clear colour: outside the quad
      emulation::testing::AsmMachine m;
      m.hardware_precision = true;
      m.v[0] = {b[3], b[3], b[3], b[3]};  // the input as the GPU quantized it
      m.run(*ps);
      off += std::abs(b[0] - m.r0[0]) > 1e-4;
      ++checked;
      banded_levels.insert(int(std::lround(b[0] * 1e4)));
      smooth_levels.insert(int(std::lround(s[0] * 1e4)));
      model_levels.insert(int(std::lround(m.r0[0] * 1e4)));
    }
  std::printf(
      "[ measured ] x^16 by squaring over a ramp: %zu distinct levels with the ps.1.1 model (CPU model %zu), "
      "%zu in float\n",
      banded_levels.size(), model_levels.size(), smooth_levels.size());
  EXPECT_GT(checked, 1000u);
  EXPECT_EQ(off, 0u);
  EXPECT_EQ(banded_levels.size(), model_levels.size());
  EXPECT_LT(banded_levels.size() * 4, smooth_levels.size());
}

}  // namespace
}  // namespace fx::vk::testing
