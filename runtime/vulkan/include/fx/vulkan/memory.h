// Device memory: choosing a memory type for a use and allocating it. One dedicated
// allocation per resource (fine for effect-sized workloads; see docs/vulkan.md).
#pragma once
#include <vulkan/vulkan.h>

#include <optional>

#include "fx/vulkan/context.h"

namespace fx::vk {

// Where a resource's memory lives and how the CPU reaches it.
enum class MemoryUsage {
  device_local,  // GPU only (textures, render targets, static buffers)
  upload,        // host-visible, written by the CPU each frame (uniforms, staging)
  readback,      // host-visible and preferably cached, read by the CPU (render results)
};

// Index of a memory type in `type_bits` having all of `required`, preferring `preferred`.
std::optional<uint32_t> find_memory_type(const VkPhysicalDeviceMemoryProperties& memory, uint32_t type_bits,
                                         VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred = 0);

// A freshly allocated block suited to `usage`; `flags` says what it turned out to be.
struct Allocation {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkMemoryPropertyFlags flags = 0;
};

// Allocates memory for `requirements`; reports "vk-no-memory-type" or "vk-call-failed".
std::optional<Allocation> allocate_memory(const Context& ctx, const VkMemoryRequirements& requirements,
                                          MemoryUsage usage, DiagnosticSink& sink);

}  // namespace fx::vk
