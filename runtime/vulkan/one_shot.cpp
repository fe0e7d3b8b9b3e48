// Blocking submissions through a transient command pool.
#include "fx/vulkan/one_shot.h"

#include <utility>

#include "fx/vulkan/vk_check.h"

namespace fx::vk {

std::optional<OneShotCommands> OneShotCommands::create(const Context& ctx, DiagnosticSink& sink) {
  OneShotCommands c;
  c.device_ = ctx.device();
  c.queue_ = ctx.queue();
  auto pool = structure<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = ctx.queue_family();
  if (!check(vkCreateCommandPool(c.device_, &pool, nullptr, &c.pool_), sink, "vkCreateCommandPool"))
    return std::nullopt;
  auto alloc = structure<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  alloc.commandPool = c.pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  if (!check(vkAllocateCommandBuffers(c.device_, &alloc, &c.cmd_), sink, "vkAllocateCommandBuffers"))
    return std::nullopt;
  auto fence = structure<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  if (!check(vkCreateFence(c.device_, &fence, nullptr, &c.fence_), sink, "vkCreateFence")) return std::nullopt;
  return c;
}

OneShotCommands::OneShotCommands(OneShotCommands&& other) noexcept { *this = std::move(other); }

OneShotCommands& OneShotCommands::operator=(OneShotCommands&& other) noexcept {
  if (this == &other) return *this;
  reset();
  device_ = std::exchange(other.device_, VK_NULL_HANDLE);
  queue_ = std::exchange(other.queue_, VK_NULL_HANDLE);
  pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
  cmd_ = std::exchange(other.cmd_, VK_NULL_HANDLE);
  fence_ = std::exchange(other.fence_, VK_NULL_HANDLE);
  return *this;
}

void OneShotCommands::reset() {
  if (device_) {
    if (fence_) vkDestroyFence(device_, fence_, nullptr);
    if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);  // frees cmd_
  }
  fence_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  cmd_ = VK_NULL_HANDLE;
}

bool OneShotCommands::run(const RecordCommands& record, DiagnosticSink& sink) {
  if (!cmd_) {
    sink.error("vk-invalid-submission", {}, "OneShotCommands used after reset or move");
    return false;
  }
  if (!check(vkResetCommandBuffer(cmd_, 0), sink, "vkResetCommandBuffer")) return false;
  auto begin = structure<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (!check(vkBeginCommandBuffer(cmd_, &begin), sink, "vkBeginCommandBuffer")) return false;
  if (record) record(cmd_);
  if (!check(vkEndCommandBuffer(cmd_), sink, "vkEndCommandBuffer")) return false;
  auto submit = structure<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd_;
  if (!check(vkQueueSubmit(queue_, 1, &submit, fence_), sink, "vkQueueSubmit")) return false;
  // No deadline: a slow device (a CPU driver on a loaded machine) finishes late, and a hung
  // one is lost (VK_ERROR_DEVICE_LOST, reported below); a timeout could not abandon the
  // submission anyway, since its pool and fence stay in use until the device is done.
  VkResult waited = vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
  if (!check(waited, sink, "vkWaitForFences")) return false;
  return check(vkResetFences(device_, 1, &fence_), sink, "vkResetFences");
}

bool submit_and_wait(const Context& ctx, const RecordCommands& record, DiagnosticSink& sink) {
  auto commands = OneShotCommands::create(ctx, sink);
  return commands && commands->run(record, sink);
}

}  // namespace fx::vk
