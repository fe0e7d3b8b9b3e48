// PassRecorder: redundant-state-skipping application of passes into a command buffer.
#include "fx/binding/pass_recorder.h"

#include <algorithm>

#include "fx/vulkan/barrier.h"
#include "fx/vulkan/vk_check.h"

namespace fx::vk {

PassRecorder::PassRecorder(const Context& ctx, PipelineCache& pipelines, FrameResources& frames,
                           DynamicStateSet dynamic)
    : frames_(&frames), ctx_(&ctx), pipelines_(&pipelines), dynamic_(dynamic) {}

void PassRecorder::begin(VkCommandBuffer cmd, const RenderingFormats& formats, const VkViewport& viewport,
                         const VkRect2D& scissor) {
  end();
  cmd_ = cmd;
  formats_ = formats;
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  stats_.dynamic_state_calls += 2;
}

void PassRecorder::end() {
  cmd_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  state_.reset();
  layout_ = VK_NULL_HANDLE;
  set_ = VK_NULL_HANDLE;
  offsets_.clear();
  pushed_ = nullptr;
  applied_ = nullptr;
}

bool PassRecorder::dispatch(VkCommandBuffer cmd, const PassDesc& pass, const uint32_t groups[3], DiagnosticSink& sink) {
  end();
  cmd_ = cmd;
  bind_point_ = VK_PIPELINE_BIND_POINT_COMPUTE;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.program->compute_pipeline());
  ++stats_.pipeline_binds;
  const bool bound = bind_descriptors(pass, sink);
  if (bound) {
    vkCmdDispatch(cmd, groups[0], groups[1], groups[2]);
    memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                   VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT |
                       VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                   VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT |
                       VK_ACCESS_INDEX_READ_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    ++stats_.passes;
  }
  bind_point_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
  end();  // the graphics passes after it bind their own pipeline and set
  return bound;
}

bool PassRecorder::apply(const PassDesc& pass, DiagnosticSink& sink) {
  ++stats_.passes;
  applied_ = nullptr;
  VkPipeline pipeline = pass.pipeline
                            ? pass.pipeline
                            : pipelines_->get(*pass.program, pass.state, *pass.vertex_input, formats_, dynamic_, sink);
  if (!pipeline) return false;
  if (pipeline != pipeline_) {
    vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    ++stats_.pipeline_binds;
    pipeline_ = pipeline;
  }
  // Consecutive passes with equal state (every object of a group) have nothing to record.
  if (!state_ || !(pass.state == *state_)) {
    record_dynamic_state(pass.state, !state_.has_value());
    state_ = pass.state;
  }
  if (!bind_descriptors(pass, sink)) return false;
  applied_ = pass.resources;
  applied_frame_ = frames_->frame();
  rebind_set_ = pass.program->descriptor_mode() != DescriptorMode::push;
  return true;
}

