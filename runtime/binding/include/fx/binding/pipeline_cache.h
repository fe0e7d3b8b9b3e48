// fx::vk::PipelineCache: graphics pipelines by key (program + static state + vertex input +
// attachment formats), backed by a VkPipelineCache that can be saved to and loaded from disk.
#pragma once
#include <vulkan/vulkan.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <unordered_map>

#include "fx/binding/shader_program.h"
#include "fx/binding/vertex_layout.h"
#include "fx/vulkan/context.h"
#include "fx/vulkan/pipeline_state.h"
#include "fx/vulkan/rendering_formats.h"

namespace fx::vk {

// Everything a pipeline is created from, reduced to comparable values.
struct PipelineKey {
  uint64_t program = 0;       // ShaderProgram::hash()
  uint64_t vertex_input = 0;  // VertexInput::hash
  PipelineState state;        // static_part() of the pass state
  RenderingFormats formats;
  uint32_t dynamic_bits = 0;  // DynamicStateSet::bits()
  friend bool operator==(const PipelineKey&, const PipelineKey&) = default;
  uint64_t hash() const;
};

// Counters for tests and benchmarks.
struct PipelineCacheStats {
  uint64_t lookups = 0;
  uint64_t created = 0;  // vkCreateGraphicsPipelines calls that succeeded
};

class PipelineCache {
 public:
  // Creates the VkPipelineCache, seeded from `initial_data` (see load_file) if given.
  static std::optional<PipelineCache> create(const Context& ctx, DiagnosticSink& sink,
                                             const std::vector<uint8_t>& initial_data = {});

  PipelineCache() = default;
  PipelineCache(PipelineCache&& other) noexcept { *this = std::move(other); }
  PipelineCache& operator=(PipelineCache&& other) noexcept;
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;
  ~PipelineCache();

  // The pipeline for this program, state, vertex input and formats; created on first use.
  // Fields of `state` in `dynamic` are masked out of the key (and must be recorded by the
  // caller as dynamic state). Null (and a diagnostic) when creation fails.
  VkPipeline get(const ShaderProgram& program, const PipelineState& state, const VertexInput& vertex_input,
                 const RenderingFormats& formats, const DynamicStateSet& dynamic, DiagnosticSink& sink);

  size_t size() const { return pipelines_.size(); }
  const PipelineCacheStats& stats() const { return stats_; }
  VkPipelineCache handle() const { return cache_; }

  // The VkPipelineCache contents behind a header naming this device (vendor, device, driver
  // version, pipelineCacheUUID) and a checksum.
  std::vector<uint8_t> serialize(DiagnosticSink& sink) const;
  // Writes serialize() to `path` via a temporary file and a rename, so a crash never leaves
  // a torn file. False and "vk-pipeline-cache-write" on I/O failure.
  bool save_file(const std::filesystem::path& path, DiagnosticSink& sink) const;
  // Reads a file written by save_file. A missing file gives an empty vector silently; a file
  // for another device or driver, or a corrupt one, gives an empty vector and a
  // "vk-pipeline-cache-stale" note (the cache then starts cold).
  static std::vector<uint8_t> load_file(const Context& ctx, const std::filesystem::path& path, DiagnosticSink& sink);

  // Destroys every pipeline now (the device must be done with them).
  void clear();

 private:
  struct KeyHash {
    size_t operator()(const PipelineKey& k) const { return size_t(k.hash()); }
  };
  VkPipeline create_pipeline(const ShaderProgram& program, const PipelineState& state, const VertexInput& vertex_input,
                             const RenderingFormats& formats, const DynamicStateSet& dynamic, DiagnosticSink& sink);

  const Context* ctx_ = nullptr;
  VkPipelineCache cache_ = VK_NULL_HANDLE;
  std::unordered_map<PipelineKey, VkPipeline, KeyHash> pipelines_;
  PipelineCacheStats stats_;
};

}  // namespace fx::vk
