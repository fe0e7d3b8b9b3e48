// Memory type choice per usage, with fallbacks for devices that lack the ideal type.
#include "fx/vulkan/memory.h"

#include "fx/vulkan/vk_check.h"

namespace fx::vk {

std::optional<uint32_t> find_memory_type(const VkPhysicalDeviceMemoryProperties& memory, uint32_t type_bits,
                                         VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
  std::optional<uint32_t> fallback;
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if (!(type_bits & (1u << i))) continue;
    VkMemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (!fallback) fallback = i;
  }
  return fallback;
}

std::optional<Allocation> allocate_memory(const Context& ctx, const VkMemoryRequirements& requirements,
                                          MemoryUsage usage, DiagnosticSink& sink) {
  VkMemoryPropertyFlags required = 0, preferred = 0;
  switch (usage) {
    case MemoryUsage::device_local: preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT; break;
    case MemoryUsage::upload:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
      preferred = VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      break;
    case MemoryUsage::readback:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
      // Uncached reads are very slow on discrete GPUs; coherency is optional.
      preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
      break;
  }
  const auto& props = ctx.memory_properties();
  auto type = find_memory_type(props, requirements.memoryTypeBits, required, preferred);
  if (!type) {
    sink.error("vk-no-memory-type", {},
               "no memory type fits the resource (type bits " + std::to_string(requirements.memoryTypeBits) + ")");
    return std::nullopt;
  }
  auto info = structure<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = *type;
  Allocation allocation;
  if (!check(vkAllocateMemory(ctx.device(), &info, nullptr, &allocation.memory), sink, "vkAllocateMemory"))
    return std::nullopt;
  allocation.flags = props.memoryTypes[*type].propertyFlags;
  return allocation;
}

}  // namespace fx::vk
