// Pass state rendered on the device: blending, depth, stencil, culling, sampler addressing,
// the dynamic-state and static pipeline paths giving byte-equal images, pipeline counts,
// redundant state skipping, and dirty-only uniform uploads.
#include <gtest/gtest.h>

#include <cmath>

#include "pass_test_util.h"

namespace fx::vk {
namespace {

using namespace testing;

const std::vector<Vertex> kFullQuad = [] {
  std::vector<Vertex> v;
  add_quad(v, -1, -1, 1, 1, 0.5f);
  return v;
}();

// Both pipeline paths, for tests that must hold on either.
class PipelineRender : public VulkanTest, public ::testing::WithParamInterface<bool> {
 protected:
  DynamicStateSet dynamic() const {
    return GetParam() ? DynamicStateSet::from_features(ctx().features()) : DynamicStateSet::none();
  }
  void TearDown() override {
    EXPECT_EQ(ctx().validation_warning_count(), 0u) << describe_messages(ctx());
    VulkanTest::TearDown();
  }
};

void set_color(PassResources& r, float red, float green, float blue, float alpha) {
  DiagnosticSink sink;
  const float c[4] = {red, green, blue, alpha};
  ASSERT_TRUE(r.set_uniform("Color", c, sizeof c, sink)) << describe(sink);
}

TEST_P(PipelineRender, BlendFactorsGiveAdditiveAndAlphaBlendedValues) {
  PassHarness h(ctx(), dynamic());
  auto prog = make_program(ctx(), "PSColor");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input) << describe(sink);
  PassResources res(prog->program);
  set_color(res, 0.5f, 0.25f, 0.0f, 0.5f);
  VkBuffer vb = h.vertices(kFullQuad);

  PipelineState additive;
  additive.blend[0].blend_enable = 1;
  additive.blend[0].src_color = VK_BLEND_FACTOR_ONE;
  additive.blend[0].dst_color = VK_BLEND_FACTOR_ONE;
  PipelineState alpha = additive;
  alpha.blend[0].src_color = VK_BLEND_FACTOR_SRC_ALPHA;
  alpha.blend[0].dst_color = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;

  const std::array<float, 4> clear = {0.25f, 0.25f, 0.25f, 1};
  fx::Image a = h.render(
      [&](VkCommandBuffer cmd, PassRecorder& r) {
        draw(cmd, r, {&prog->program, additive, &*input, &res}, vb, 6);
      },
      clear);
  fx::Image b = h.render(
      [&](VkCommandBuffer cmd, PassRecorder& r) {
        draw(cmd, r, {&prog->program, alpha, &*input, &res}, vb, 6);
      },
      clear);
  auto near = [](std::array<int, 4> got, std::array<double, 3> want) {
    for (int c = 0; c < 3; ++c)
      if (std::abs(got[c] - want[c] * 255.0) > 1.0) return false;
    return true;
  };
  // ONE/ONE: 0.25 + colour. SRC_ALPHA/INV_SRC_ALPHA: 0.5 * colour + 0.5 * 0.25.
  EXPECT_TRUE(near(pixel(a, 4, 4), {0.75, 0.5, 0.25}));
  EXPECT_TRUE(near(pixel(b, 4, 4), {0.375, 0.25, 0.125}));
}

TEST_P(PipelineRender, DepthTestAndWrite) {
  PassHarness h(ctx(), dynamic());
  auto prog = make_program(ctx(), "PSColor");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input);
  PassResources near_res(prog->program), far_res(prog->program);
  set_color(near_res, 0, 1, 0, 1);
  set_color(far_res, 1, 0, 0, 1);
  std::vector<Vertex> v;
  add_quad(v, -1, -1, 1, 1, 0.2f);  // near
  add_quad(v, -1, -1, 1, 1, 0.8f);  // far, drawn second
  VkBuffer vb = h.vertices(v);
  for (bool write : {true, false}) {
    PipelineState s;
    s.depth_test = 1;
    s.depth_write = write;
    s.depth_compare = VK_COMPARE_OP_LESS;
    fx::Image img = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
      draw(cmd, r, {&prog->program, s, &*input, &near_res}, vb, 6, 0);
      draw(cmd, r, {&prog->program, s, &*input, &far_res}, vb, 6, 6);
    });
    // With depth writes the far quad fails the test; without, the cleared depth (1.0) lets it through.
    EXPECT_EQ(pixel(img, 3, 3), (write ? std::array<int, 4>{0, 255, 0, 255} : std::array<int, 4>{255, 0, 0, 255}));
  }
}

TEST_P(PipelineRender, StencilMasksTheSecondPass) {
  PassHarness h(ctx(), dynamic());
  auto prog = make_program(ctx(), "PSColor");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input);
  PassResources res(prog->program);
  set_color(res, 1, 1, 1, 1);
  std::vector<Vertex> v;
  add_quad(v, -1, -1, 0, 1, 0.5f);  // left half: writes stencil only
  add_quad(v, -1, -1, 1, 1, 0.5f);  // full screen: drawn where stencil == 1
  VkBuffer vb = h.vertices(v);
  PipelineState mark;
  mark.stencil_test = 1;
  mark.front_compare = mark.back_compare = VK_COMPARE_OP_ALWAYS;
  mark.front_pass = mark.back_pass = VK_STENCIL_OP_REPLACE;
  mark.front_reference = mark.back_reference = 1;
  mark.blend[0].write_mask = 0;
  PipelineState masked;
  masked.stencil_test = 1;
  masked.front_compare = masked.back_compare = VK_COMPARE_OP_EQUAL;
  masked.front_reference = masked.back_reference = 1;
  fx::Image img = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
    draw(cmd, r, {&prog->program, mark, &*input, &res}, vb, 6, 0);
    draw(cmd, r, {&prog->program, masked, &*input, &res}, vb, 6, 6);
  });
  EXPECT_EQ(pixel(img, 1, 4), (std::array<int, 4>{255, 255, 255, 255}));
  EXPECT_EQ(pixel(img, 6, 4), (std::array<int, 4>{0, 0, 0, 255}));
}

