// ShaderProgram: modules, descriptor set layout and pipeline layout from linked reflection.
#include "fx/binding/shader_program.h"

#define XXH_INLINE_ALL  // xxHash header-only: fxkit links no libxxhash
#include <xxhash.h>

#include <algorithm>
#include <span>
#include <utility>

#include "fx/vulkan/vk_check.h"
#include "tessellation_patch.h"

namespace fx::vk {
namespace {

// The Location of every Input variable of a SPIR-V module. glslang's reflection can list an
// input its optimiser removed; a vertex attribute no input reads is a validation warning.
std::vector<uint32_t> input_locations(std::span<const uint32_t> spirv) {
  constexpr uint32_t kOpVariable = 59, kOpDecorate = 71, kDecorationLocation = 30, kStorageClassInput = 1;
  std::vector<std::pair<uint32_t, uint32_t>> locations;  // id, Location
  std::vector<uint32_t> inputs;                          // ids of Input variables
  for (size_t i = 5; i < spirv.size();) {
    const uint32_t words = spirv[i] >> 16, op = spirv[i] & 0xffffu;
    if (words == 0 || i + words > spirv.size()) break;
    if (op == kOpDecorate && words >= 4 && spirv[i + 2] == kDecorationLocation)
      locations.emplace_back(spirv[i + 1], spirv[i + 3]);
    if (op == kOpVariable && words >= 4 && spirv[i + 3] == kStorageClassInput) inputs.push_back(spirv[i + 2]);
    i += words;
  }
  std::vector<uint32_t> out;
  for (const auto& [id, location] : locations)
    if (std::find(inputs.begin(), inputs.end(), id) != inputs.end()) out.push_back(location);
  return out;
}

}  // namespace

VkShaderStageFlagBits to_vk_stage(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::vertex: return VK_SHADER_STAGE_VERTEX_BIT;
    case ShaderStage::tess_control: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    case ShaderStage::tess_evaluation: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
    case ShaderStage::geometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
    case ShaderStage::fragment: return VK_SHADER_STAGE_FRAGMENT_BIT;
    case ShaderStage::compute: return VK_SHADER_STAGE_COMPUTE_BIT;
  }
  return VK_SHADER_STAGE_ALL;
}

VkDescriptorType to_vk_descriptor(DescriptorKind kind, DescriptorMode mode) {
  switch (kind) {
    case DescriptorKind::uniform_buffer:
      return mode == DescriptorMode::sets ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC
                                          : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case DescriptorKind::storage_buffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case DescriptorKind::combined_image_sampler: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case DescriptorKind::sampled_image: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case DescriptorKind::sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
    case DescriptorKind::storage_image: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    case DescriptorKind::uniform_texel_buffer: return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    case DescriptorKind::storage_texel_buffer: return VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  }
  return VK_DESCRIPTOR_TYPE_MAX_ENUM;
}

static VkShaderStageFlags stage_flags(uint32_t stage_mask) {
  VkShaderStageFlags flags = 0;
  for (uint32_t s = 0; s <= uint32_t(ShaderStage::compute); ++s)
    if (stage_mask & (1u << s)) flags |= to_vk_stage(ShaderStage(s));
  return flags;
}

ShaderProgram::ShaderProgram(ShaderProgram&& o) noexcept { *this = std::move(o); }

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& o) noexcept {
  if (this == &o) return *this;
  reset();
  device_ = std::exchange(o.device_, VK_NULL_HANDLE);
  hash_ = o.hash_;
  mode_ = o.mode_;
  modules_ = std::move(o.modules_);
  entry_points_ = std::move(o.entry_points_);
  stage_infos_ = std::move(o.stage_infos_);
  set_layout_ = std::exchange(o.set_layout_, VK_NULL_HANDLE);
  pipeline_layout_ = std::exchange(o.pipeline_layout_, VK_NULL_HANDLE);
  vertex_inputs_ = std::move(o.vertex_inputs_);
  patch_control_points_ = o.patch_control_points_;
  blocks_ = std::move(o.blocks_);
  images_ = std::move(o.images_);
  storage_buffers_ = std::move(o.storage_buffers_);
  texel_buffers_ = std::move(o.texel_buffers_);
  compute_pipeline_ = std::exchange(o.compute_pipeline_, VK_NULL_HANDLE);
  std::copy(std::begin(o.local_size_), std::end(o.local_size_), local_size_);
  o.modules_.clear();
  return *this;
}