void PassRecorder::record_dynamic_state(const PipelineState& s, bool all) {
  const PipelineState* p = all ? nullptr : &*state_;
  uint64_t& calls = stats_.dynamic_state_calls;
  VkCommandBuffer cmd = cmd_;
#define FX_CHANGED(field) (!p || s.field != p->field)
  if (dynamic_.eds1) {
    if (FX_CHANGED(cull_mode)) vkCmdSetCullMode(cmd, s.cull_mode), ++calls;
    if (FX_CHANGED(front_face)) vkCmdSetFrontFace(cmd, VkFrontFace(s.front_face)), ++calls;
    if (FX_CHANGED(topology)) vkCmdSetPrimitiveTopology(cmd, VkPrimitiveTopology(s.topology)), ++calls;
    if (FX_CHANGED(depth_test)) vkCmdSetDepthTestEnable(cmd, s.depth_test), ++calls;
    if (FX_CHANGED(depth_write)) vkCmdSetDepthWriteEnable(cmd, s.depth_write), ++calls;
    if (FX_CHANGED(depth_compare)) vkCmdSetDepthCompareOp(cmd, VkCompareOp(s.depth_compare)), ++calls;
    if (FX_CHANGED(stencil_test)) vkCmdSetStencilTestEnable(cmd, s.stencil_test), ++calls;
    if (FX_CHANGED(front_fail) || FX_CHANGED(front_pass) || FX_CHANGED(front_depth_fail) || FX_CHANGED(front_compare))
      vkCmdSetStencilOp(cmd, VK_STENCIL_FACE_FRONT_BIT, VkStencilOp(s.front_fail), VkStencilOp(s.front_pass),
                        VkStencilOp(s.front_depth_fail), VkCompareOp(s.front_compare)),
          ++calls;
    if (FX_CHANGED(back_fail) || FX_CHANGED(back_pass) || FX_CHANGED(back_depth_fail) || FX_CHANGED(back_compare))
      vkCmdSetStencilOp(cmd, VK_STENCIL_FACE_BACK_BIT, VkStencilOp(s.back_fail), VkStencilOp(s.back_pass),
                        VkStencilOp(s.back_depth_fail), VkCompareOp(s.back_compare)),
          ++calls;
    if (FX_CHANGED(front_compare_mask))
      vkCmdSetStencilCompareMask(cmd, VK_STENCIL_FACE_FRONT_BIT, s.front_compare_mask), ++calls;
    if (FX_CHANGED(back_compare_mask))
      vkCmdSetStencilCompareMask(cmd, VK_STENCIL_FACE_BACK_BIT, s.back_compare_mask), ++calls;
    if (FX_CHANGED(front_write_mask))
      vkCmdSetStencilWriteMask(cmd, VK_STENCIL_FACE_FRONT_BIT, s.front_write_mask), ++calls;
    if (FX_CHANGED(back_write_mask))
      vkCmdSetStencilWriteMask(cmd, VK_STENCIL_FACE_BACK_BIT, s.back_write_mask), ++calls;
    if (FX_CHANGED(front_reference))
      vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_BIT, s.front_reference), ++calls;
    if (FX_CHANGED(back_reference)) vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_BACK_BIT, s.back_reference), ++calls;
    if (FX_CHANGED(depth_bias_constant) || FX_CHANGED(depth_bias_slope) || FX_CHANGED(depth_bias_clamp))
      vkCmdSetDepthBias(cmd, s.depth_bias_constant, s.depth_bias_clamp, s.depth_bias_slope), ++calls;
    if (!p || std::memcmp(s.blend_constants, p->blend_constants, sizeof s.blend_constants) != 0)
      vkCmdSetBlendConstants(cmd, s.blend_constants), ++calls;
  }
  if (dynamic_.eds2) {
    if (FX_CHANGED(depth_bias_enable)) vkCmdSetDepthBiasEnable(cmd, s.depth_bias_enable), ++calls;
    if (FX_CHANGED(rasterizer_discard)) vkCmdSetRasterizerDiscardEnable(cmd, s.rasterizer_discard), ++calls;
    if (FX_CHANGED(primitive_restart)) vkCmdSetPrimitiveRestartEnable(cmd, s.primitive_restart), ++calls;
  }
  const DeviceFunctions& fn = ctx_->functions();
  if (dynamic_.patch_control_points && s.topology == VK_PRIMITIVE_TOPOLOGY_PATCH_LIST &&
      FX_CHANGED(patch_control_points))
    fn.set_patch_control_points(cmd, s.patch_control_points), ++calls;
  if (dynamic_.polygon_mode && FX_CHANGED(polygon_mode))
    fn.set_polygon_mode(cmd, VkPolygonMode(s.polygon_mode)), ++calls;
  if (dynamic_.depth_clamp && FX_CHANGED(depth_clamp)) fn.set_depth_clamp_enable(cmd, s.depth_clamp), ++calls;
  if (dynamic_.sample_mask && FX_CHANGED(sample_mask)) {
    const VkSampleMask mask = s.sample_mask;
    fn.set_sample_mask(cmd, s.samples(), &mask), ++calls;
  }
  if (dynamic_.alpha_to_coverage && FX_CHANGED(alpha_to_coverage))
    fn.set_alpha_to_coverage_enable(cmd, s.alpha_to_coverage), ++calls;
