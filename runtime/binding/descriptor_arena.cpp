// DescriptorArena: long-lived descriptor sets from pools added as they fill.
#include "fx/binding/descriptor_arena.h"

#include <algorithm>

#include "fx/vulkan/vk_check.h"

namespace fx::vk {
namespace {

constexpr uint32_t kSetsPerPool = 64;

}  // namespace

DescriptorArena::~DescriptorArena() {
  for (VkDescriptorPool pool : pools_) vkDestroyDescriptorPool(ctx_->device(), pool, nullptr);
}

VkDescriptorPool DescriptorArena::add_pool(const ShaderProgram& program, DiagnosticSink& sink) {
  // Room for kSetsPerPool sets of this program's shape, and of at least kPerSet descriptors
  // of every type an effect's programs usually hold, so that most effects need one pool.
  constexpr uint32_t kPerSet = 4;
  std::vector<VkDescriptorPoolSize> sizes;
  auto add = [&](VkDescriptorType type, uint32_t count) {
    auto it = std::find_if(sizes.begin(), sizes.end(), [&](const VkDescriptorPoolSize& s) { return s.type == type; });
    if (it == sizes.end()) sizes.push_back({type, count});
    else it->descriptorCount += count;
  };
  for (VkDescriptorType type : {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLER})
    add(type, 0);
  add(to_vk_descriptor(DescriptorKind::uniform_buffer, DescriptorMode::sets),
      uint32_t(program.uniform_blocks().size()));
  for (const ProgramImage& image : program.images())
    add(to_vk_descriptor(image.kind, DescriptorMode::sets), image.count);
  add(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, uint32_t(program.storage_buffers().size()));
  for (const ProgramTexelBuffer& t : program.texel_buffers()) add(to_vk_descriptor(t.kind, DescriptorMode::sets), 1);
  for (VkDescriptorPoolSize& size : sizes)
    size.descriptorCount = std::max(size.descriptorCount, kPerSet) * kSetsPerPool;
  auto info = structure<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  info.maxSets = kSetsPerPool;
  info.poolSizeCount = uint32_t(sizes.size());
  info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  if (!check(vkCreateDescriptorPool(ctx_->device(), &info, nullptr, &pool), sink, "vkCreateDescriptorPool"))
    return VK_NULL_HANDLE;
  pools_.push_back(pool);
  return pool;
}

VkDescriptorSet DescriptorArena::allocate(const ShaderProgram& program, DiagnosticSink& sink) {
  const VkDescriptorSetLayout layout = program.set_layout();
  auto info = structure<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  // The newest pool first; a full one (out of pool memory, fragmented) gets a successor.
  if (!pools_.empty()) {
    info.descriptorPool = pools_.back();
    const VkResult result = vkAllocateDescriptorSets(ctx_->device(), &info, &set);
    if (result == VK_SUCCESS) return set;
    if (result != VK_ERROR_OUT_OF_POOL_MEMORY && result != VK_ERROR_FRAGMENTED_POOL) {
      check(result, sink, "vkAllocateDescriptorSets");
      return VK_NULL_HANDLE;
    }
  }
  info.descriptorPool = add_pool(program, sink);
  if (!info.descriptorPool) return VK_NULL_HANDLE;
  if (vkAllocateDescriptorSets(ctx_->device(), &info, &set) != VK_SUCCESS) {
    sink.error("vk-descriptor-arena", {}, "a descriptor set could not be allocated from a new pool sized for it");
    return VK_NULL_HANDLE;
  }
  return set;
}

}  // namespace fx::vk
