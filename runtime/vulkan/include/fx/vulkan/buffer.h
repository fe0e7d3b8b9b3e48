// fx::vk::Buffer: a VkBuffer with its own memory, persistently mapped when host-visible.
#pragma once
#include <vulkan/vulkan.h>

#include <optional>

#include "fx/vulkan/context.h"
#include "fx/vulkan/memory.h"

namespace fx::vk {

// What Buffer::create makes.
struct BufferDesc {
  VkDeviceSize size = 0;
  VkBufferUsageFlags usage = 0;
  MemoryUsage memory = MemoryUsage::upload;
  const char* debug_name = nullptr;  // shown by validation messages and debuggers
};

// Move-only owner of a buffer and its memory. Holds the VkDevice, not the Context, so the
// Context may move; it must outlive the buffer.
class Buffer {
 public:
  // Reports "vk-invalid-buffer" (size 0, no usage) or allocation failures.
  static std::optional<Buffer> create(const Context& ctx, const BufferDesc& desc, DiagnosticSink& sink);

  Buffer() = default;
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer() { reset(); }

  VkBuffer handle() const { return buffer_; }
  VkDeviceMemory memory() const { return memory_; }
  VkDeviceSize size() const { return size_; }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
  // Mapped pointer for host-visible memory, null otherwise.
  void* mapped() const { return mapped_; }
  bool host_visible() const { return mapped_ != nullptr; }
  // Whether CPU writes need no flush (host-coherent memory).
  bool coherent() const { return coherent_; }

  // Copies into the mapping and flushes it; false if not host-visible or out of range.
  bool write(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  // Invalidates the mapping and copies out; false if not host-visible or out of range.
  bool read(void* out, VkDeviceSize bytes, VkDeviceSize offset = 0) const;
  // Makes CPU writes visible to the device (no-op for coherent memory).
  void flush(VkDeviceSize offset = 0, VkDeviceSize bytes = VK_WHOLE_SIZE) const;
  // Makes device writes visible to the CPU (no-op for coherent memory).
  void invalidate(VkDeviceSize offset = 0, VkDeviceSize bytes = VK_WHOLE_SIZE) const;

  // Destroys the buffer now (the device must be done with it).
  void reset();

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  bool coherent_ = true;
  VkDeviceSize atom_ = 1;  // nonCoherentAtomSize
};

}  // namespace fx::vk
