// What a Vulkan backend reads from a pass without knowing Direct3D: rasterization,
// depth/stencil, blending, alpha test, multisampling, and sampler descriptions. D3D9
// render states and D3D10/11 state objects map onto the same structures.
// Enum values equal the matching Vulkan enums (VkCompareOp, VkBlendFactor, VkBlendOp,
// VkStencilOp, VkCullModeFlagBits, VkFrontFace, VkPolygonMode, VkSamplerAddressMode,
// VkFilter, VkSamplerMipmapMode) so a backend may static_cast; no Vulkan header here.
// Stable: every field below. Defaults are documented in docs/effect-model.md.
#pragma once
#include <array>
#include <cstdint>

namespace fx {

enum class CompareOp : uint8_t { never, less, equal, less_or_equal, greater, not_equal, greater_or_equal, always };
enum class BlendFactor : uint8_t {
  zero,
  one,
  src_color,
  one_minus_src_color,
  dst_color,
  one_minus_dst_color,
  src_alpha,
  one_minus_src_alpha,
  dst_alpha,
  one_minus_dst_alpha,
  constant_color,
  one_minus_constant_color,
  constant_alpha,
  one_minus_constant_alpha,
  src_alpha_saturate,
  src1_color,
  one_minus_src1_color,
  src1_alpha,
  one_minus_src1_alpha,
};
enum class BlendOp : uint8_t { add, subtract, reverse_subtract, min, max };
enum class StencilOp : uint8_t {
  keep,
  zero,
  replace,
  increment_clamp,
  decrement_clamp,
  invert,
  increment_wrap,
  decrement_wrap
};
enum class CullMode : uint8_t { none = 0, front = 1, back = 2 };
enum class FrontFace : uint8_t { counter_clockwise = 0, clockwise = 1 };
enum class FillMode : uint8_t { solid = 0, wireframe = 1, point = 2 };
enum class AddressMode3 : uint8_t { repeat, mirrored_repeat, clamp_to_edge, clamp_to_border, mirror_clamp_to_edge };
enum class TexelFilter : uint8_t { nearest, linear };
enum class MipFilter : uint8_t { nearest, linear, none /* D3D9 MipFilter=None: sample level 0 only */ };

struct StencilFace {
  StencilOp fail = StencilOp::keep, depth_fail = StencilOp::keep, pass = StencilOp::keep;
  CompareOp compare = CompareOp::always;
  bool operator==(const StencilFace&) const = default;
};

// Blending of one colour attachment.
struct TargetBlend {
  bool enable = false;
  BlendFactor src_color = BlendFactor::one, dst_color = BlendFactor::zero;
  BlendOp color_op = BlendOp::add;
  BlendFactor src_alpha = BlendFactor::one, dst_alpha = BlendFactor::zero;
  BlendOp alpha_op = BlendOp::add;
  uint8_t write_mask = 0xF;  // bit 0 R, 1 G, 2 B, 3 A (as VkColorComponentFlags)
  bool operator==(const TargetBlend&) const = default;
};

inline constexpr int kMaxRenderTargets = 8;

// The fixed-function-free state of one pass. Window-space winding is D3D's: with the
// default FrontFace::clockwise, a backend that flips Y with a negative viewport height
// keeps it as is; one that flips in the projection must swap it.
struct PassStateSummary {
  // Rasterization.
  CullMode cull = CullMode::back;
  FrontFace front_face = FrontFace::clockwise;
  FillMode fill = FillMode::solid;
  float depth_bias = 0;               // D3D9: depth-buffer units (float); D3D10+: integer units
  bool depth_bias_normalized = true;  // true when depth_bias came from D3D9 (fraction of range)
  float depth_bias_slope = 0;
  float depth_bias_clamp = 0;
  bool depth_clip = true;
  bool scissor = false;
  bool antialiased_lines = false;
  // Depth and stencil.
  bool depth_test = true;
  bool depth_write = true;
  CompareOp depth_compare = CompareOp::less_or_equal;
  bool stencil = false;
  StencilFace stencil_front, stencil_back;
  uint32_t stencil_read_mask = 0xFFFFFFFF, stencil_write_mask = 0xFFFFFFFF, stencil_ref = 0;
  // Blending and output.
  std::array<TargetBlend, kMaxRenderTargets> blend{};
  std::array<float, 4> blend_constants{0, 0, 0, 0};
  bool alpha_to_coverage = false;
  bool alpha_test = false;  // emulated: the backend adds a discard
  CompareOp alpha_compare = CompareOp::always;
  uint32_t alpha_ref = 0;   // 0..255 as in D3D9 (compare alpha*255 with it)
  bool srgb_write = false;  // emulated: render through an sRGB view
  bool multisample = true;
  uint32_t sample_mask = 0xFFFFFFFF;
  bool operator==(const PassStateSummary&) const = default;
};

// A sampler as Vulkan needs it (plus the texture it reads in D3D9 sampler_state form).
struct SamplerDesc {
  std::array<AddressMode3, 3> address{AddressMode3::repeat, AddressMode3::repeat, AddressMode3::repeat};
  std::array<float, 4> border_color{0, 0, 0, 0};
  TexelFilter min_filter = TexelFilter::nearest, mag_filter = TexelFilter::nearest;
  MipFilter mip_filter = MipFilter::none;
  bool anisotropic = false;
  uint32_t max_anisotropy = 1;
  float lod_bias = 0;
  float min_lod = 0, max_lod = 1000.0f;
  uint32_t max_mip_level = 0;  // D3D9 MaxMipLevel: most detailed level used (min LOD)
  bool srgb = false;           // D3D9 SRGBTexture: decode through an sRGB view
  bool compare_enable = false;
  CompareOp compare = CompareOp::never;
  bool operator==(const SamplerDesc&) const = default;
};

}  // namespace fx