TEST_P(PipelineRender, CullModeAndFrontFace) {
  PassHarness h(ctx(), dynamic());
  auto prog = make_program(ctx(), "PSColor");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input);
  PassResources res(prog->program);
  set_color(res, 1, 1, 1, 1);
  std::vector<Vertex> v;
  add_quad(v, -1, -1, 1, 1, 0.5f, 0, 1, /*clockwise=*/true);
  VkBuffer vb = h.vertices(v);
  auto drawn = [&](VkCullModeFlags cull, VkFrontFace front) {
    PipelineState s;
    s.cull_mode = cull;
    s.front_face = front;
    fx::Image img = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
      draw(cmd, r, {&prog->program, s, &*input, &res}, vb, 6);
    });
    return pixel(img, 4, 4)[0] == 255;
  };
  EXPECT_TRUE(drawn(VK_CULL_MODE_NONE, VK_FRONT_FACE_COUNTER_CLOCKWISE));
  EXPECT_TRUE(drawn(VK_CULL_MODE_BACK_BIT, VK_FRONT_FACE_CLOCKWISE));
  EXPECT_FALSE(drawn(VK_CULL_MODE_FRONT_BIT, VK_FRONT_FACE_CLOCKWISE));
  EXPECT_FALSE(drawn(VK_CULL_MODE_BACK_BIT, VK_FRONT_FACE_COUNTER_CLOCKWISE));
  EXPECT_TRUE(drawn(VK_CULL_MODE_FRONT_BIT, VK_FRONT_FACE_COUNTER_CLOCKWISE));
}

// Texel index Vulkan's nearest filter picks for integer texel coordinate i of a size-2 texture,
// or -1 for the border colour.
int address(VkSamplerAddressMode mode, int i) {
  switch (mode) {
    case VK_SAMPLER_ADDRESS_MODE_REPEAT: return ((i % 2) + 2) % 2;
    case VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE: return i < 0 ? 0 : (i > 1 ? 1 : i);
    case VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT: {
      const int m = ((i % 4) + 4) % 4 - 2;
      return 1 - (m >= 0 ? m : -(1 + m));
    }
    default: return (i < 0 || i > 1) ? -1 : i;
  }
}

TEST_P(PipelineRender, SamplerAddressModesOnAMagnifiedTwoByTwoTexture) {
  PassHarness h(ctx(), dynamic());
  auto prog = make_program(ctx(), "PSTex");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input);
  fx::Image texels = fx::Image::blank(2, 2, 4);
  const uint8_t colors[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
  for (int i = 0; i < 4; ++i) std::memcpy(texels.at(i % 2, i / 2), colors[i], 4);
  auto tex = Texture::from_image(ctx(), texels, ColorSpace::linear, sink);
  ASSERT_TRUE(tex) << describe(sink);
  SamplerCache samplers(ctx());
  std::vector<Vertex> v;
  add_quad(v, -1, -1, 1, 1, 0.5f, -1, 2);  // uv from -1 to 2 over 8 pixels
  VkBuffer vb = h.vertices(v);
  for (VkSamplerAddressMode mode : {VK_SAMPLER_ADDRESS_MODE_REPEAT, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                    VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER}) {
    SamplerKey d;
    d.min_filter = d.mag_filter = VK_FILTER_NEAREST;
    d.mip_filter = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    d.address_u = d.address_v = d.address_w = mode;
    d.border = VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK;
    PassResources res(prog->program);
    ASSERT_TRUE(res.bind("Tex", *tex, samplers.get(d, sink), sink)) << describe(sink);
    fx::Image img = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
      draw(cmd, r, {&prog->program, PipelineState{}, &*input, &res}, vb, 6);
    });
    for (uint32_t y = 0; y < 8; ++y)
      for (uint32_t x = 0; x < 8; ++x) {
        const double u = -1 + (x + 0.5) * 3 / 8, vv = -1 + (y + 0.5) * 3 / 8;
        const int tx = address(mode, int(std::floor(u * 2))), ty = address(mode, int(std::floor(vv * 2)));
        std::array<int, 4> want = {0, 0, 0, 255};
        if (tx >= 0 && ty >= 0)
          for (int c = 0; c < 4; ++c) want[c] = colors[ty * 2 + tx][c];
        ASSERT_EQ(pixel(img, x, y), want) << "mode " << mode << " at " << x << "," << y;
      }
  }
  EXPECT_EQ(samplers.size(), 4u);
}

INSTANTIATE_TEST_SUITE_P(Paths, PipelineRender, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "dynamic" : "static"; });

}  // namespace
}  // namespace fx::vk
