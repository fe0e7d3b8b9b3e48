// fxkit::Device: fxkit on one Vulkan device. An engine makes it from its own handles, a tool
// headlessly; effects are loaded from it, and begin_frame() once per frame does the
// per-frame bookkeeping (uniform and descriptor memory of the frame slot, reloads swapped in).
// See docs/embedding.md and samples/minimal.
#pragma once
#include <vulkan/vulkan.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fxkit/effect.h"
#include "fxkit/message.h"
#include "fxkit/target.h"

namespace fxkit {

// The application's Vulkan objects. fxkit borrows them: it destroys none, and submits to
// `queue` only from Device::submit (Vulkan queues need external synchronisation).
struct VulkanHandles {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;  // a graphics queue
  uint32_t queue_family = 0;
  // What the device was created with (extensions, pEnabledFeatures and the feature structs
  // chained on pNext): fxkit uses only what is enabled. Null: everything the physical
  // device supports is assumed enabled. Read during create() only.
  const VkDeviceCreateInfo* created_with = nullptr;
};

// For Device::headless (tools, tests, CI): fxkit makes its own instance and device.
struct HeadlessOptions {
  bool validation = false;  // VK_LAYER_KHRONOS_validation; messages become vk-validation errors
  std::string device{};     // index or name substring; "": FXKIT_DEVICE, else the best device
};

struct DeviceOptions {
  Target target{};                          // required: formats, vertex layout, conventions
  std::vector<std::string> include_dirs{};  // searched after the including file's folder
  std::vector<std::string> defines{};       // "NAME" or "NAME=VALUE", as -D
  bool watch = true;                        // reload effects when they or their includes change
  uint32_t frames_in_flight = 2;            // frames the GPU may still be reading
  // Per frame in flight: uniform data fxkit writes (host-visible memory) and descriptor
  // sets it allocates. Running out is a vk-uniform-ring-full / vk-descriptor-pool-full error.
  uint32_t uniform_bytes_per_frame = 4u << 20;
  uint32_t descriptor_sets_per_frame = 1024;
  // Pass states the device can set dynamically (extended dynamic state) are set per draw, so
  // one pipeline serves many state combinations; false bakes every state into its pipeline
  // (more pipelines, as hand-written Vulkan usually does).
  bool dynamic_state = true;
  std::string cache_dir{};       // SPIR-V cache on disk; "": in memory only
  uint32_t compile_threads = 0;  // threads compiling an effect's shaders; 0: one per core
  // glslang runs in fxkit-compile-worker processes that stay alive (one per compile thread),
  // so a compiler crash or hang on an edited effect fails that reload with a
  // `compiler-crashed` error instead of taking the application down. false compiles in this
  // process: no extra processes, but glslang's crashes are the application's.
  // docs/shader-compilation.md weighs the two.
  bool compile_in_workers = true;
  // The worker program; "": $FXKIT_COMPILE_WORKER, then beside the running program (where
  // the fxkit tool installs it), then fxkit's build tree. Not found: in-process, with a
  // warning in Device::warnings().
  std::string compile_worker{};
};

// What begin_frame() swapped in or could not.
struct Reload {
  enum class Kind : uint8_t { reloaded, failed, deleted } kind = Kind::reloaded;
  std::string file{};
  std::vector<Message> messages{};              // failed: why (the last good version stays live)
  std::vector<std::string> defaults_changed{};  // parameters that took an edited default
  std::string technique{};                      // the technique selection chose after the reload
  // One line per event, then the messages: "reloaded effects/lit.fx (technique lit)".
  std::string str() const;
};

namespace detail {
struct DeviceState;
}

class Device {
 public:
  // nullptr with `errors` when the target is incomplete or the device lacks dynamic
  // rendering (Vulkan 1.3 or VK_KHR_dynamic_rendering).
  static std::unique_ptr<Device> create(const VulkanHandles& vulkan, const DeviceOptions& options,
                                        std::vector<Message>& errors);
  static std::unique_ptr<Device> headless(const DeviceOptions& options, const HeadlessOptions& headless,
                                          std::vector<Message>& errors);
  // Waits for the device to be idle, then releases every effect (handles become inert).
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  // Loads an effect (synchronously: parse, compile, pipelines) and watches its files. A
  // failed load still returns an Effect (ok() false, messages() say why) that comes alive
  // when an edit fixes the file. Loading a path again returns the same effect.
  Effect load(const std::string& path);

  // Once per frame, before recording it, after waiting for the fence of the frame that
  // used this frame slot (frames_in_flight earlier): recycles that slot's uniform and
  // descriptor memory, releases effect versions no frame uses, and swaps in reloads.
  std::vector<Reload> begin_frame();
  uint64_t frame() const;
  // Uniform bytes written into frame memory since the device was made (profiling).
  uint64_t uniform_bytes_written() const;

  // Records `record` into a one-time command buffer, submits it to the queue and waits:
  // for tools, uploads and readbacks, not for the frame loop.
  bool submit(const std::function<void(VkCommandBuffer)>& record);
  // Blocks until a reload is ready for begin_frame() or `timeout` passes (tools, tests).
  bool wait_for_reload(std::chrono::milliseconds timeout);

  VkDevice vk_device() const;
  VkPhysicalDevice vk_physical_device() const;
  const Target& target() const;
  const std::string& device_name() const;
  // What create() worked around and the application may want to know (compile workers
  // that did not start: shaders compile in this process).
  const std::vector<Message>& warnings() const;
  // Errors the validation layer reported (headless with validation), as messages; cleared.
  std::vector<Message> take_validation_messages();

  detail::DeviceState& state() { return *state_; }

 private:
  explicit Device(std::unique_ptr<detail::DeviceState> state);
  std::unique_ptr<detail::DeviceState> state_;
};

}  // namespace fxkit
