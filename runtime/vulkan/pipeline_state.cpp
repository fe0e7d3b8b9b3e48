// PipelineState hashing, dynamic-state masking and the dynamic state list.
#include "fx/vulkan/pipeline_state.h"

#define XXH_INLINE_ALL  // xxHash header-only: fxkit links no libxxhash
#include <xxhash.h>

#include <bit>

namespace fx::vk {

void PipelineState::set_samples(VkSampleCountFlagBits samples) {
  sample_count_log2 = uint32_t(std::countr_zero(uint32_t(samples)));
}

uint64_t PipelineState::hash() const { return XXH3_64bits(this, sizeof(PipelineState)); }

DynamicStateSet DynamicStateSet::from_features(const DeviceFeatures& f) {
  DynamicStateSet d;
  d.eds1 = f.extended_dynamic_state;
  d.eds2 = f.extended_dynamic_state2;
  d.patch_control_points = f.eds2_patch_control_points;
  d.polygon_mode = f.eds3.polygon_mode;
  d.depth_clamp = f.eds3.depth_clamp_enable && f.depth_clamp;
  d.sample_mask = f.eds3.sample_mask;
  d.alpha_to_coverage = f.eds3.alpha_to_coverage_enable;
  d.color_blend_enable = f.eds3.color_blend_enable;
  d.color_blend_equation = f.eds3.color_blend_equation;
  d.color_write_mask = f.eds3.color_write_mask;
  return d;
}

uint32_t DynamicStateSet::bits() const {
  const bool flags[] = {eds1,
                        eds2,
                        polygon_mode,
                        depth_clamp,
                        sample_mask,
                        alpha_to_coverage,
                        color_blend_enable,
                        color_blend_equation,
                        color_write_mask,
                        patch_control_points};
  uint32_t b = 0;
  for (uint32_t i = 0; i < std::size(flags); ++i) b |= uint32_t(flags[i]) << i;
  return b;
}

uint32_t DynamicStateSet::dynamic_state_list(VkDynamicState* out, uint32_t attachment_count, bool patches) const {
  uint32_t n = 0;
  out[n++] = VK_DYNAMIC_STATE_VIEWPORT;
  out[n++] = VK_DYNAMIC_STATE_SCISSOR;
  if (eds1) {
    for (VkDynamicState s :
         {VK_DYNAMIC_STATE_CULL_MODE, VK_DYNAMIC_STATE_FRONT_FACE, VK_DYNAMIC_STATE_PRIMITIVE_TOPOLOGY,
          VK_DYNAMIC_STATE_DEPTH_TEST_ENABLE, VK_DYNAMIC_STATE_DEPTH_WRITE_ENABLE, VK_DYNAMIC_STATE_DEPTH_COMPARE_OP,
          VK_DYNAMIC_STATE_STENCIL_TEST_ENABLE, VK_DYNAMIC_STATE_STENCIL_OP, VK_DYNAMIC_STATE_DEPTH_BIAS,
          VK_DYNAMIC_STATE_STENCIL_COMPARE_MASK, VK_DYNAMIC_STATE_STENCIL_WRITE_MASK,
          VK_DYNAMIC_STATE_STENCIL_REFERENCE, VK_DYNAMIC_STATE_BLEND_CONSTANTS})
      out[n++] = s;
  }
  if (eds2) {
    out[n++] = VK_DYNAMIC_STATE_DEPTH_BIAS_ENABLE;
    out[n++] = VK_DYNAMIC_STATE_RASTERIZER_DISCARD_ENABLE;
    out[n++] = VK_DYNAMIC_STATE_PRIMITIVE_RESTART_ENABLE;
  }
  if (patch_control_points && patches) out[n++] = VK_DYNAMIC_STATE_PATCH_CONTROL_POINTS_EXT;
  if (polygon_mode) out[n++] = VK_DYNAMIC_STATE_POLYGON_MODE_EXT;
  if (depth_clamp) out[n++] = VK_DYNAMIC_STATE_DEPTH_CLAMP_ENABLE_EXT;
  if (sample_mask) out[n++] = VK_DYNAMIC_STATE_SAMPLE_MASK_EXT;
  if (alpha_to_coverage) out[n++] = VK_DYNAMIC_STATE_ALPHA_TO_COVERAGE_ENABLE_EXT;
  // With no colour attachment (a stream-output capture) there is nothing to set them for.
  if (color_blend_enable && attachment_count) out[n++] = VK_DYNAMIC_STATE_COLOR_BLEND_ENABLE_EXT;
  if (color_blend_equation && attachment_count) out[n++] = VK_DYNAMIC_STATE_COLOR_BLEND_EQUATION_EXT;
  if (color_write_mask && attachment_count) out[n++] = VK_DYNAMIC_STATE_COLOR_WRITE_MASK_EXT;
  return n;
}

PipelineState with_patches(PipelineState state, uint32_t control_points) {
  if (control_points == 0) return state;
  state.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
  state.patch_control_points = control_points;
  return state;
}

VkPrimitiveTopology topology_class_representative(VkPrimitiveTopology t) {
  switch (t) {
    case VK_PRIMITIVE_TOPOLOGY_POINT_LIST: return VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    case VK_PRIMITIVE_TOPOLOGY_LINE_LIST:
    case VK_PRIMITIVE_TOPOLOGY_LINE_STRIP:
    case VK_PRIMITIVE_TOPOLOGY_LINE_LIST_WITH_ADJACENCY:
    case VK_PRIMITIVE_TOPOLOGY_LINE_STRIP_WITH_ADJACENCY: return VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
    case VK_PRIMITIVE_TOPOLOGY_PATCH_LIST: return VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    default: return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  }
}

PipelineState static_part(const PipelineState& s, const DynamicStateSet& d) {
  PipelineState p = s;
  const PipelineState def;
  if (d.eds1) {
    p.cull_mode = def.cull_mode;
    p.front_face = def.front_face;
    p.topology = topology_class_representative(VkPrimitiveTopology(s.topology));
    p.depth_test = def.depth_test;
    p.depth_write = def.depth_write;
    p.depth_compare = def.depth_compare;
    p.stencil_test = def.stencil_test;
    p.front_fail = def.front_fail, p.front_pass = def.front_pass;
    p.front_depth_fail = def.front_depth_fail, p.front_compare = def.front_compare;
    p.back_fail = def.back_fail, p.back_pass = def.back_pass;
    p.back_depth_fail = def.back_depth_fail, p.back_compare = def.back_compare;
    p.front_compare_mask = def.front_compare_mask, p.front_write_mask = def.front_write_mask;
    p.back_compare_mask = def.back_compare_mask, p.back_write_mask = def.back_write_mask;
    p.front_reference = def.front_reference, p.back_reference = def.back_reference;
    p.depth_bias_constant = def.depth_bias_constant;
    p.depth_bias_slope = def.depth_bias_slope;
    p.depth_bias_clamp = def.depth_bias_clamp;
    for (int i = 0; i < 4; ++i) p.blend_constants[i] = def.blend_constants[i];
  }
  if (d.eds2) {
    p.depth_bias_enable = def.depth_bias_enable;
    p.rasterizer_discard = def.rasterizer_discard;
    p.primitive_restart = def.primitive_restart;
  }
  if (d.polygon_mode) p.polygon_mode = def.polygon_mode;
  if (d.depth_clamp) p.depth_clamp = def.depth_clamp;
  if (d.sample_mask) p.sample_mask = def.sample_mask;
  if (d.alpha_to_coverage) p.alpha_to_coverage = def.alpha_to_coverage;
  for (uint32_t i = 0; i < kMaxColorAttachments; ++i) {
    AttachmentBlend& b = p.blend[i];
    const AttachmentBlend db;
    if (d.color_blend_enable) b.blend_enable = db.blend_enable;
    if (d.color_blend_equation) {
      b.src_color = db.src_color, b.dst_color = db.dst_color, b.color_op = db.color_op;
      b.src_alpha = db.src_alpha, b.dst_alpha = db.dst_alpha, b.alpha_op = db.alpha_op;
    }
    if (d.color_write_mask) b.write_mask = db.write_mask;
  }
  return p;
}

}  // namespace fx::vk
