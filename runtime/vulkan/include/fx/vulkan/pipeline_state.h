// fx::vk::PipelineState: every piece of fixed-function state a pass sets, packed into a few
// 32-bit words of bitfields (Granite style) so it hashes and compares as bytes.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <cstring>

#include "fx/vulkan/context.h"
#include "fx/vulkan/rendering_formats.h"

namespace fx::vk {

// Blend and write-mask state of one colour attachment: one word.
struct AttachmentBlend {
  uint32_t blend_enable : 1 = 0;
  uint32_t src_color : 5 = VK_BLEND_FACTOR_ONE;
  uint32_t dst_color : 5 = VK_BLEND_FACTOR_ZERO;
  uint32_t color_op : 3 = VK_BLEND_OP_ADD;  // ADD..MAX (0..4)
  uint32_t src_alpha : 5 = VK_BLEND_FACTOR_ONE;
  uint32_t dst_alpha : 5 = VK_BLEND_FACTOR_ZERO;
  uint32_t alpha_op : 3 = VK_BLEND_OP_ADD;
  uint32_t write_mask : 4 = 0xF;  // VkColorComponentFlags
  uint32_t reserved : 1 = 0;
};

// Static state of a graphics pipeline. Default-constructed: triangle lists (a program with
// tessellation stages draws patch lists: see with_patches()), no culling,
// counter-clockwise front faces, depth test and write off (compare LESS_OR_EQUAL; D3D
// defaults are applied by the pass-state mapping, not here), no stencil, no blending, 1 sample.
struct PipelineState {
  // Word 0: input assembly, rasterisation, depth, multisampling.
  uint32_t topology : 4 = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  uint32_t cull_mode : 2 = VK_CULL_MODE_NONE;
  uint32_t front_face : 1 = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  uint32_t polygon_mode : 2 = VK_POLYGON_MODE_FILL;
  uint32_t depth_test : 1 = 0;
  uint32_t depth_write : 1 = 0;
  uint32_t depth_compare : 3 = VK_COMPARE_OP_LESS_OR_EQUAL;
  uint32_t depth_bias_enable : 1 = 0;
  uint32_t depth_clamp : 1 = 0;
  uint32_t stencil_test : 1 = 0;
  uint32_t alpha_to_coverage : 1 = 0;
  uint32_t sample_count_log2 : 3 = 0;  // 1 << n samples
  uint32_t color_attachment_count : 3 = 1;
  uint32_t rasterizer_discard : 1 = 0;
  uint32_t primitive_restart : 1 = 0;
  // Control points per patch (1..32) when topology is PATCH_LIST (a tessellating program's
  // ShaderProgram::patch_control_points()), 0 otherwise.
  uint32_t patch_control_points : 6 = 0;
  // Word 1: stencil operations, front and back.
  uint32_t front_fail : 3 = VK_STENCIL_OP_KEEP;
  uint32_t front_pass : 3 = VK_STENCIL_OP_KEEP;
  uint32_t front_depth_fail : 3 = VK_STENCIL_OP_KEEP;
  uint32_t front_compare : 3 = VK_COMPARE_OP_ALWAYS;
  uint32_t back_fail : 3 = VK_STENCIL_OP_KEEP;
  uint32_t back_pass : 3 = VK_STENCIL_OP_KEEP;
  uint32_t back_depth_fail : 3 = VK_STENCIL_OP_KEEP;
  uint32_t back_compare : 3 = VK_COMPARE_OP_ALWAYS;
  uint32_t reserved1 : 8 = 0;
  // Word 2: stencil masks.
  uint32_t front_compare_mask : 8 = 0xFF;
  uint32_t front_write_mask : 8 = 0xFF;
  uint32_t back_compare_mask : 8 = 0xFF;
  uint32_t back_write_mask : 8 = 0xFF;
  // Word 3: stencil references.
  uint32_t front_reference : 8 = 0;
  uint32_t back_reference : 8 = 0;
  uint32_t reserved3 : 16 = 0;
  // Word 4: multisample coverage mask.
  uint32_t sample_mask = 0xFFFFFFFFu;
  // Words 5..8: per-attachment blending.
  AttachmentBlend blend[kMaxColorAttachments];
  // Depth bias (D3D DepthBias / SlopeScaleDepthBias; Vulkan constant/slope/clamp) and the
  // constant blend colour (D3D BlendFactor).
  float depth_bias_constant = 0, depth_bias_slope = 0, depth_bias_clamp = 0;
  float blend_constants[4] = {0, 0, 0, 0};

  VkSampleCountFlagBits samples() const { return VkSampleCountFlagBits(1u << sample_count_log2); }
  // Sets sample_count_log2 from a power-of-two count (1..64).
  void set_samples(VkSampleCountFlagBits samples);
  // 64-bit XXH3 of the bytes.
  uint64_t hash() const;
  friend bool operator==(const PipelineState& a, const PipelineState& b) {
    return std::memcmp(&a, &b, sizeof(PipelineState)) == 0;
  }
};
static_assert(sizeof(AttachmentBlend) == 4);
static_assert(sizeof(PipelineState) == 4 * (9 + 7), "no padding: PipelineState hashes as bytes");

// Which pipeline states are recorded as dynamic state instead of being baked into pipelines.
// A dynamic field is masked out of the pipeline key, so passes that differ only in it share
// one pipeline. `none()` is the fully static path that works on every Vulkan 1.0 device
// (viewport and scissor are always dynamic).
struct DynamicStateSet {
  // Vulkan 1.3 core (extended dynamic state 1): cull mode, front face, topology (within its
  // class), depth test/write/compare, stencil test enable and ops. Plus the Vulkan 1.0
  // dynamic states that go with them: depth bias constants, stencil masks and references,
  // blend constants.
  bool eds1 = false;
  // Vulkan 1.3 core (extended dynamic state 2): depth bias enable, rasterizer discard,
  // primitive restart.
  bool eds2 = false;
  // VK_EXT_extended_dynamic_state2's patch control points (pipelines with tessellation stages
  // only; their count stays in the key too, being the program's).
  bool patch_control_points = false;
  // VK_EXT_extended_dynamic_state3, per state.
  bool polygon_mode = false, depth_clamp = false, sample_mask = false, alpha_to_coverage = false,
       color_blend_enable = false, color_blend_equation = false, color_write_mask = false;

  // Everything the context's device has enabled.
  static DynamicStateSet from_features(const DeviceFeatures& features);
  // The fully static path.
  static DynamicStateSet none() { return {}; }
  // Packs the toggles into bits (part of the pipeline key).
  uint32_t bits() const;
  // How many VkDynamicState values a pipeline built with this set declares (`patches`: the
  // pipeline draws patch lists, so it has tessellation stages).
  uint32_t dynamic_state_list(VkDynamicState* out, uint32_t attachment_count, bool patches = false) const;
};

// The part of `state` a pipeline bakes in: fields that `dynamic` records at apply time are
// reset to their defaults, so states differing only in them hash and compare equal.
PipelineState static_part(const PipelineState& state, const DynamicStateSet& dynamic);

// `state` drawing patches of `control_points` (PATCH_LIST) when a program tessellates
// (control_points > 0), `state` unchanged otherwise: Vulkan requires a pipeline with
// tessellation stages to take patch lists, and its patch size is the hull shader's.
PipelineState with_patches(PipelineState state, uint32_t control_points);

// The topology class that stays baked in when topology is dynamic (points, lines, triangles,
// patches): Vulkan requires the dynamic topology to be of the pipeline's class.
VkPrimitiveTopology topology_class_representative(VkPrimitiveTopology topology);

}  // namespace fx::vk
