// fx::vk::create_graphics_pipeline: the one place fxkit fills a VkGraphicsPipelineCreateInfo,
// from shader stages, a PipelineState, vertex input, attachment formats and dynamic states
// (dynamic rendering, no render pass). PipelineCache, the accuracy bench and tests use it.
#pragma once
#include <vulkan/vulkan.h>

#include <span>

#include "fx/diagnostic.h"
#include "fx/vulkan/pipeline_state.h"
#include "fx/vulkan/rendering_formats.h"

namespace fx::vk {

// Everything a graphics pipeline is created from. The defaults draw a full-screen pass: no
// vertex buffers, PipelineState's defaults (triangle lists, no culling, depth off, no
// blending, all colour channels written), viewport and scissor set at record time.
struct GraphicsPipelineDesc {
  std::span<const VkPipelineShaderStageCreateInfo> stages;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  PipelineState state;
  std::span<const VkVertexInputBindingDescription> vertex_bindings;
  std::span<const VkVertexInputAttributeDescription> vertex_attributes;
  // Blend state is given for formats.color_count attachments (state.blend[i]).
  RenderingFormats formats;
  // Must hold VK_DYNAMIC_STATE_VIEWPORT and _SCISSOR: the viewport state declares one of each
  // and no values.
  std::span<const VkDynamicState> dynamic_states;
};

// The pipeline, created through `cache` (VK_NULL_HANDLE: none). Null and "vk-call-failed"
// when vkCreateGraphicsPipelines fails.
VkPipeline create_graphics_pipeline(VkDevice device, VkPipelineCache cache, const GraphicsPipelineDesc& desc,
                                    DiagnosticSink& sink);

}  // namespace fx::vk
