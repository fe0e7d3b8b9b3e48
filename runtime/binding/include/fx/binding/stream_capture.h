// fx::vk::StreamCapture: the output buffers of one stream-output pass (ConstructGSWithSO)
// with their byte counters, and the commands that capture into them (VK_EXT_transform_feedback)
// and draw what they hold (Direct3D's DrawAuto: vkCmdDrawIndirectByteCountEXT).
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <optional>

#include "fx/compile/stream_output.h"
#include "fx/vulkan/app_vertex_layout.h"
#include "fx/vulkan/buffer.h"
#include "fx/vulkan/context.h"

namespace fx::vk {

// One output buffer of a capture: vertices and the byte count the capture wrote.
struct StreamOutputBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;   // TRANSFORM_FEEDBACK, VERTEX, STORAGE and TRANSFER_SRC usage
  VkBuffer counter = VK_NULL_HANDLE;  // 4 bytes: the bytes captured (INDIRECT, TRANSFER_SRC usage)
  VkDeviceSize size = 0;              // bytes
  uint32_t stride = 0;                // bytes per vertex
};

class StreamCapture {
 public:
  // Vertices a buffer holds when the pass has no `int StreamOutVertices` annotation.
  static constexpr uint32_t kDefaultVertices = 4096;

  // Buffers for `vertices` vertices in each slot `layout` writes. Null (with
  // "vk-stream-output-stride") when a stride passes the device's limit.
  static std::optional<StreamCapture> create(const Context& ctx, const StreamOutputLayout& layout, uint32_t vertices,
                                             DiagnosticSink& sink);

  // Records the barrier that orders the capture after earlier reads of the buffers, then
  // vkCmdBeginRendering with no attachments (inside which the capture runs).
  void begin_rendering(VkCommandBuffer cmd) const;
  // With the capturing pipeline bound: binds the buffers and begins transform feedback at
  // their starts.
  void begin(VkCommandBuffer cmd) const;
  // Ends transform feedback (the counters take the byte counts), ends the rendering, and
  // records the barrier that makes the vertices and counts visible to vertex input, indirect
  // draws, shaders and copies recorded after it.
  void end(VkCommandBuffer cmd) const;
  // Draws the vertices slot 0 captured last (its vertex buffer bound at `binding`), inside
  // rendering with a pipeline whose vertex input is vertex_layout().
  void draw(VkCommandBuffer cmd, uint32_t binding = 0) const;

  // Slot 0's vertices as a vertex layout: each captured output an attribute by its semantic.
  const VertexLayout& vertex_layout() const { return vertex_layout_; }
  StreamOutputBuffer buffer(uint32_t slot) const;

 private:
  explicit StreamCapture(const Context& ctx) : ctx_(&ctx) {}
  const Context* ctx_;
  StreamOutputLayout layout_;
  std::array<Buffer, kStreamOutSlots> buffers_, counters_;
  uint32_t used_ = 0;  // slots 0 .. used_ - 1 are bound (unused ones below the last get a small buffer)
  VertexLayout vertex_layout_;
};

}  // namespace fx::vk
