// RenderingFormats -> VkPipelineRenderingCreateInfo.
#include "fx/vulkan/rendering_formats.h"

#include "fx/vulkan/vk_check.h"

namespace fx::vk {

VkPipelineRenderingCreateInfo RenderingFormats::pipeline_info() const& {
  auto info = structure<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
  info.colorAttachmentCount = color_count;
  info.pColorAttachmentFormats = color;
  info.depthAttachmentFormat = depth;
  info.stencilAttachmentFormat = stencil;
  return info;
}

}  // namespace fx::vk
