// fx::vk::SamplerCache: one VkSampler per distinct SamplerKey, shared by every pass.
#pragma once
#include <vulkan/vulkan.h>

#include <cstring>
#include <unordered_map>

#include "fx/vulkan/context.h"

namespace fx::vk {

// Neutral sampler description (D3D sampler states map onto it). Value-initialised: linear
// min/mag/mip, wrap addressing, no anisotropy, full LOD range, transparent black border.
struct SamplerKey {
  VkFilter min_filter = VK_FILTER_LINEAR;
  VkFilter mag_filter = VK_FILTER_LINEAR;
  VkSamplerMipmapMode mip_filter = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  VkSamplerAddressMode address_u = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  VkSamplerAddressMode address_v = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  VkSamplerAddressMode address_w = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  float mip_lod_bias = 0;
  float max_anisotropy = 1;  // > 1 enables anisotropic filtering where the device allows
  float min_lod = 0;
  float max_lod = VK_LOD_CLAMP_NONE;
  VkBorderColor border = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  uint32_t compare_enable = 0;  // shadow samplers
  VkCompareOp compare_op = VK_COMPARE_OP_LESS_OR_EQUAL;
  friend bool operator==(const SamplerKey& a, const SamplerKey& b) {
    return std::memcmp(&a, &b, sizeof(SamplerKey)) == 0;
  }
};
static_assert(sizeof(SamplerKey) == 13 * 4, "no padding: SamplerKey hashes as bytes");

class SamplerCache {
 public:
  explicit SamplerCache(const Context& ctx) : ctx_(&ctx) {}
  SamplerCache(const SamplerCache&) = delete;
  SamplerCache& operator=(const SamplerCache&) = delete;
  ~SamplerCache();

  // The sampler for `desc`, created on first use. Anisotropy is used only when the device
  // enabled samplerAnisotropy and is clamped to maxSamplerAnisotropy; LOD bias is clamped to
  // maxSamplerLodBias. Null and "vk-call-failed" on failure.
  VkSampler get(const SamplerKey& desc, DiagnosticSink& sink);
  // The description after device clamping (what get() creates).
  SamplerKey effective(const SamplerKey& desc) const;
  size_t size() const { return samplers_.size(); }

 private:
  struct DescHash {
    size_t operator()(const SamplerKey& d) const;
  };
  const Context* ctx_;
  std::unordered_map<SamplerKey, VkSampler, DescHash> samplers_;
};

}  // namespace fx::vk