#undef FX_CHANGED
  const uint32_t n = formats_.color_count;
  auto blend_changed = [&](auto same) {
    if (!p) return true;
    for (uint32_t i = 0; i < n; ++i)
      if (!same(s.blend[i], p->blend[i])) return true;
    return false;
  };
  if (n && dynamic_.color_blend_enable && blend_changed([](const AttachmentBlend& a, const AttachmentBlend& b) {
        return a.blend_enable == b.blend_enable;
      })) {
    VkBool32 enables[kMaxColorAttachments];
    for (uint32_t i = 0; i < n; ++i) enables[i] = s.blend[i].blend_enable;
    fn.set_color_blend_enable(cmd, 0, n, enables), ++calls;
  }
  if (n && dynamic_.color_blend_equation && blend_changed([](const AttachmentBlend& a, const AttachmentBlend& b) {
        return a.src_color == b.src_color && a.dst_color == b.dst_color && a.color_op == b.color_op &&
               a.src_alpha == b.src_alpha && a.dst_alpha == b.dst_alpha && a.alpha_op == b.alpha_op;
      })) {
    VkColorBlendEquationEXT eq[kMaxColorAttachments];
    for (uint32_t i = 0; i < n; ++i) {
      const AttachmentBlend& b = s.blend[i];
      eq[i] = {VkBlendFactor(b.src_color), VkBlendFactor(b.dst_color), VkBlendOp(b.color_op),
               VkBlendFactor(b.src_alpha), VkBlendFactor(b.dst_alpha), VkBlendOp(b.alpha_op)};
    }
    fn.set_color_blend_equation(cmd, 0, n, eq), ++calls;
  }
  if (n && dynamic_.color_write_mask &&
      blend_changed([](const AttachmentBlend& a, const AttachmentBlend& b) { return a.write_mask == b.write_mask; })) {
    VkColorComponentFlags masks[kMaxColorAttachments];
    for (uint32_t i = 0; i < n; ++i) masks[i] = s.blend[i].write_mask;
    fn.set_color_write_mask(cmd, 0, n, masks), ++calls;
  }
}

bool PassRecorder::images_bound(const PassResources& r, DiagnosticSink& sink) const {
  const auto& images = r.program().images();
  for (size_t i = 0; i < images.size(); ++i) {
    const PassResources::Bound& b = r.images_[i];
    const bool needs_view = images[i].kind != DescriptorKind::sampler;
    const bool needs_sampler =
        images[i].kind == DescriptorKind::sampler || images[i].kind == DescriptorKind::combined_image_sampler;
    if ((needs_view && !b.view) || (needs_sampler && !b.sampler)) {
      sink.error("vk-texture-unbound", {},
                 "'" + images[i].name + "' has no " + (needs_view && !b.view ? "texture" : "sampler") + " bound");
      return false;
    }
  }
  const auto& buffers = r.program().storage_buffers();
  for (size_t i = 0; i < buffers.size(); ++i)
    if (!r.buffers_[i].buffer) {
      sink.error("vk-texture-unbound", {}, "storage buffer '" + buffers[i].name + "' has no buffer bound");
      return false;
    }
  const auto& texel = r.program().texel_buffers();
  for (size_t i = 0; i < texel.size(); ++i)
    if (!r.texel_views_[i]) {
      sink.error("vk-texture-unbound", {}, "texel buffer '" + texel[i].name + "' has no view bound");
      return false;
    }
  return true;
}

