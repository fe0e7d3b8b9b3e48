// PipelineCache: keyed graphics pipelines (static or dynamic-state path) and persistence.
#include "fx/vulkan/pipeline_cache.h"

#define XXH_INLINE_ALL  // xxHash header-only: fxkit links no libxxhash
#include <xxhash.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

#include "vk_check.h"

namespace fx::vk {

uint64_t PipelineKey::hash() const {
  XXH3_state_t* hs = XXH3_createState();
  XXH3_64bits_reset(hs);
  XXH3_64bits_update(hs, &program, sizeof program);
  XXH3_64bits_update(hs, &vertex_input, sizeof vertex_input);
  XXH3_64bits_update(hs, &state, sizeof state);
  XXH3_64bits_update(hs, &formats, sizeof formats);
  XXH3_64bits_update(hs, &dynamic_bits, sizeof dynamic_bits);
  const uint64_t h = XXH3_64bits_digest(hs);
  XXH3_freeState(hs);
  return h;
}

std::optional<PipelineCache> PipelineCache::create(const Context& ctx, DiagnosticSink& sink,
                                                   const std::vector<uint8_t>& initial_data) {
  PipelineCache c;
  c.ctx_ = &ctx;
  VkPipelineCacheCreateInfo info = structure<VkPipelineCacheCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
  info.initialDataSize = initial_data.size();
  info.pInitialData = initial_data.empty() ? nullptr : initial_data.data();
  if (!check(vkCreatePipelineCache(ctx.device(), &info, nullptr, &c.cache_), sink,
             "vkCreatePipelineCache"))
    return std::nullopt;
  return c;
}

PipelineCache& PipelineCache::operator=(PipelineCache&& o) noexcept {
  if (this == &o) return *this;
  clear();
  if (cache_) vkDestroyPipelineCache(ctx_->device(), cache_, nullptr);
  ctx_ = o.ctx_;
  cache_ = std::exchange(o.cache_, VK_NULL_HANDLE);
  pipelines_ = std::move(o.pipelines_);
  o.pipelines_.clear();
  stats_ = o.stats_;
  return *this;
}

PipelineCache::~PipelineCache() {
  clear();
  if (cache_) vkDestroyPipelineCache(ctx_->device(), cache_, nullptr);
}

void PipelineCache::clear() {
  for (auto& [key, pipeline] : pipelines_) vkDestroyPipeline(ctx_->device(), pipeline, nullptr);
  pipelines_.clear();
}

VkPipeline PipelineCache::get(const ShaderProgram& program, const PipelineState& state,
                              const VertexInput& vertex_input, const RenderingFormats& formats,
                              const DynamicStateSet& dynamic, DiagnosticSink& sink) {
  ++stats_.lookups;
  PipelineKey key;
  key.program = program.hash();
  key.vertex_input = vertex_input.hash;
  key.state = static_part(state, dynamic);
  key.formats = formats;
  key.dynamic_bits = dynamic.bits();
  auto it = pipelines_.find(key);
  if (it != pipelines_.end()) return it->second;
  VkPipeline p = create_pipeline(program, key.state, vertex_input, formats, dynamic, sink);
  if (p) pipelines_.emplace(key, p), ++stats_.created;
  return p;
}

VkPipeline PipelineCache::create_pipeline(const ShaderProgram& program, const PipelineState& s,
                                          const VertexInput& vi, const RenderingFormats& formats,
                                          const DynamicStateSet& dynamic, DiagnosticSink& sink) {
  auto vertex = structure<VkPipelineVertexInputStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  vertex.vertexBindingDescriptionCount = uint32_t(vi.bindings.size());
  vertex.pVertexBindingDescriptions = vi.bindings.data();
  vertex.vertexAttributeDescriptionCount = uint32_t(vi.attributes.size());
  vertex.pVertexAttributeDescriptions = vi.attributes.data();

  auto assembly = structure<VkPipelineInputAssemblyStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  assembly.topology = VkPrimitiveTopology(s.topology);
  assembly.primitiveRestartEnable = s.primitive_restart;

  auto viewport = structure<VkPipelineViewportStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  auto raster = structure<VkPipelineRasterizationStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
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

  auto multisample = structure<VkPipelineMultisampleStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = s.samples();
  const VkSampleMask sample_mask = s.sample_mask;
  multisample.pSampleMask = &sample_mask;
  multisample.alphaToCoverageEnable = s.alpha_to_coverage;

  auto depth = structure<VkPipelineDepthStencilStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
  depth.depthTestEnable = s.depth_test;
  depth.depthWriteEnable = s.depth_write;
  depth.depthCompareOp = VkCompareOp(s.depth_compare);
  depth.stencilTestEnable = s.stencil_test;
  depth.front = {VkStencilOp(s.front_fail), VkStencilOp(s.front_pass),
                 VkStencilOp(s.front_depth_fail), VkCompareOp(s.front_compare),
                 s.front_compare_mask, s.front_write_mask, s.front_reference};
  depth.back = {VkStencilOp(s.back_fail), VkStencilOp(s.back_pass),
                VkStencilOp(s.back_depth_fail), VkCompareOp(s.back_compare),
                s.back_compare_mask, s.back_write_mask, s.back_reference};
  depth.maxDepthBounds = 1.0f;

  VkPipelineColorBlendAttachmentState attachments[kMaxColorAttachments]{};
  for (uint32_t i = 0; i < formats.color_count; ++i) {
    const AttachmentBlend& b = s.blend[i];
    attachments[i] = {b.blend_enable,          VkBlendFactor(b.src_color),
                      VkBlendFactor(b.dst_color), VkBlendOp(b.color_op),
                      VkBlendFactor(b.src_alpha), VkBlendFactor(b.dst_alpha),
                      VkBlendOp(b.alpha_op),      VkColorComponentFlags(b.write_mask)};
  }
  auto blend = structure<VkPipelineColorBlendStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  blend.attachmentCount = formats.color_count;
  blend.pAttachments = attachments;
  std::memcpy(blend.blendConstants, s.blend_constants, sizeof blend.blendConstants);

  VkDynamicState dynamic_states[40];
  auto dyn = structure<VkPipelineDynamicStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
  dyn.dynamicStateCount = dynamic.dynamic_state_list(dynamic_states, formats.color_count);
  dyn.pDynamicStates = dynamic_states;

  const VkPipelineRenderingCreateInfo rendering = formats.pipeline_info();

  auto info = structure<VkGraphicsPipelineCreateInfo>(
      VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  info.pNext = &rendering;
  info.stageCount = uint32_t(program.stage_infos().size());
  info.pStages = program.stage_infos().data();
  info.pVertexInputState = &vertex;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dyn;
  info.layout = program.pipeline_layout();
  VkPipeline pipeline = VK_NULL_HANDLE;
  if (!check(vkCreateGraphicsPipelines(ctx_->device(), cache_, 1, &info, nullptr, &pipeline),
             sink, "vkCreateGraphicsPipelines"))
    return VK_NULL_HANDLE;
  return pipeline;
}

namespace {

// On-disk header in front of the VkPipelineCache data.
struct FileHeader {
  char magic[8] = {'F', 'X', 'P', 'C', 'A', 'C', 'H', 'E'};
  uint32_t version = 1;
  uint32_t vendor_id = 0, device_id = 0, driver_version = 0;
  uint8_t uuid[VK_UUID_SIZE] = {};
  uint64_t data_size = 0;
  uint64_t checksum = 0;  // XXH3 of the data
};

FileHeader header_for(const Context& ctx) {
  FileHeader h;
  h.vendor_id = ctx.info().vendor_id;
  h.device_id = ctx.info().device_id;
  h.driver_version = ctx.info().driver_version;
  std::memcpy(h.uuid, ctx.info().uuid.data(), VK_UUID_SIZE);
  return h;
}

}  // namespace

std::vector<uint8_t> PipelineCache::serialize(DiagnosticSink& sink) const {
  size_t size = 0;
  if (!check(vkGetPipelineCacheData(ctx_->device(), cache_, &size, nullptr), sink,
             "vkGetPipelineCacheData"))
    return {};
  std::vector<uint8_t> out(sizeof(FileHeader) + size);
  if (!check(vkGetPipelineCacheData(ctx_->device(), cache_, &size, out.data() + sizeof(FileHeader)),
             sink, "vkGetPipelineCacheData"))
    return {};
  out.resize(sizeof(FileHeader) + size);
  FileHeader h = header_for(*ctx_);
  h.data_size = size;
  h.checksum = XXH3_64bits(out.data() + sizeof(FileHeader), size);
  std::memcpy(out.data(), &h, sizeof h);
  return out;
}

bool PipelineCache::save_file(const std::filesystem::path& path, DiagnosticSink& sink) const {
  std::vector<uint8_t> bytes = serialize(sink);
  if (bytes.empty()) return false;
  std::filesystem::path temp = path;
  temp += ".tmp";
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out.good()) {
      sink.error("vk-pipeline-cache-write", {}, "cannot write " + temp.string());
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    sink.error("vk-pipeline-cache-write", {},
               "cannot rename " + temp.string() + " to " + path.string() + ": " + ec.message());
    std::filesystem::remove(temp, ec);
    return false;
  }
  return true;
}

std::vector<uint8_t> PipelineCache::load_file(const Context& ctx,
                                              const std::filesystem::path& path,
                                              DiagnosticSink& sink) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto stale = [&](const std::string& why) {
    sink.report(Severity::note, "vk-pipeline-cache-stale", {},
                "ignoring pipeline cache " + path.string() + ": " + why);
    return std::vector<uint8_t>{};
  };
  FileHeader h;
  if (bytes.size() < sizeof h) return stale("file too short");
  std::memcpy(&h, bytes.data(), sizeof h);
  const FileHeader want = header_for(ctx);
  if (std::memcmp(h.magic, want.magic, sizeof h.magic) != 0 || h.version != want.version)
    return stale("not an fxkit pipeline cache");
  if (h.vendor_id != want.vendor_id || h.device_id != want.device_id ||
      h.driver_version != want.driver_version ||
      std::memcmp(h.uuid, want.uuid, VK_UUID_SIZE) != 0)
    return stale("written for another device or driver");
  if (h.data_size != bytes.size() - sizeof h ||
      h.checksum != XXH3_64bits(bytes.data() + sizeof h, size_t(h.data_size)))
    return stale("checksum mismatch");
  return std::vector<uint8_t>(bytes.begin() + sizeof h, bytes.end());
}

}  // namespace fx::vk
