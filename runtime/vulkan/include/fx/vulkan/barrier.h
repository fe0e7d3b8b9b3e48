// Image layout transitions and memory barriers. Uses the Vulkan 1.0 barrier entry point so
// it also works on wrapped devices that did not enable synchronization2.
#pragma once
#include <vulkan/vulkan.h>

namespace fx::vk {

// The stages and accesses that use an image in a given layout (conservative).
struct LayoutUse {
  VkPipelineStageFlags stages = 0;
  VkAccessFlags access = 0;
};
LayoutUse layout_use(VkImageLayout layout);

// Records a barrier moving `range` of `image` from `from` to `to`, ordering against the
// previous and next users implied by the layouts. UNDEFINED as `from` discards contents.
void transition_image(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout from,
                      VkImageLayout to);

// Records a global memory barrier (e.g. buffer copy -> host read).
void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stages, VkAccessFlags src_access,
                    VkPipelineStageFlags dst_stages, VkAccessFlags dst_access);

}  // namespace fx::vk
