// SamplerCache: device-clamped sampler creation keyed by description bytes.
#include "fx/vulkan/sampler_cache.h"

#define XXH_INLINE_ALL  // xxHash header-only: fxkit links no libxxhash
#include <xxhash.h>

#include <algorithm>

#include "fx/vulkan/vk_check.h"

namespace fx::vk {

size_t SamplerCache::DescHash::operator()(const SamplerKey& d) const { return size_t(XXH3_64bits(&d, sizeof d)); }

SamplerCache::~SamplerCache() {
  for (auto& [desc, sampler] : samplers_) vkDestroySampler(ctx_->device(), sampler, nullptr);
}

SamplerKey SamplerCache::effective(const SamplerKey& in) const {
  SamplerKey d = in;
  const VkPhysicalDeviceLimits& limits = ctx_->info().limits;
  if (!ctx_->features().sampler_anisotropy) d.max_anisotropy = 1;
  d.max_anisotropy = std::clamp(d.max_anisotropy, 1.0f, std::max(1.0f, limits.maxSamplerAnisotropy));
  d.mip_lod_bias = std::clamp(d.mip_lod_bias, -limits.maxSamplerLodBias, limits.maxSamplerLodBias);
  if (!d.compare_enable) d.compare_op = VK_COMPARE_OP_LESS_OR_EQUAL;  // ignored: one key
  return d;
}

VkSampler SamplerCache::get(const SamplerKey& requested, DiagnosticSink& sink) {
  const SamplerKey d = effective(requested);
  auto it = samplers_.find(d);
  if (it != samplers_.end()) return it->second;
  auto info = structure<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  info.magFilter = d.mag_filter;
  info.minFilter = d.min_filter;
  info.mipmapMode = d.mip_filter;
  info.addressModeU = d.address_u;
  info.addressModeV = d.address_v;
  info.addressModeW = d.address_w;
  info.mipLodBias = d.mip_lod_bias;
  info.anisotropyEnable = d.max_anisotropy > 1.0f;
  info.maxAnisotropy = d.max_anisotropy;
  info.compareEnable = d.compare_enable;
  info.compareOp = d.compare_op;
  info.minLod = d.min_lod;
  info.maxLod = d.max_lod;
  info.borderColor = d.border;
  VkSampler sampler = VK_NULL_HANDLE;
  if (!check(vkCreateSampler(ctx_->device(), &info, nullptr, &sampler), sink, "vkCreateSampler")) return VK_NULL_HANDLE;
  samplers_.emplace(d, sampler);
  return sampler;
}

}  // namespace fx::vk
