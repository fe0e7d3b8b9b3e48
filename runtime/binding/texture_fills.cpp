// TextureFills: texture shaders' compute programs made with a binding, run at its first bind.
#include "fx/binding/texture_fills.h"

#include <algorithm>

#include "fx/binding/pass_resources.h"
#include "fx/compile/texture_fill_unit.h"
#include "fx/compile/uniform_layout.h"
#include "fx/vulkan/buffer.h"

namespace fx::vk {

struct TextureFills::Fill {
  std::string what;   // "texture shader 'F' of 'T'", for messages
  SourceRange range;  // the function annotation
  TextureShader shader;
  const PassProgram* program = nullptr;
  ShaderProgram compute;
  std::vector<std::pair<uint32_t, ProgramUniformBlock>> blocks;  // store block id, the program's block
  std::optional<Texture> texture;
  bool failed = false;
};

namespace {

ImageDim sampled_as(TextureShape shape) {
  switch (shape) {
    case TextureShape::tex3d: return ImageDim::dim_3d;
    case TextureShape::cube: return ImageDim::cube;
    default: return ImageDim::dim_2d;
  }
}

const char* shape_name(ImageDim dim) {
  switch (dim) {
    case ImageDim::dim_1d: return "1D";
    case ImageDim::dim_3d: return "3D";
    case ImageDim::cube: return "cube";
    default: return "2D";
  }
}

ImageKind image_kind(TextureShape shape) {
  switch (shape) {
    case TextureShape::tex3d: return ImageKind::image3d;
    case TextureShape::cube: return ImageKind::cube;
    default: return ImageKind::image2d;
  }
}

// The compiler's diagnostics of the fill's stage, as warnings: the effect draws without the fill.
void report_as_warnings(const std::vector<Diagnostic>& diagnostics, DiagnosticSink& sink) {
  for (const Diagnostic& d : diagnostics) {
    Diagnostic& copy = sink.warning(d.id, d.range, d.message);
    copy.notes = d.notes;
  }
}

// The first error's message among `diagnostics`, or `fallback`.
std::string first_error(const std::vector<Diagnostic>& diagnostics, const char* fallback) {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::error) return d.message;
  return fallback;
}

// A descriptor pool for the one set of a fill, destroyed with it.
struct OneSetPool {
  VkDevice device = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  ~OneSetPool() {
    if (pool) vkDestroyDescriptorPool(device, pool, nullptr);
  }
};

}  // namespace

TextureFills::TextureFills(const Context& ctx, ParameterStore& params) : ctx_(&ctx), params_(&params) {}

TextureFills::~TextureFills() = default;

uint32_t TextureFills::add(const EffectModel& model, uint32_t texture, ImageDim dim, bool arrayed,
                           EffectPrograms& programs, DiagnosticSink& sink) {
  for (const auto& [param, answer] : added_)
    if (param == texture) return answer;
  const TextureInfo* info = model.texture_of(texture);
  if (!info || !info->shader) return kNoIndex;
  uint32_t& answer = added_.emplace_back(texture, kNoIndex).second;
  auto fill = std::make_unique<Fill>();
  fill->shader = *info->shader;
  fill->range = fill->shader.range;
  fill->what = "texture shader '" + fill->shader.function + "' of '" + model.parameters[texture].name + "'";
  const std::string standing_in = "; a stand-in is bound";
  if (sampled_as(fill->shader.shape) != dim || arrayed) {
    sink.warning("vk-texture-shader-failed", fill->range,
                 fill->what + " fills a " + shape_name(sampled_as(fill->shader.shape)) +
                     " texture; the shader samples it as a " + shape_name(dim) + (arrayed ? " array" : "") +
                     standing_in);
    return kNoIndex;
  }
  const PassProgram& program = programs.texture_fill(fill->shader);
  if (!program.compiled) {
    std::vector<Diagnostic> diagnostics = program.diagnostics;
    if (!program.stages.empty())
      diagnostics.insert(diagnostics.begin(), program.stages[0].diagnostics.begin(),
                         program.stages[0].diagnostics.end());
    sink.warning("vk-texture-shader-failed", fill->range,
                 fill->what + " does not compile as a compute shader (" +
                     first_error(diagnostics, "the compiler gave no reason") + ")" + standing_in);
    report_as_warnings(diagnostics, sink);
    return kNoIndex;
  }
  for (const ProgramBinding& b : program.layout.bindings) {
    const bool texels = b.kind == DescriptorKind::storage_buffer && b.name == kTextureFillTexels;
    if (texels || b.kind == DescriptorKind::uniform_buffer) continue;
    sink.warning("vk-texture-shader-failed", fill->range,
                 fill->what + " reads '" + b.name +
                     "': a texture shader reads its position, its texel size and the effect's constants, no "
                     "textures, samplers or buffers" +
                     standing_in);
    return kNoIndex;
  }
  DiagnosticSink made;
  std::optional<ShaderProgram> compute =
      ShaderProgram::create(*ctx_, {&program.stages[0].shader}, program.layout, DescriptorMode::sets, made);
  if (!compute) {
    sink.warning("vk-texture-shader-failed", fill->range,
                 fill->what + ": its compute pipeline could not be made (" +
                     first_error(made.diagnostics(), "no reason given") + ")" + standing_in);
    return kNoIndex;
  }
  fill->compute = std::move(*compute);
  // The globals it reads, laid out over the parameters as a pass's are.
  const std::vector<UniformBlockLayout> layouts = uniform_layouts(model, program);
  for (const ProgramUniformBlock& block : fill->compute.uniform_blocks()) {
    const uint32_t id = unique_uniform_block_id();
    auto layout = std::find_if(layouts.begin(), layouts.end(),
                               [&](const UniformBlockLayout& l) { return l.binding == block.binding; });
    if (layout != layouts.end()) {
      ParamStatus status = params_->bind_layout(id, layout->members, block.size);
      if (!status.message.empty())
        sink.warning("vk-uniform-unbound", fill->range, fill->what + ", block '" + block.name + "': " + status.message);
    }
    fill->blocks.emplace_back(id, block);
  }
  answer = static_cast<uint32_t>(fills_.size());
  fills_.push_back(std::move(fill));
  return answer;
}

