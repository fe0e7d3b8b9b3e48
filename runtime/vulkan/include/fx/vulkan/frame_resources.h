// fx::vk::FrameResources: per-frame-in-flight transient memory: a uniform ring buffer
// (host-visible, persistently mapped) and a descriptor pool, both recycled when the frame
// that used them has retired.
#pragma once
#include <vulkan/vulkan.h>

#include <optional>
#include <vector>

#include "fx/vulkan/buffer.h"
#include "fx/vulkan/context.h"

namespace fx::vk {

// Sizes of what one frame may use.
struct FrameResourcesDesc {
  uint32_t frames_in_flight = 2;
  VkDeviceSize uniform_bytes_per_frame = 256 * 1024;
  uint32_t sets_per_frame = 256;
  uint32_t descriptors_per_type = 1024;  // per descriptor type, per frame
};

// A slice of the ring: where uniform data was written.
struct UniformAllocation {
  VkBuffer buffer = VK_NULL_HANDLE;
  uint32_t offset = 0;  // aligned to minUniformBufferOffsetAlignment
  void* mapped = nullptr;
};

class FrameResources {
 public:
  // Reports allocation failures.
  static std::optional<FrameResources> create(const Context& ctx, const FrameResourcesDesc& desc, DiagnosticSink& sink);

  FrameResources() = default;
  FrameResources(FrameResources&& other) noexcept { *this = std::move(other); }
  FrameResources& operator=(FrameResources&& other) noexcept;
  FrameResources(const FrameResources&) = delete;
  FrameResources& operator=(const FrameResources&) = delete;
  ~FrameResources();

  // Starts the next frame. Call once the GPU has finished the frame that is
  // `frames_in_flight` older (its fence waited): its ring slice and pool are reused.
  void begin_frame();
  // Frame counter (0 before the first begin_frame()).
  uint64_t frame() const { return frame_; }
  uint32_t frames_in_flight() const { return frames_in_flight_; }
  // Unique in the process per create() (a moved-into FrameResources takes the source's):
  // what kept descriptor sets are written for.
  uint64_t id() const { return id_; }
  // Whether data written (or a set allocated) in frame `written` may be used by the frame
  // being recorded: only this frame's. An earlier frame's data is still intact, but its slot
  // is recycled once that frame's fence is waited, while this frame may still be reading it.
  bool still_valid(uint64_t written) const { return written != 0 && written == frame_; }

  // Copies `bytes` into this frame's ring slice. "vk-uniform-ring-full" when the slice has
  // no room (raise FrameResourcesDesc::uniform_bytes_per_frame).
  std::optional<UniformAllocation> upload_uniform(const void* data, uint32_t bytes, DiagnosticSink& sink);
  // Reserves `bytes` of this frame's ring slice for the caller to fill through `mapped`
  // (then flush_uniform): data packed straight into the ring, no staging copy. Inline: it
  // runs once per uniform block and draw.
  std::optional<UniformAllocation> reserve_uniform(uint32_t bytes, DiagnosticSink& sink) {
    const VkDeviceSize start = (head_ + alignment_ - 1) & ~(alignment_ - 1);  // a power of two
    if (start + bytes > slice_) return ring_full(sink);
    const VkDeviceSize offset = slice_start_ + start;
    head_ = start + bytes;
    bytes_uploaded_ += bytes;
    return UniformAllocation{ring_.handle(), uint32_t(offset), static_cast<uint8_t*>(ring_.mapped()) + offset};
  }
  // Makes what the caller wrote into a reservation visible to the device (no-op for
  // coherent memory).
  void flush_uniform(const UniformAllocation& a, uint32_t bytes) const {
    if (!ring_coherent_) ring_.flush(a.offset, bytes);
  }
  // A descriptor set from this frame's pool; null and "vk-descriptor-pool-full" when empty.
  VkDescriptorSet allocate_set(VkDescriptorSetLayout layout, DiagnosticSink& sink);

  VkBuffer ring_buffer() const { return ring_.handle(); }
  uint64_t uniform_bytes_uploaded() const { return bytes_uploaded_; }

 private:
  std::optional<UniformAllocation> ring_full(DiagnosticSink& sink) const;

  // What reserve_uniform reads, once per block and draw, first: in one cache line.
  uint64_t frame_ = 0;
  VkDeviceSize head_ = 0;         // within the current slice
  VkDeviceSize slice_start_ = 0;  // ring offset of the current frame's slice
  VkDeviceSize slice_ = 0, alignment_ = 256;
  uint64_t bytes_uploaded_ = 0;
  bool ring_coherent_ = true;
  Buffer ring_;
  const Context* ctx_ = nullptr;
  std::vector<VkDescriptorPool> pools_;
  uint64_t id_ = 0;
  uint32_t frames_in_flight_ = 0;
};

}  // namespace fx::vk
