// One-shot command submission: record, submit to the context's queue, wait on a fence.
// For uploads, readbacks and tests; frame rendering belongs to the application.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <optional>

#include "fx/vulkan/context.h"

namespace fx::vk {

// Records commands with `record`.
using RecordCommands = std::function<void(VkCommandBuffer)>;

// A reusable command pool + buffer + fence for repeated blocking submissions. Not
// thread-safe; the queue must not be used by another thread during run().
class OneShotCommands {
 public:
  // Reports "vk-call-failed" when pool, buffer or fence creation fails.
  static std::optional<OneShotCommands> create(const Context& ctx, DiagnosticSink& sink);

  OneShotCommands() = default;
  OneShotCommands(OneShotCommands&& other) noexcept;
  OneShotCommands& operator=(OneShotCommands&& other) noexcept;
  OneShotCommands(const OneShotCommands&) = delete;
  OneShotCommands& operator=(const OneShotCommands&) = delete;
  ~OneShotCommands() { reset(); }

  // Records, submits and waits until the device finishes it or is lost (no deadline: a slow
  // device is not an error, and a pending submission cannot be abandoned).
  bool run(const RecordCommands& record, DiagnosticSink& sink);

  void reset();

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
};

// Creates a temporary OneShotCommands and runs `record` once.
bool submit_and_wait(const Context& ctx, const RecordCommands& record, DiagnosticSink& sink);

}  // namespace fx::vk