const Texture* TextureFills::texture(uint32_t index, DiagnosticSink& sink) {
  if (index >= fills_.size()) return nullptr;
  Fill& fill = *fills_[index];
  if (!fill.texture && !fill.failed) {
    DiagnosticSink made;
    fill.failed = !run(fill, made);
    if (fill.failed)
      sink.warning("vk-texture-shader-failed", fill.range,
                   fill.what + " could not be run (" + first_error(made.diagnostics(), "no reason given") +
                       "); a stand-in is bound");
  }
  return fill.texture ? &*fill.texture : nullptr;
}

bool TextureFills::run(Fill& fill, DiagnosticSink& sink) {
  const TextureShader& s = fill.shader;
  const uint32_t layers = texture_fill_layers(s);
  const VkDeviceSize bytes = VkDeviceSize(s.width) * s.height * layers * 4;
  std::optional<Buffer> texels =
      Buffer::create(*ctx_,
                     {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                      MemoryUsage::device_local, "texture shader texels"},
                     sink);
  if (!texels) return false;
  // The globals as the store holds them now.
  std::vector<Buffer> uniforms;
  for (const auto& [id, block] : fill.blocks) {
    std::optional<Buffer> u = Buffer::create(
        *ctx_, {block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUsage::upload, "texture shader constants"}, sink);
    if (!u) return false;
    std::vector<uint8_t> packed(block.size, 0);
    params_->write_block(id, packed);  // a block whose layout the store refused stays zero
    u->write(packed.data(), packed.size());
    uniforms.push_back(std::move(*u));
  }
  OneSetPool pool{ctx_->device()};
  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, std::max<uint32_t>(1, uint32_t(uniforms.size()))}};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 2;
  pool_info.pPoolSizes = sizes;
  if (vkCreateDescriptorPool(ctx_->device(), &pool_info, nullptr, &pool.pool) != VK_SUCCESS) {
    sink.error("vk-call-failed", {}, "vkCreateDescriptorPool failed for a texture shader");
    return false;
  }
  VkDescriptorSetLayout set_layout = fill.compute.set_layout();
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool.pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  if (vkAllocateDescriptorSets(ctx_->device(), &alloc, &set) != VK_SUCCESS) {
    sink.error("vk-call-failed", {}, "vkAllocateDescriptorSets failed for a texture shader");
    return false;
  }
  std::vector<VkDescriptorBufferInfo> infos;
  infos.reserve(uniforms.size() + 1);
  std::vector<VkWriteDescriptorSet> writes;
  auto write = [&](uint32_t binding, VkDescriptorType type, VkBuffer buffer, VkDeviceSize range) {
    infos.push_back({buffer, 0, range});
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pBufferInfo = &infos.back();
    writes.push_back(w);
  };
  for (const ProgramStorageBuffer& b : fill.compute.storage_buffers())
    write(b.binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, texels->handle(), VK_WHOLE_SIZE);
  for (size_t i = 0; i < uniforms.size(); ++i)
    write(fill.blocks[i].second.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, uniforms[i].handle(),
          fill.blocks[i].second.size);
  vkUpdateDescriptorSets(ctx_->device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
  const std::vector<uint32_t> dynamic_offsets(uniforms.size(), 0);
  ImageDesc desc;
  desc.kind = image_kind(s.shape);
  desc.format = VK_FORMAT_R8G8B8A8_UNORM;
  desc.width = s.width;
  desc.height = s.height;
  desc.depth = s.shape == TextureShape::tex3d ? s.depth : 1;
  desc.debug_name = "texture shader";
  const auto groups = [](uint32_t n) { return (n + kTextureFillGroup - 1) / kTextureFillGroup; };
  fill.texture = Texture::from_device_texels(
      *ctx_, desc, texels->handle(),
      [&](VkCommandBuffer cmd) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, fill.compute.compute_pipeline());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, fill.compute.pipeline_layout(), 0, 1, &set,
                                uint32_t(dynamic_offsets.size()), dynamic_offsets.data());
        vkCmdDispatch(cmd, groups(s.width), groups(s.height), layers);
      },
      sink);
  return fill.texture.has_value();
}

}  // namespace fx::vk
