// FrameResources: uniform ring slices and descriptor pools per frame in flight.
#include "fx/vulkan/frame_resources.h"

#include <atomic>
#include <bit>
#include <cstring>

#include "fx/vulkan/vk_check.h"

namespace fx::vk {

std::optional<FrameResources> FrameResources::create(const Context& ctx, const FrameResourcesDesc& desc,
                                                     DiagnosticSink& sink) {
  FrameResources f;
  static std::atomic<uint64_t> next_id{1};
  f.id_ = next_id++;
  f.ctx_ = &ctx;
  f.frames_in_flight_ = std::max(1u, desc.frames_in_flight);
  // A power of two per the Vulkan spec; rounded up anyway, reserve_uniform masks with it.
  f.alignment_ = std::bit_ceil(std::max<VkDeviceSize>(1, ctx.info().limits.minUniformBufferOffsetAlignment));
  f.slice_ = (desc.uniform_bytes_per_frame + f.alignment_ - 1) / f.alignment_ * f.alignment_;
  std::optional<Buffer> ring = Buffer::create(
      ctx,
      {f.slice_ * f.frames_in_flight_, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUsage::upload, "fxkit uniform ring"},
      sink);
  if (!ring) return std::nullopt;
  f.ring_ = std::move(*ring);
  f.ring_coherent_ = f.ring_.coherent();
  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, desc.descriptors_per_type},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, desc.descriptors_per_type},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, desc.descriptors_per_type},
      {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, desc.descriptors_per_type},
      {VK_DESCRIPTOR_TYPE_SAMPLER, desc.descriptors_per_type},
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, desc.descriptors_per_type},
      {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, desc.descriptors_per_type},
      {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, desc.descriptors_per_type},
      {VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, desc.descriptors_per_type},
  };
  for (uint32_t i = 0; i < f.frames_in_flight_; ++i) {
    auto info = structure<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    info.maxSets = desc.sets_per_frame;
    info.poolSizeCount = uint32_t(std::size(sizes));
    info.pPoolSizes = sizes;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (!check(vkCreateDescriptorPool(ctx.device(), &info, nullptr, &pool), sink, "vkCreateDescriptorPool"))
      return std::nullopt;
    f.pools_.push_back(pool);
  }
  return f;
}

FrameResources& FrameResources::operator=(FrameResources&& o) noexcept {
  if (this == &o) return *this;
  for (VkDescriptorPool pool : pools_) vkDestroyDescriptorPool(ctx_->device(), pool, nullptr);
  ctx_ = o.ctx_;
  ring_ = std::move(o.ring_);
  ring_coherent_ = o.ring_coherent_;
  pools_ = std::move(o.pools_);
  o.pools_.clear();
  frames_in_flight_ = o.frames_in_flight_;
  id_ = o.id_;
  slice_ = o.slice_, alignment_ = o.alignment_, head_ = o.head_, slice_start_ = o.slice_start_, frame_ = o.frame_;
  bytes_uploaded_ = o.bytes_uploaded_;
  return *this;
}

FrameResources::~FrameResources() {
  for (VkDescriptorPool pool : pools_) vkDestroyDescriptorPool(ctx_->device(), pool, nullptr);
  pools_.clear();
}

void FrameResources::begin_frame() {
  ++frame_;
  head_ = 0;
  slice_start_ = slice_ * (frame_ % frames_in_flight_);
  vkResetDescriptorPool(ctx_->device(), pools_[frame_ % frames_in_flight_], 0);
}

std::optional<UniformAllocation> FrameResources::ring_full(DiagnosticSink& sink) const {
  sink.error("vk-uniform-ring-full", {},
             "uniform data of frame " + std::to_string(frame_) + " exceeds the " + std::to_string(slice_) +
                 "-byte ring slice");
  return std::nullopt;
}

std::optional<UniformAllocation> FrameResources::upload_uniform(const void* data, uint32_t bytes,
                                                                DiagnosticSink& sink) {
  std::optional<UniformAllocation> a = reserve_uniform(bytes, sink);
  if (!a) return std::nullopt;
  std::memcpy(a->mapped, data, bytes);
  flush_uniform(*a, bytes);
  return a;
}

VkDescriptorSet FrameResources::allocate_set(VkDescriptorSetLayout layout, DiagnosticSink& sink) {
  auto info = structure<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  info.descriptorPool = pools_[frame_ % frames_in_flight_];
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  if (vkAllocateDescriptorSets(ctx_->device(), &info, &set) != VK_SUCCESS) {
    sink.error("vk-descriptor-pool-full", {},
               "the descriptor pool of frame " + std::to_string(frame_) + " is exhausted");
    return VK_NULL_HANDLE;
  }
  return set;
}

}  // namespace fx::vk
