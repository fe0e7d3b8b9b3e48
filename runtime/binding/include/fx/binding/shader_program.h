// fx::vk::ShaderProgram: the shader modules of one pass plus the descriptor set layout and
// pipeline layout derived from its linked reflection.
#pragma once
#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <vector>

#include "fx/compile/program_link.h"
#include "fx/compile/shader_compiler.h"
#include "fx/vulkan/context.h"

namespace fx::vk {

// How a program's descriptors are delivered.
enum class DescriptorMode {
  // Descriptor sets from per-frame pools; uniform blocks are UNIFORM_BUFFER_DYNAMIC so the
  // ring offset changes without touching the set.
  sets,
  // vkCmdPushDescriptorSetKHR (VK_KHR_push_descriptor); uniform blocks are UNIFORM_BUFFER
  // with the ring offset written into each push.
  push,
};

// One uniform block of the program (set 0).
struct ProgramUniformBlock {
  std::string name;
  uint32_t binding = 0;
  uint32_t size = 0;                         // bytes
  const UniformBlock* reflection = nullptr;  // members, from the first stage using it
};

// One texture, sampler or combined image-sampler of the program (set 0).
struct ProgramImage {
  std::string name;
  DescriptorKind kind = DescriptorKind::combined_image_sampler;
  ImageDim dim = ImageDim::dim_2d;
  uint32_t binding = 0;
  uint32_t count = 1;
  bool arrayed = false;                      // Texture2DArray, TextureCubeArray, Texture1DArray
  bool shadow = false;                       // sampled with depth comparison (SamplerComparisonState, sampler2DShadow)
  bool multisampled = false;                 // Texture2DMS, Texture2DMSArray: needs an image of more than one sample
  ScalarKind sampled = ScalarKind::float32;  // int32/uint32: Texture2D<int>/<uint> need an integer view
};

// One storage buffer of the program (set 0): a (RW/Append/Consume)StructuredBuffer,
// (RW)ByteAddressBuffer or tbuffer, or an Append/Consume buffer's counter ("name@count").
struct ProgramStorageBuffer {
  std::string name;
  uint32_t binding = 0;
  uint32_t size = 0;     // bytes before any runtime-sized array (the fixed part of the block)
  bool written = false;  // some stage writes it (an RW, Append or Consume buffer, a counter)
  // The scalar of its first member (a StructuredBuffer<float3>'s float, a struct's first
  // field's): how a preview fills a stand-in it only reads, and pictures what a pass wrote.
  ScalarKind element = ScalarKind::other;
};

// One texel buffer of the program (set 0): Buffer<T> (uniform) or RWBuffer<T> (storage).
struct ProgramTexelBuffer {
  std::string name;
  DescriptorKind kind = DescriptorKind::uniform_texel_buffer;
  uint32_t binding = 0;
};

class ShaderProgram {
 public:
  // `stages` must be compiled, linked with link_program (giving `layout`) and outlive the
  // program (reflection is referenced, not copied). Reports "vk-program-no-vertex-stage",
  // "vk-program-tessellation-stages" (a hull shader without a domain shader or the reverse),
  // "vk-descriptor-unsupported" (arrays in push mode) and "vk-call-failed".
  // A program of one compute stage is a compute program: its pipeline is made here.
  static std::optional<ShaderProgram> create(const Context& ctx, const std::vector<const CompiledShader*>& stages,
                                             const ProgramLayout& layout, DescriptorMode mode, DiagnosticSink& sink);

  ShaderProgram() = default;
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  ~ShaderProgram() { reset(); }

  // XXH3 over every stage's SPIR-V and entry point (the program's part of a pipeline key).
  uint64_t hash() const { return hash_; }
  DescriptorMode descriptor_mode() const { return mode_; }
  VkDescriptorSetLayout set_layout() const { return set_layout_; }
  VkPipelineLayout pipeline_layout() const { return pipeline_layout_; }
  // Shader stage create infos (entry point names point into the program).
  const std::vector<VkPipelineShaderStageCreateInfo>& stage_infos() const { return stage_infos_; }
  // Vertex shader inputs with their semantics (vertex attributes): those the SPIR-V still
  // reads (an input the compiler removed as unused must not be fed an attribute).
  const std::vector<InterfaceVariable>& vertex_inputs() const { return vertex_inputs_; }
  // Colour outputs of the fragment stage (0 without a fragment stage).
  // Control points per patch the hull (tessellation control) shader takes: its pipelines
  // draw patch lists of this size. 0 for a program without tessellation stages.
  uint32_t patch_control_points() const { return patch_control_points_; }
  const std::vector<ProgramUniformBlock>& uniform_blocks() const { return blocks_; }
  const std::vector<ProgramImage>& images() const { return images_; }
  const std::vector<ProgramStorageBuffer>& storage_buffers() const { return storage_buffers_; }
  const std::vector<ProgramTexelBuffer>& texel_buffers() const { return texel_buffers_; }
  // A compute program's pipeline (VK_NULL_HANDLE for a graphics program) and workgroup size.
  VkPipeline compute_pipeline() const { return compute_pipeline_; }
  const uint32_t* local_size() const { return local_size_; }
  // Descriptor counts of the set layout, for pool sizing.

  void reset();

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  uint64_t hash_ = 0;
  DescriptorMode mode_ = DescriptorMode::sets;
  std::vector<VkShaderModule> modules_;
  std::vector<std::string> entry_points_;
  std::vector<VkPipelineShaderStageCreateInfo> stage_infos_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  std::vector<InterfaceVariable> vertex_inputs_;
  uint32_t patch_control_points_ = 0;
  std::vector<ProgramUniformBlock> blocks_;
  std::vector<ProgramImage> images_;
  std::vector<ProgramStorageBuffer> storage_buffers_;
  std::vector<ProgramTexelBuffer> texel_buffers_;
  VkPipeline compute_pipeline_ = VK_NULL_HANDLE;
  uint32_t local_size_[3] = {1, 1, 1};
};

// VkShaderStageFlagBits of a shader stage.
VkShaderStageFlagBits to_vk_stage(ShaderStage stage);
// VkDescriptorType of a program binding in `mode`.
VkDescriptorType to_vk_descriptor(DescriptorKind kind, DescriptorMode mode);

}  // namespace fx::vk
