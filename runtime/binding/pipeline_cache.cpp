// PipelineCache: keyed graphics pipelines (static or dynamic-state path) and persistence.
#include "fx/binding/pipeline_cache.h"

#define XXH_INLINE_ALL  // xxHash header-only: fxkit links no libxxhash
#include <xxhash.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

#include "fx/vulkan/graphics_pipeline.h"
#include "fx/vulkan/vk_check.h"

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
  VkPipelineCacheCreateInfo info = structure<VkPipelineCacheCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
  info.initialDataSize = initial_data.size();
  info.pInitialData = initial_data.empty() ? nullptr : initial_data.data();
  if (!check(vkCreatePipelineCache(ctx.device(), &info, nullptr, &c.cache_), sink, "vkCreatePipelineCache"))
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

VkPipeline PipelineCache::get(const ShaderProgram& program, const PipelineState& state, const VertexInput& vertex_input,
                              const RenderingFormats& formats, const DynamicStateSet& dynamic, DiagnosticSink& sink) {
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

VkPipeline PipelineCache::create_pipeline(const ShaderProgram& program, const PipelineState& s, const VertexInput& vi,
                                          const RenderingFormats& formats, const DynamicStateSet& dynamic,
                                          DiagnosticSink& sink) {
  VkDynamicState dynamic_states[40];
  GraphicsPipelineDesc desc;
  desc.stages = program.stage_infos();
  desc.layout = program.pipeline_layout();
  desc.state = s;
  desc.vertex_bindings = vi.bindings;
  desc.vertex_attributes = vi.attributes;
  desc.formats = formats;
  desc.dynamic_states = {dynamic_states, dynamic.dynamic_state_list(dynamic_states, formats.color_count,
                                                                    s.topology == VK_PRIMITIVE_TOPOLOGY_PATCH_LIST)};
  return create_graphics_pipeline(ctx_->device(), cache_, desc, sink);
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
  if (!check(vkGetPipelineCacheData(ctx_->device(), cache_, &size, nullptr), sink, "vkGetPipelineCacheData")) return {};
  std::vector<uint8_t> out(sizeof(FileHeader) + size);
  if (!check(vkGetPipelineCacheData(ctx_->device(), cache_, &size, out.data() + sizeof(FileHeader)), sink,
             "vkGetPipelineCacheData"))
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

std::vector<uint8_t> PipelineCache::load_file(const Context& ctx, const std::filesystem::path& path,
                                              DiagnosticSink& sink) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto stale = [&](const std::string& why) {
    sink.report(Severity::note, "vk-pipeline-cache-stale", {}, "ignoring pipeline cache " + path.string() + ": " + why);
    return std::vector<uint8_t>{};
  };
  FileHeader h;
  if (bytes.size() < sizeof h) return stale("file too short");
  std::memcpy(&h, bytes.data(), sizeof h);
  const FileHeader want = header_for(ctx);
  if (std::memcmp(h.magic, want.magic, sizeof h.magic) != 0 || h.version != want.version)
    return stale("not an fxkit pipeline cache");
  if (h.vendor_id != want.vendor_id || h.device_id != want.device_id || h.driver_version != want.driver_version ||
      std::memcmp(h.uuid, want.uuid, VK_UUID_SIZE) != 0)
    return stale("written for another device or driver");
  if (h.data_size != bytes.size() - sizeof h || h.checksum != XXH3_64bits(bytes.data() + sizeof h, size_t(h.data_size)))
    return stale("checksum mismatch");
  return std::vector<uint8_t>(bytes.begin() + sizeof h, bytes.end());
}

}  // namespace fx::vk
