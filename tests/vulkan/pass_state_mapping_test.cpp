// Mapping the effect model's pass state summary and samplers into Vulkan state.
#include <gtest/gtest.h>

#include "fx/binding/pass_state_mapping.h"

namespace fx::vk {
namespace {

TEST(PassStateMapping, DefaultsAndD3DRules) {
  PassStateSummary p;  // D3D defaults: cull back (CW front), depth test+write LESS_EQUAL
  DeviceFeatures f;
  DiagnosticSink sink;
  auto s = to_pipeline_state(p, {}, f, sink);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->cull_mode, uint32_t(VK_CULL_MODE_BACK_BIT));
  EXPECT_EQ(s->front_face, uint32_t(VK_FRONT_FACE_CLOCKWISE));
  EXPECT_EQ(s->depth_test, 1u);
  EXPECT_EQ(s->depth_write, 1u);
  EXPECT_EQ(s->depth_compare, uint32_t(VK_COMPARE_OP_LESS_OR_EQUAL));
  EXPECT_EQ(s->depth_bias_enable, 0u);
  // No depth writes without the depth test (D3D ZEnable = FALSE).
  p.depth_test = false;
  EXPECT_EQ(to_pipeline_state(p, {}, f, sink)->depth_write, 0u);
  EXPECT_FALSE(sink.has_errors());
}

// Each of "the projection flips Y" and "the meshes are counter-clockwise" mirrors D3D's
// winding once; both together cancel.
TEST(PassStateMapping, FrontFaceFollowsViewportAndMeshWinding) {
  DeviceFeatures f;
  DiagnosticSink sink;
  auto front = [&](FrontFace effect, bool negative_viewport, FrontFace mesh) {
    PassStateSummary p;
    p.front_face = effect;
    auto s = to_pipeline_state(p, {.negative_viewport_height = negative_viewport, .mesh_front_face = mesh}, f, sink);
    return s ? VkFrontFace(s->front_face) : VK_FRONT_FACE_MAX_ENUM;
  };
  constexpr auto cw = FrontFace::clockwise, ccw = FrontFace::counter_clockwise;
  EXPECT_EQ(front(cw, true, cw), VK_FRONT_FACE_CLOCKWISE);           // D3D as is
  EXPECT_EQ(front(cw, false, cw), VK_FRONT_FACE_COUNTER_CLOCKWISE);  // projection flip
  EXPECT_EQ(front(cw, true, ccw), VK_FRONT_FACE_COUNTER_CLOCKWISE);  // EffectPreview
  EXPECT_EQ(front(cw, false, ccw), VK_FRONT_FACE_CLOCKWISE);         // two mirrors
  // An effect that declares counter-clockwise front faces is mirrored the same way.
  EXPECT_EQ(front(ccw, true, cw), VK_FRONT_FACE_COUNTER_CLOCKWISE);
  EXPECT_EQ(front(ccw, false, cw), VK_FRONT_FACE_CLOCKWISE);
  EXPECT_EQ(front(ccw, true, ccw), VK_FRONT_FACE_CLOCKWISE);
  EXPECT_EQ(front(ccw, false, ccw), VK_FRONT_FACE_COUNTER_CLOCKWISE);
  EXPECT_FALSE(sink.has_errors());
}

TEST(PassStateMapping, BlendStencilAndBias) {
  PassStateSummary p;
  p.blend[0] = {true,
                BlendFactor::src_alpha,
                BlendFactor::one_minus_src_alpha,
                BlendOp::add,
                BlendFactor::one,
                BlendFactor::zero,
                BlendOp::max,
                0x7};
  p.stencil = true;
  p.stencil_front = {StencilOp::keep, StencilOp::increment_wrap, StencilOp::replace, CompareOp::equal};
  p.stencil_ref = 0x1234;
  p.depth_bias = 1.0f / (1 << 20);  // D3D9: fraction of the depth range
  DiagnosticSink sink;
  auto s = to_pipeline_state(p, {.depth_bits = 24}, DeviceFeatures{}, sink);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->blend[0].src_color, uint32_t(VK_BLEND_FACTOR_SRC_ALPHA));
  EXPECT_EQ(s->blend[0].dst_color, uint32_t(VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA));
  EXPECT_EQ(s->blend[0].alpha_op, uint32_t(VK_BLEND_OP_MAX));
  EXPECT_EQ(s->blend[0].write_mask, 0x7u);
  EXPECT_EQ(s->front_depth_fail, uint32_t(VK_STENCIL_OP_INCREMENT_AND_WRAP));
  EXPECT_EQ(s->front_pass, uint32_t(VK_STENCIL_OP_REPLACE));
  EXPECT_EQ(s->front_compare, uint32_t(VK_COMPARE_OP_EQUAL));
  EXPECT_EQ(s->front_reference, 0x34u);
  EXPECT_EQ(s->depth_bias_enable, 1u);
  EXPECT_FLOAT_EQ(s->depth_bias_constant, 16.0f);  // 2^-20 of the range = 16 units of 2^-24
}