void ShaderProgram::reset() {
  if (device_ == VK_NULL_HANDLE) return;
  if (compute_pipeline_) vkDestroyPipeline(device_, compute_pipeline_, nullptr);
  compute_pipeline_ = VK_NULL_HANDLE;
  for (VkShaderModule m : modules_) vkDestroyShaderModule(device_, m, nullptr);
  modules_.clear();
  stage_infos_.clear();
  if (pipeline_layout_) vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
  pipeline_layout_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE;
  device_ = VK_NULL_HANDLE;
}

std::optional<ShaderProgram> ShaderProgram::create(const Context& ctx, const std::vector<const CompiledShader*>& stages,
                                                   const ProgramLayout& layout, DescriptorMode mode,
                                                   DiagnosticSink& sink) {
  ShaderProgram p;
  p.device_ = ctx.device();
  p.mode_ = mode;
  const CompiledShader* vertex = nullptr;
  const CompiledShader* compute = nullptr;
  XXH3_state_t* hs = XXH3_createState();
  XXH3_64bits_reset(hs);
  std::vector<const CompiledShader*> ordered = stages;
  std::sort(ordered.begin(), ordered.end(),
            [](const CompiledShader* a, const CompiledShader* b) { return a->reflection.stage < b->reflection.stage; });
  p.entry_points_.reserve(ordered.size());  // stage infos point into these strings
  for (const CompiledShader* s : ordered) {
    if (s->reflection.stage == ShaderStage::vertex) vertex = s;
    if (s->reflection.stage == ShaderStage::compute) compute = s;
    XXH3_64bits_update(hs, s->spirv.data(), s->spirv.size() * 4);
    XXH3_64bits_update(hs, s->entry_point.c_str(), s->entry_point.size() + 1);
    VkShaderModuleCreateInfo info = structure<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = s->spirv.size() * 4;
    info.pCode = s->spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    if (!check(vkCreateShaderModule(ctx.device(), &info, nullptr, &module), sink, "vkCreateShaderModule")) {
      XXH3_freeState(hs);
      return std::nullopt;
    }
    p.modules_.push_back(module);
    p.entry_points_.push_back(s->entry_point);
    VkPipelineShaderStageCreateInfo stage =
        structure<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    stage.stage = to_vk_stage(s->reflection.stage);
    stage.module = module;
    stage.pName = p.entry_points_.back().c_str();
    p.stage_infos_.push_back(stage);
  }
  p.hash_ = XXH3_64bits_digest(hs);
  XXH3_freeState(hs);
  if (compute && ordered.size() > 1) {
    sink.error("vk-program-no-vertex-stage", {}, "a compute shader runs alone: its pass can have no other stage");
    return std::nullopt;
  }
  if (!vertex && !compute) {
    sink.error("vk-program-no-vertex-stage", {}, "a graphics program needs a vertex shader");
    return std::nullopt;
  }
  const auto has = [&](ShaderStage stage) {
    return std::any_of(ordered.begin(), ordered.end(),
                       [&](const CompiledShader* s) { return s->reflection.stage == stage; });
  };
  if (has(ShaderStage::tess_control) != has(ShaderStage::tess_evaluation)) {
    sink.error("vk-program-tessellation-stages", {},
               "a tessellating program needs both a hull (tessellation control) and a domain (tessellation "
               "evaluation) shader");
    return std::nullopt;
  }
  for (const CompiledShader* s : ordered)
    if (s->reflection.stage == ShaderStage::tess_control)
      p.patch_control_points_ = tessellation_patch_sizes(s->spirv).input;
  if (vertex) {
    const std::vector<uint32_t> live = input_locations(vertex->spirv);
    for (const InterfaceVariable& input : vertex->reflection.inputs)
      if (std::find(live.begin(), live.end(), input.location) != live.end()) p.vertex_inputs_.push_back(input);
  }
  if (compute)
    for (int d = 0; d < 3; ++d) p.local_size_[d] = std::max(1u, compute->reflection.local_size[d]);

  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const ProgramBinding& b : layout.bindings) {
    if (b.set != 0 || (mode == DescriptorMode::push && b.count != 1)) {
      sink.error("vk-descriptor-unsupported", {},
                 "resource '" + b.name + "' (set " + std::to_string(b.set) +
                     ") is not a resource in set 0 that this descriptor mode can bind");
      return std::nullopt;
    }
    VkDescriptorSetLayoutBinding vb{};
    vb.binding = b.binding;
    vb.descriptorType = to_vk_descriptor(b.kind, mode);
    vb.descriptorCount = b.count;
    vb.stageFlags = stage_flags(b.stage_mask);
    bindings.push_back(vb);
    if (b.kind == DescriptorKind::uniform_buffer) {
      ProgramUniformBlock block{b.name, b.binding, 0, nullptr};
      for (const CompiledShader* s : ordered)
        for (const UniformBlock& u : s->reflection.uniform_blocks)
          if (u.binding == b.binding && !block.reflection) block.size = u.size, block.reflection = &u;
      p.blocks_.push_back(block);
    } else if (b.kind == DescriptorKind::storage_buffer) {
      ProgramStorageBuffer buffer{b.name, b.binding, 0, false};
      for (const CompiledShader* s : ordered)
        for (const UniformBlock& u : s->reflection.storage_blocks)
          if (u.binding == b.binding) {
            buffer.size = std::max(buffer.size, u.size);
            buffer.written |= u.written;
            if (buffer.element == ScalarKind::other && !u.members.empty()) buffer.element = u.members[0].type.scalar;
          }
      p.storage_buffers_.push_back(buffer);
    } else if (b.kind == DescriptorKind::uniform_texel_buffer || b.kind == DescriptorKind::storage_texel_buffer) {
      p.texel_buffers_.push_back({b.name, b.kind, b.binding});
    } else {
      ProgramImage image{b.name, b.kind, ImageDim::dim_2d, b.binding, b.count};
      for (const CompiledShader* s : ordered)
        for (const ImageBinding& i : s->reflection.images)
          if (i.binding == b.binding)
            image.dim = i.dim, image.arrayed = i.arrayed, image.shadow |= i.shadow,
            image.multisampled |= i.multisampled, image.sampled = i.sampled;
      p.images_.push_back(image);
    }
  }
  VkDescriptorSetLayoutCreateInfo set_info =
      structure<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  if (mode == DescriptorMode::push) set_info.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  set_info.bindingCount = uint32_t(bindings.size());
  set_info.pBindings = bindings.data();
  if (!check(vkCreateDescriptorSetLayout(ctx.device(), &set_info, nullptr, &p.set_layout_), sink,
             "vkCreateDescriptorSetLayout"))
    return std::nullopt;

  std::vector<VkPushConstantRange> ranges;
  for (const CompiledShader* s : ordered)
    for (const UniformBlock& pc : s->reflection.push_constants)
      ranges.push_back({VkShaderStageFlags(to_vk_stage(s->reflection.stage)), 0, pc.size});
  VkPipelineLayoutCreateInfo layout_info =
      structure<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &p.set_layout_;
  layout_info.pushConstantRangeCount = uint32_t(ranges.size());
  layout_info.pPushConstantRanges = ranges.data();
  if (!check(vkCreatePipelineLayout(ctx.device(), &layout_info, nullptr, &p.pipeline_layout_), sink,
             "vkCreatePipelineLayout"))
    return std::nullopt;
  if (compute) {
    VkComputePipelineCreateInfo info =
        structure<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    info.stage = p.stage_infos_.front();
    info.layout = p.pipeline_layout_;
    if (!check(vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &p.compute_pipeline_), sink,
               "vkCreateComputePipelines"))
      return std::nullopt;
  }
  return p;
}

}  // namespace fx::vk
