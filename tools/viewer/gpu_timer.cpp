// GpuTimer: one query pool per frame in flight.
#include "gpu_timer.h"
#include "vk_struct.h"

GpuTimer::GpuTimer(VkDevice device, uint32_t slots, float period_ns) : device_(device), period_ns_(period_ns) {
  if (!available()) return;
  pools_.resize(slots, VK_NULL_HANDLE);
  written_.resize(slots, 0);
  for (VkQueryPool& pool : pools_) {
    VkQueryPoolCreateInfo info = vk_struct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = kMaxMarks;
    vkCreateQueryPool(device_, &info, nullptr, &pool);
  }
}

GpuTimer::~GpuTimer() {
  for (VkQueryPool pool : pools_) vkDestroyQueryPool(device_, pool, nullptr);
}

std::vector<double> GpuTimer::begin(VkCommandBuffer cmd, uint32_t slot) {
  std::vector<double> ms;
  if (!available()) return ms;
  slot_ = slot;
  if (const uint32_t n = written_[slot]; n >= 2) {
    std::vector<uint64_t> ticks(n);
    if (vkGetQueryPoolResults(device_, pools_[slot], 0, n, n * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                              VK_QUERY_RESULT_64_BIT) == VK_SUCCESS)
      for (uint32_t i = 0; i + 1 < n; i += 2) ms.push_back(double(ticks[i + 1] - ticks[i]) * period_ns_ * 1e-6);
  }
  vkCmdResetQueryPool(cmd, pools_[slot], 0, kMaxMarks);
  written_[slot] = 0;
  return ms;
}

void GpuTimer::mark(VkCommandBuffer cmd) {
  if (!available() || written_[slot_] >= kMaxMarks) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pools_[slot_], written_[slot_]++);
}
