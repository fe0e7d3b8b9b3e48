// Fills VkGraphicsPipelineCreateInfo from a GraphicsPipelineDesc (see graphics_pipeline.h).
#include "fx/vulkan/graphics_pipeline.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "fx/vulkan/vk_check.h"

namespace fx::vk {

VkPipeline create_graphics_pipeline(VkDevice device, VkPipelineCache cache, const GraphicsPipelineDesc& desc,
                                    DiagnosticSink& sink) {
  const PipelineState& s = desc.state;
  // Vulkan allows patch lists exactly when the stages tessellate; the driver may crash on
  // either mismatch rather than fail, so it is a diagnostic here.
  const bool tessellates = std::any_of(
      desc.stages.begin(), desc.stages.end(),
      [](const VkPipelineShaderStageCreateInfo& i) { return i.stage == VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT; });
  const bool patches = s.topology == VK_PRIMITIVE_TOPOLOGY_PATCH_LIST && s.patch_control_points > 0;
  if (tessellates != patches) {
    sink.error("vk-tessellation-patches", {},
               tessellates ? "a pipeline with a hull (tessellation control) shader must draw patch lists "
                             "(PipelineState::patch_control_points, see with_patches())"
                           : "a pipeline draws patch lists only with hull and domain (tessellation) shaders");
    return VK_NULL_HANDLE;
  }
  auto vertex =
      structure<VkPipelineVertexInputStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  vertex.vertexBindingDescriptionCount = uint32_t(desc.vertex_bindings.size());
  vertex.pVertexBindingDescriptions = desc.vertex_bindings.data();
  vertex.vertexAttributeDescriptionCount = uint32_t(desc.vertex_attributes.size());
  vertex.pVertexAttributeDescriptions = desc.vertex_attributes.data();

  auto assembly =
      structure<VkPipelineInputAssemblyStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  assembly.topology = VkPrimitiveTopology(s.topology);
  assembly.primitiveRestartEnable = s.primitive_restart;

  // Vulkan's default domain origin, upper left, is Direct3D's: glslang keeps an HLSL hull
  // shader's outputtopology("triangle_cw") as VertexOrderCw, so the winding comes out as in
  // Direct3D (TessellationRenderTest checks it with SV_IsFrontFace).
  auto tessellation =
      structure<VkPipelineTessellationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO);
  tessellation.patchControlPoints = s.patch_control_points;

  auto viewport = structure<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  auto raster =
      structure<VkPipelineRasterizationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
  raster.depthClampEnable = s.depth_clamp;
  raster.rasterizerDiscardEnable = s.rasterizer_discard;
  raster.polygonMode = VkPolygonMode(s.polygon_mode);
  raster.cullMode = s.cull_mode;
  raster.frontFace = VkFrontFace(s.front_face);
  raster.depthBiasEnable = s.depth_bias_enable;
  raster.depthBiasConstantFactor = s.depth_bias_constant;
  raster.depthBiasSlopeFactor = s.depth_bias_slope;
  raster.depthBiasClamp = s.depth_bias_clamp;
  raster.lineWidth = 1.0f;

  auto multisample =
      structure<VkPipelineMultisampleStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = s.samples();
  const VkSampleMask sample_mask = s.sample_mask;
  multisample.pSampleMask = &sample_mask;
  multisample.alphaToCoverageEnable = s.alpha_to_coverage;

  auto depth =
      structure<VkPipelineDepthStencilStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
  depth.depthTestEnable = s.depth_test;
  depth.depthWriteEnable = s.depth_write;
  depth.depthCompareOp = VkCompareOp(s.depth_compare);
  depth.stencilTestEnable = s.stencil_test;
  depth.front = {VkStencilOp(s.front_fail),
                 VkStencilOp(s.front_pass),
                 VkStencilOp(s.front_depth_fail),
                 VkCompareOp(s.front_compare),
                 s.front_compare_mask,
                 s.front_write_mask,
                 s.front_reference};
  depth.back = {VkStencilOp(s.back_fail),
                VkStencilOp(s.back_pass),
                VkStencilOp(s.back_depth_fail),
                VkCompareOp(s.back_compare),
                s.back_compare_mask,
                s.back_write_mask,
                s.back_reference};
  depth.maxDepthBounds = 1.0f;

  VkPipelineColorBlendAttachmentState attachments[kMaxColorAttachments]{};
  for (uint32_t i = 0; i < desc.formats.color_count; ++i) {
    const AttachmentBlend& b = s.blend[i];
    attachments[i] = {b.blend_enable,        VkBlendFactor(b.src_color),         VkBlendFactor(b.dst_color),
                      VkBlendOp(b.color_op), VkBlendFactor(b.src_alpha),         VkBlendFactor(b.dst_alpha),
                      VkBlendOp(b.alpha_op), VkColorComponentFlags(b.write_mask)};
  }
  auto blend = structure<VkPipelineColorBlendStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  blend.attachmentCount = desc.formats.color_count;
  blend.pAttachments = attachments;
  std::memcpy(blend.blendConstants, s.blend_constants, sizeof blend.blendConstants);

  auto dyn = structure<VkPipelineDynamicStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
  dyn.dynamicStateCount = uint32_t(desc.dynamic_states.size());
  dyn.pDynamicStates = desc.dynamic_states.data();

  const VkPipelineRenderingCreateInfo rendering = desc.formats.pipeline_info();

  auto info = structure<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  info.pNext = &rendering;
  info.stageCount = uint32_t(desc.stages.size());
  info.pStages = desc.stages.data();
  info.pVertexInputState = &vertex;
  info.pInputAssemblyState = &assembly;
  info.pTessellationState = tessellates ? &tessellation : nullptr;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dyn;
  info.layout = desc.layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  if (!check(vkCreateGraphicsPipelines(device, cache, 1, &info, nullptr, &pipeline), sink, "vkCreateGraphicsPipelines"))
    return VK_NULL_HANDLE;
  return pipeline;
}

}  // namespace fx::vk
