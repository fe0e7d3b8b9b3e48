// fx::vk::PassRecorder: applies passes into the application's command buffer: binds the
// pipeline, records dynamic state and binds descriptors (uniform ring offsets), skipping
// anything identical to what the previous pass left bound. The application draws between
// apply() calls, all inside its vkCmdBeginRendering; usage: docs/vulkan-pipelines.md.
#pragma once
#include <vulkan/vulkan.h>

#include <optional>
#include <span>
#include <vector>

#include "fx/binding/pass_resources.h"
#include "fx/binding/pipeline_cache.h"
#include "fx/vulkan/apply_stats.h"
#include "fx/vulkan/frame_resources.h"

namespace fx::vk {

// Everything apply() needs for one pass.
struct PassDesc {
  const ShaderProgram* program = nullptr;
  PipelineState state;
  const VertexInput* vertex_input = nullptr;
  PassResources* resources = nullptr;  // its program must be `program`
  // When set, the pipeline the cache gives for this pass at the begun formats: a caller that
  // remembers it spares the recorder hashing the pipeline key on every apply.
  VkPipeline pipeline = VK_NULL_HANDLE;
  // When not empty: the ring offsets (from write_uniform) of every uniform block, in
  // program.uniform_blocks() order, written by the caller; the resources' block shadows
  // are then not read.
  std::span<const uint32_t> uniform_offsets = {};
};

class PassRecorder {
 public:
  // `dynamic` chooses the pipeline path: DynamicStateSet::from_features(ctx.features()) or
  // DynamicStateSet::none(). Everything referenced must outlive the recorder.
  PassRecorder(const Context& ctx, PipelineCache& pipelines, FrameResources& frames, DynamicStateSet dynamic);

  // Starts recording passes into `cmd` for attachments of `formats`; sets viewport and scissor.
  void begin(VkCommandBuffer cmd, const RenderingFormats& formats, const VkViewport& viewport, const VkRect2D& scissor);
  // Binds what `pass` needs. False (with diagnostics) if a pipeline, upload or descriptor
  // could not be made, or a texture is unbound ("vk-texture-unbound"); nothing is drawn then.
  bool apply(const PassDesc& pass, DiagnosticSink& sink);
  // Applies again the pass applied last (nothing else applied since), whose caller-written
  // uniforms moved to `uniform_offsets`: pipeline, dynamic state and textures are bound
  // already, so only the descriptor offsets are bound again. `moved` false promises the
  // offsets are the ones applied last (nothing to bind). False (nothing recorded) when
  // `resources` is not that pass's, its textures changed, it pushes descriptors or the
  // frame moved on since: call apply() then. Inline: it runs once per object.
  bool reapply(const PassResources& r, std::span<const uint32_t> uniform_offsets, bool moved = true) {
    // The same resources are the same program: as many offsets as apply() bound.
    if (&r != applied_ || r.images_changed_) return false;
    return rebind(uniform_offsets, moved);
  }
  // reapply() for a caller that knows the last apply() was this pass's resources and no
  // image of theirs was bound since (EffectBinding, between begin() and end()).
  bool rebind(std::span<const uint32_t> uniform_offsets, bool moved) {
    if (moved) {
      // apply() left a set valid for its frame bound; a pushed set is pushed by apply().
      if (!rebind_set_ || frames_->frame() != applied_frame_) return false;
      vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_,
                              uint32_t(uniform_offsets.size()), uniform_offsets.data());
      ++stats_.descriptor_binds;
      // Not copied (this runs once per object): the next apply() finds no bound offsets
      // and binds its own.
      offsets_.clear();
    }
    ++stats_.passes;
    return true;
  }
  // Ends the sequence; the next begin() assumes nothing is bound.
  void end();
  // Records compute pass `pass` (a compute program; no vertex input, no state) into `cmd`
  // outside any rendering: binds its pipeline and descriptors, dispatches `groups`
  // workgroups, then a barrier that makes its writes (storage buffers and images) visible to
  // the shader reads, vertex and index fetches and indirect arguments of everything recorded
  // after it. Between passes (not between begin() and end()).
  bool dispatch(VkCommandBuffer cmd, const PassDesc& pass, const uint32_t groups[3], DiagnosticSink& sink);
  // Reserves `bytes` of the frame's uniform ring, lets `fill(uint8_t*)` write them in place
  // and returns their offset for PassDesc::uniform_offsets (counted as an upload).
  // nullopt and "vk-uniform-ring-full" when the frame's slice has no room.
  template <class Fill>
  std::optional<uint32_t> write_uniform(uint32_t bytes, Fill&& fill, DiagnosticSink& sink) {
    std::optional<UniformAllocation> a = frames_->reserve_uniform(bytes, sink);
    if (!a) return std::nullopt;
    fill(static_cast<uint8_t*>(a->mapped));
    frames_->flush_uniform(*a, bytes);
    ++stats_.uniform_uploads;
    return a->offset;
  }

  const ApplyStats& stats() const { return stats_; }
  void reset_stats() { stats_ = {}; }
  const DynamicStateSet& dynamic() const { return dynamic_; }

 private:
  void record_dynamic_state(const PipelineState& s, bool all);
  bool bind_descriptors(const PassDesc& pass, DiagnosticSink& sink);
  VkPipelineBindPoint bind_point_ = VK_PIPELINE_BIND_POINT_GRAPHICS;  // of the pass being bound
  bool images_bound(const PassResources& r, DiagnosticSink& sink) const;

  // What reapply() reads, once per object, first: together in one or two cache lines.
  FrameResources* frames_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  // The last successful apply(): its resources, frame, and whether reapply() may bind its
  // set with other offsets (a set, not a push).
  const PassResources* applied_ = nullptr;
  uint64_t applied_frame_ = 0;
  bool rebind_set_ = false;
  // What is bound now.
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  std::vector<uint32_t> offsets_;  // empty after reapply(): unknown, apply() binds again
  ApplyStats stats_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  std::optional<PipelineState> state_;
  const PassResources* pushed_ = nullptr;

  const Context* ctx_;
  PipelineCache* pipelines_;
  DynamicStateSet dynamic_;
  RenderingFormats formats_;
  // Scratch reused by every apply so recording allocates nothing once warm.
  std::vector<uint32_t> next_offsets_;
  std::vector<VkDescriptorBufferInfo> buffer_infos_;
  std::vector<VkDescriptorImageInfo> image_infos_;
  std::vector<VkWriteDescriptorSet> writes_;
};

}  // namespace fx::vk
