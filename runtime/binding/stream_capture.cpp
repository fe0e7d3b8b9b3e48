// StreamCapture: a stream-output pass's buffers, its capture and the draw of what it captured.
#include "fx/binding/stream_capture.h"

#include <algorithm>

#include "fx/vulkan/barrier.h"
#include "fx/vulkan/vk_check.h"

namespace fx::vk {
namespace {

VkFormat attribute_format(const CapturedOutput& out) {
  static constexpr VkFormat kFloat[] = {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32B32_SFLOAT,
                                        VK_FORMAT_R32G32B32A32_SFLOAT};
  static constexpr VkFormat kInt[] = {VK_FORMAT_R32_SINT, VK_FORMAT_R32G32_SINT, VK_FORMAT_R32G32B32_SINT,
                                      VK_FORMAT_R32G32B32A32_SINT};
  static constexpr VkFormat kUint[] = {VK_FORMAT_R32_UINT, VK_FORMAT_R32G32_UINT, VK_FORMAT_R32G32B32_UINT,
                                       VK_FORMAT_R32G32B32A32_UINT};
  const uint32_t i = std::clamp(out.components, 1u, 4u) - 1;
  switch (out.scalar) {
    case ScalarKind::int32: return kInt[i];
    case ScalarKind::uint32: return kUint[i];
    default: return kFloat[i];
  }
}

// What reads a capture's buffers: vertex input, indirect draws (the counter), shaders, copies.
constexpr VkPipelineStageFlags kReaders = VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT |
                                          VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                                          VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkAccessFlags kReads = VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT |
                                 VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_READ_BIT_EXT | VK_ACCESS_SHADER_READ_BIT |
                                 VK_ACCESS_TRANSFER_READ_BIT;
constexpr VkAccessFlags kWrites =
    VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT;

}  // namespace

std::optional<StreamCapture> StreamCapture::create(const Context& ctx, const StreamOutputLayout& layout,
                                                   uint32_t vertices, DiagnosticSink& sink) {
  StreamCapture c(ctx);
  c.layout_ = layout;
  for (uint32_t slot = 0; slot < kStreamOutSlots; ++slot) {
    const uint32_t stride = layout.strides[slot];
    if (stride) c.used_ = slot + 1;
    if (stride > ctx.info().transform_feedback_stride_max) {
      sink.error("vk-stream-output-stride", {},
                 "stream-output buffer " + std::to_string(slot) + " takes " + std::to_string(stride) +
                     " bytes per vertex; the device captures at most " +
                     std::to_string(ctx.info().transform_feedback_stride_max));
      return std::nullopt;
    }
  }
  for (uint32_t slot = 0; slot < c.used_; ++slot) {
    // A slot below the last one the declaration writes is bound too (bindings are a range).
    const VkDeviceSize bytes = std::max<VkDeviceSize>(VkDeviceSize(layout.strides[slot]) * vertices, 16);
    auto buffer =
        Buffer::create(ctx,
                       {bytes,
                        VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                        MemoryUsage::device_local, "fxkit stream output"},
                       sink);
    auto counter = Buffer::create(ctx,
                                  {4,
                                   VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_COUNTER_BUFFER_BIT_EXT |
                                       VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                   MemoryUsage::device_local, "fxkit stream output counter"},
                                  sink);
    if (!buffer || !counter) return std::nullopt;
    c.buffers_[slot] = std::move(*buffer);
    c.counters_[slot] = std::move(*counter);
  }
  c.vertex_layout_.bindings.push_back({0, layout.strides[0], VK_VERTEX_INPUT_RATE_VERTEX});
  for (const CapturedOutput& out : layout.outputs)
    if (out.slot == 0) c.vertex_layout_.attributes.push_back({out.semantic, attribute_format(out), out.offset, 0});
  return c;
}

void StreamCapture::begin_rendering(VkCommandBuffer cmd) const {
  // Earlier reads of these buffers (the last frame's draw of them) finish before they are written.
  memory_barrier(cmd, kReaders, 0, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT, kWrites);
  VkRenderingInfo info = structure<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  info.renderArea = {{0, 0}, {1, 1}};
  info.layerCount = 1;
  vkCmdBeginRendering(cmd, &info);
}

void StreamCapture::begin(VkCommandBuffer cmd) const {
  std::array<VkBuffer, kStreamOutSlots> handles{};
  std::array<VkDeviceSize, kStreamOutSlots> offsets{}, sizes{};
  for (uint32_t slot = 0; slot < used_; ++slot) {
    handles[slot] = buffers_[slot].handle();
    sizes[slot] = buffers_[slot].size();
  }
  const DeviceFunctions& f = ctx_->functions();
  f.bind_transform_feedback_buffers(cmd, 0, used_, handles.data(), offsets.data(), sizes.data());
  f.begin_transform_feedback(cmd, 0, 0, nullptr, nullptr);  // no counters: each buffer from its start
}

void StreamCapture::end(VkCommandBuffer cmd) const {
  std::array<VkBuffer, kStreamOutSlots> counters{};
  std::array<VkDeviceSize, kStreamOutSlots> offsets{};
  for (uint32_t slot = 0; slot < used_; ++slot) counters[slot] = counters_[slot].handle();
  ctx_->functions().end_transform_feedback(cmd, 0, used_, counters.data(), offsets.data());
  vkCmdEndRendering(cmd);
  memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT, kWrites, kReaders, kReads);
}

void StreamCapture::draw(VkCommandBuffer cmd, uint32_t binding) const {
  const VkBuffer vertices = buffers_[0].handle();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, binding, 1, &vertices, &offset);
  ctx_->functions().draw_indirect_byte_count(cmd, 1, 0, counters_[0].handle(), 0, 0, layout_.strides[0]);
}

StreamOutputBuffer StreamCapture::buffer(uint32_t slot) const {
  if (slot >= used_) return {};
  return {buffers_[slot].handle(), counters_[slot].handle(), buffers_[slot].size(), layout_.strides[slot]};
}

}  // namespace fx::vk