TEST(PassStateMapping, MissingFeaturesAreReasons) {
  PassStateSummary p;
  p.fill = FillMode::wireframe;
  DiagnosticSink sink;
  EXPECT_FALSE(to_pipeline_state(p, {}, DeviceFeatures{}, sink));
  EXPECT_EQ(sink.diagnostics().back().id, "vk-feature-missing");
  DeviceFeatures f;
  f.fill_mode_non_solid = true;
  EXPECT_EQ(to_pipeline_state(p, {}, f, sink)->polygon_mode, uint32_t(VK_POLYGON_MODE_LINE));
  PassStateSummary mrt;
  mrt.blend[1].enable = true;
  EXPECT_FALSE(to_pipeline_state(mrt, {.color_attachment_count = 2}, f, sink));
  f.independent_blend = true;
  EXPECT_TRUE(to_pipeline_state(mrt, {.color_attachment_count = 2}, f, sink));
}

// DepthBiasClamp needs depthBiasClamp (not depthClamp); without it Vulkan takes 0, no clamp.
TEST(PassStateMapping, ABiasClampNeedsTheDepthBiasClampFeature) {
  PassStateSummary p;
  p.depth_bias = 100, p.depth_bias_normalized = false, p.depth_bias_clamp = 0.25f;
  DiagnosticSink sink;
  DeviceFeatures f;
  f.depth_clamp = true;
  EXPECT_EQ(to_pipeline_state(p, {}, f, sink)->depth_bias_clamp, 0.0f);
  f.depth_bias_clamp = true;
  EXPECT_EQ(to_pipeline_state(p, {}, f, sink)->depth_bias_clamp, 0.25f);
}

TEST(PassStateMapping, Samplers) {
  fx::SamplerDesc m;
  m.address = {AddressMode3::clamp_to_border, AddressMode3::mirrored_repeat, AddressMode3::clamp_to_edge};
  m.min_filter = m.mag_filter = TexelFilter::linear;
  m.mip_filter = MipFilter::none;
  m.border_color = {1, 1, 1, 1};
  m.anisotropic = true;
  m.max_anisotropy = 8;
  m.max_mip_level = 2;
  DiagnosticSink sink;
  SamplerKey d = to_sampler_key(m, sink);
  EXPECT_EQ(d.address_u, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER);
  EXPECT_EQ(d.address_v, VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT);
  EXPECT_EQ(d.address_w, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
  EXPECT_EQ(d.min_filter, VK_FILTER_LINEAR);
  EXPECT_EQ(d.border, VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE);
  EXPECT_EQ(d.max_anisotropy, 8.0f);
  EXPECT_EQ(d.min_lod, 2.0f);
  EXPECT_EQ(d.max_lod, 2.0f);  // MipFilter None: one level
  EXPECT_EQ(sink.diagnostics().size(), 0u);
  m.border_color = {0.5f, 0.2f, 0.1f, 1};
  m.address[0] = AddressMode3::mirror_clamp_to_edge;
  d = to_sampler_key(m, sink);
  EXPECT_EQ(d.border, VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK);
  EXPECT_EQ(d.address_u, VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT);
  EXPECT_EQ(sink.warning_count(), 2u);
}

}  // namespace
}  // namespace fx::vk