bool PassRecorder::bind_descriptors(const PassDesc& pass, DiagnosticSink& sink) {
  PassResources& r = *pass.resources;
  const ShaderProgram& program = *pass.program;
  const auto& blocks = program.uniform_blocks();
  const auto& images = program.images();
  std::span<const uint32_t> offsets = pass.uniform_offsets;
  if (offsets.empty() && !blocks.empty()) {
    next_offsets_.resize(blocks.size());
    for (size_t i = 0; i < blocks.size(); ++i) {
      PassResources::Block& b = r.blocks_[i];
      if (b.dirty || !frames_->still_valid(b.uploaded_frame)) {
        std::optional<UniformAllocation> a = frames_->upload_uniform(b.data.data(), uint32_t(b.data.size()), sink);
        if (!a) return false;
        b.dirty = false;
        b.uploaded_frame = frames_->frame();
        b.offset = a->offset;
        ++stats_.uniform_uploads;
      }
      next_offsets_[i] = b.offset;
    }
    offsets = next_offsets_;
  } else if (offsets.size() != blocks.size()) {
    sink.error("vk-uniform-offsets", {},
               std::to_string(offsets.size()) + " uniform offsets for " + std::to_string(blocks.size()) + " blocks");
    return false;
  }
  const bool push = program.descriptor_mode() == DescriptorMode::push;
  const bool layout_changed = program.pipeline_layout() != layout_;
  const bool same_offsets = std::equal(offsets.begin(), offsets.end(), offsets_.begin(), offsets_.end());
  if (push && !layout_changed && pushed_ == &r && same_offsets && !r.images_changed_) return true;
  // A set or push is written only from validated images: unchanged ones were checked then.
  if (push && !images_bound(r, sink)) return false;

  // Descriptor writes: uniform blocks then images.
  std::vector<VkDescriptorBufferInfo>& buffers = buffer_infos_;
  std::vector<VkDescriptorImageInfo>& image_infos = image_infos_;
  std::vector<VkWriteDescriptorSet>& writes = writes_;
  auto write_all = [&](VkDescriptorSet set) {
    // Sized up front: the writes point into these arrays.
    buffers.resize(blocks.size());
    size_t elements = 0;
    for (const ProgramImage& image : images) elements += image.count;  // at least 1 (link_program)
    image_infos.resize(elements);
    writes.clear();
    const auto& storage = program.storage_buffers();
    const auto& texel = program.texel_buffers();
    writes.reserve(blocks.size() + images.size() + storage.size() + texel.size());
    for (size_t i = 0; i < blocks.size(); ++i) {
      buffers[i] = {frames_->ring_buffer(), push ? offsets[i] : 0, blocks[i].size};
      auto w = structure<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      w.dstSet = set;
      w.dstBinding = blocks[i].binding;
      w.descriptorCount = 1;
      w.descriptorType = to_vk_descriptor(DescriptorKind::uniform_buffer, program.descriptor_mode());
      w.pBufferInfo = &buffers[i];
      writes.push_back(w);
    }
    for (size_t i = 0, first = 0; i < images.size(); ++i) {
      const PassResources::Bound& b = r.images_[i];
      // Every element of an array is written (an unwritten one is undefined to sample); all
      // take the image bound to the array (EffectBinding warns, vk-image-array-first).
      const uint32_t count = images[i].count;
      std::fill_n(image_infos.begin() + static_cast<std::ptrdiff_t>(first), count,
                  VkDescriptorImageInfo{b.sampler, b.view, b.layout});
      auto w = structure<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      w.dstSet = set;
      w.dstBinding = images[i].binding;
      w.descriptorCount = count;
      w.descriptorType = to_vk_descriptor(images[i].kind, program.descriptor_mode());
      w.pImageInfo = &image_infos[first];
      writes.push_back(w);
      first += count;
    }
    for (size_t i = 0; i < storage.size(); ++i) {
      auto w = structure<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      w.dstSet = set;
      w.dstBinding = storage[i].binding;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      w.pBufferInfo = &r.buffers_[i];
      writes.push_back(w);
    }
    for (size_t i = 0; i < texel.size(); ++i) {
      auto w = structure<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      w.dstSet = set;
      w.dstBinding = texel[i].binding;
      w.descriptorCount = 1;
      w.descriptorType = to_vk_descriptor(texel[i].kind, program.descriptor_mode());
      w.pTexelBufferView = &r.texel_views_[i];
      writes.push_back(w);
    }
  };

  if (push) {
    write_all(VK_NULL_HANDLE);
    ctx_->functions().push_descriptor_set(cmd_, bind_point_, program.pipeline_layout(), 0, uint32_t(writes.size()),
                                          writes.data());
    ++stats_.descriptor_pushes;
    r.images_changed_ = false;
    pushed_ = &r;
  } else {
    if (!r.set_ || r.images_changed_ || !frames_->still_valid(r.set_frame_)) {
      const uint64_t frame = frames_->frame();
      PassResources::KeptSet* kept = nullptr;
      if (r.arena_ && (r.kept_for_ == 0 || r.kept_for_ == frames_->id())) {
        r.kept_for_ = frames_->id();
        r.kept_.resize(frames_->frames_in_flight());
        kept = &r.kept_[frame % r.kept_.size()];
      }
      VkDescriptorSet set = VK_NULL_HANDLE;
      if (kept && kept->set && kept->images_version == r.images_version_) {
        set = kept->set;  // as it was written
      } else {
        if (!images_bound(r, sink)) return false;
        // A kept set is written only when no command of this frame bound it (the frame that
        // last did, of the same slot, has retired); else this frame takes one of its own.
        if (kept && kept->frame != frame) {
          if (!kept->set) kept->set = r.arena_->allocate(program, sink);
          set = kept->set;
        } else {
          set = frames_->allocate_set(program.set_layout(), sink);
        }
        if (!set) return false;
        write_all(set);
        vkUpdateDescriptorSets(ctx_->device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
        ++stats_.descriptor_writes;
        if (kept && set == kept->set) kept->images_version = r.images_version_;
      }
      if (kept && set == kept->set) kept->frame = frame;
      r.set_ = set;
      r.set_frame_ = frame;
      r.images_changed_ = false;
    }
    if (r.set_ != set_ || !same_offsets || layout_changed) {
      vkCmdBindDescriptorSets(cmd_, bind_point_, program.pipeline_layout(), 0, 1, &r.set_, uint32_t(offsets.size()),
                              offsets.data());
      ++stats_.descriptor_binds;
      set_ = r.set_;
    }
  }
  if (!same_offsets) offsets_.assign(offsets.begin(), offsets.end());
  layout_ = program.pipeline_layout();
  return true;
}

}  // namespace fx::vk
