// Private: the store behind Context's validation messages, and the debug-utils callback
// that fills it. The callback may run on any thread the application records or submits on.
#pragma once
#include <functional>
#include <mutex>
#include <vector>

#include "fx/vulkan/context.h"

namespace fx::vk {

class ValidationLog {
 public:
  explicit ValidationLog(std::function<void(const ValidationMessage&)> listener = {})
      : listener_(std::move(listener)) {}
  void record(ValidationMessage message);
  std::vector<ValidationMessage> messages() const;
  std::vector<ValidationMessage> take();
  size_t error_count() const;
  size_t warning_count() const;
  void clear();

  // Keeps memory bounded when a broken loop reports the same error every frame.
  static constexpr size_t kMaxStored = 4096;

 private:
  std::function<void(const ValidationMessage&)> listener_;
  mutable std::mutex mutex_;
  std::vector<ValidationMessage> messages_;
  size_t errors_ = 0, warnings_ = 0;
};

// PFN_vkDebugUtilsMessengerCallbackEXT; user data is a ValidationLog*.
VKAPI_ATTR VkBool32 VKAPI_CALL record_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                         VkDebugUtilsMessageTypeFlagsEXT types,
                                                         const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                         void* user_data);

// Create info for a messenger that records warnings and errors (and info if asked).
VkDebugUtilsMessengerCreateInfoEXT messenger_create_info(ValidationLog* log, bool include_info);

}  // namespace fx::vk
