// Buffer creation, mapping and host access.
#include "fx/vulkan/buffer.h"

#include <cstring>
#include <utility>

#include "fx/vulkan/vk_check.h"

namespace fx::vk {

std::optional<Buffer> Buffer::create(const Context& ctx, const BufferDesc& desc, DiagnosticSink& sink) {
  if (desc.size == 0 || desc.usage == 0) {
    sink.error("vk-invalid-buffer", {}, "a buffer needs a non-zero size and usage");
    return std::nullopt;
  }
  Buffer b;
  b.device_ = ctx.device();
  b.size_ = desc.size;
  b.atom_ = ctx.info().limits.nonCoherentAtomSize ? ctx.info().limits.nonCoherentAtomSize : 1;
  auto info = structure<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = desc.size;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (!check(vkCreateBuffer(b.device_, &info, nullptr, &b.buffer_), sink, "vkCreateBuffer")) return std::nullopt;
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(b.device_, b.buffer_, &req);
  auto allocation = allocate_memory(ctx, req, desc.memory, sink);
  if (!allocation) return std::nullopt;
  b.memory_ = allocation->memory;
  b.coherent_ = allocation->flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  if (!check(vkBindBufferMemory(b.device_, b.buffer_, b.memory_, 0), sink, "vkBindBufferMemory")) return std::nullopt;
  if (allocation->flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    if (!check(vkMapMemory(b.device_, b.memory_, 0, VK_WHOLE_SIZE, 0, &b.mapped_), sink, "vkMapMemory"))
      return std::nullopt;
  }
  if (desc.debug_name) ctx.set_object_name(VK_OBJECT_TYPE_BUFFER, uint64_t(b.buffer_), desc.debug_name);
  return b;
}

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this == &other) return *this;
  reset();
  device_ = std::exchange(other.device_, VK_NULL_HANDLE);
  buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
  memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
  size_ = std::exchange(other.size_, 0);
  mapped_ = std::exchange(other.mapped_, nullptr);
  coherent_ = other.coherent_;
  atom_ = other.atom_;
  return *this;
}

void Buffer::reset() {
  if (device_) {
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);  // also unmaps
  }
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
  size_ = 0;
}

bool Buffer::write(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
  if (!mapped_ || offset > size_ || bytes > size_ - offset) return false;
  std::memcpy(static_cast<uint8_t*>(mapped_) + offset, data, size_t(bytes));
  flush(offset, bytes);
  return true;
}

bool Buffer::read(void* out, VkDeviceSize bytes, VkDeviceSize offset) const {
  if (!mapped_ || offset > size_ || bytes > size_ - offset) return false;
  invalidate(offset, bytes);
  std::memcpy(out, static_cast<const uint8_t*>(mapped_) + offset, size_t(bytes));
  return true;
}

namespace {
// Non-coherent ranges must be aligned to the atom size; widen to the whole mapping if needed.
VkMappedMemoryRange aligned_range(VkDeviceMemory memory, VkDeviceSize offset, VkDeviceSize bytes, VkDeviceSize atom,
                                  VkDeviceSize size) {
  auto range = structure<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
  range.memory = memory;
  range.offset = offset / atom * atom;
  if (bytes == VK_WHOLE_SIZE || offset + bytes >= size) {
    range.size = VK_WHOLE_SIZE;
  } else {
    VkDeviceSize end = (offset + bytes + atom - 1) / atom * atom;
    range.size = end >= size ? VK_WHOLE_SIZE : end - range.offset;
  }
  return range;
}
}  // namespace

void Buffer::flush(VkDeviceSize offset, VkDeviceSize bytes) const {
  if (!mapped_ || coherent_) return;
  VkMappedMemoryRange range = aligned_range(memory_, offset, bytes, atom_, size_);
  vkFlushMappedMemoryRanges(device_, 1, &range);
}

void Buffer::invalidate(VkDeviceSize offset, VkDeviceSize bytes) const {
  if (!mapped_ || coherent_) return;
  VkMappedMemoryRange range = aligned_range(memory_, offset, bytes, atom_, size_);
  vkInvalidateMappedMemoryRanges(device_, 1, &range);
}

}  // namespace fx::vk
