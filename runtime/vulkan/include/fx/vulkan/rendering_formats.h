// fx::vk::RenderingFormats: the attachment formats of a dynamic-rendering pass, the one
// format type of the Vulkan backend (RenderTarget::formats(), PassRecorder::begin,
// EffectBinding, PipelineCache keys, ReloadBackendDesc).
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>

namespace fx::vk {

// Most colour attachments a pass may draw and blend into (D3D9 has 4 render targets, D3D11
// has 8; 4 keeps PipelineState at 64 bytes and covers every effect seen so far).
inline constexpr uint32_t kMaxColorAttachments = 4;

// Attachment formats for dynamic rendering (VkPipelineRenderingCreateInfo).
struct RenderingFormats {
  VkFormat color[kMaxColorAttachments] = {VK_FORMAT_UNDEFINED, VK_FORMAT_UNDEFINED, VK_FORMAT_UNDEFINED,
                                          VK_FORMAT_UNDEFINED};
  uint32_t color_count = 0;
  VkFormat depth = VK_FORMAT_UNDEFINED;
  VkFormat stencil = VK_FORMAT_UNDEFINED;
  friend bool operator==(const RenderingFormats&, const RenderingFormats&) = default;

  // The formats for VkGraphicsPipelineCreateInfo::pNext. The result points into this object
  // (pColorAttachmentFormats = color), so it exists only for a named RenderingFormats, which
  // must outlive vkCreateGraphicsPipelines; on a temporary it does not compile.
  VkPipelineRenderingCreateInfo pipeline_info() const&;
  VkPipelineRenderingCreateInfo pipeline_info() const&& = delete;
};

}  // namespace fx::vk
