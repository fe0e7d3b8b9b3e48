// GpuTimer: timestamp queries around each pass of a frame, read back when the frame's slot
// comes round again (no stall).
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

class GpuTimer {
 public:
  static constexpr uint32_t kMaxMarks = 64;
  // `period_ns` 0: the queue has no timestamps and every call does nothing.
  GpuTimer(VkDevice device, uint32_t slots, float period_ns);
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  // After the slot's fence: the intervals of its last frame between marks 0-1, 2-3, ...
  // (milliseconds), then resets the slot's queries (outside any rendering).
  std::vector<double> begin(VkCommandBuffer cmd, uint32_t slot);
  // A timestamp after everything recorded so far (inside rendering too).
  void mark(VkCommandBuffer cmd);
  bool available() const { return period_ns_ > 0; }

 private:
  VkDevice device_;
  float period_ns_;
  std::vector<VkQueryPool> pools_;
  std::vector<uint32_t> written_;  // marks written per slot
  uint32_t slot_ = 0;
};
