// Recording validation messages: counted always, stored up to a bound.
#include "validation_log.h"

#include "fx/vulkan/vk_check.h"

namespace fx::vk {

void ValidationLog::record(ValidationMessage message) {
  if (listener_) listener_(message);
  std::lock_guard lock(mutex_);
  if (message.severity == Severity::error) ++errors_;
  if (message.severity == Severity::warning) ++warnings_;
  if (messages_.size() < kMaxStored) messages_.push_back(std::move(message));
}

std::vector<ValidationMessage> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

std::vector<ValidationMessage> ValidationLog::take() {
  std::lock_guard lock(mutex_);
  std::vector<ValidationMessage> out = std::move(messages_);
  messages_.clear();
  errors_ = warnings_ = 0;
  return out;
}

size_t ValidationLog::error_count() const {
  std::lock_guard lock(mutex_);
  return errors_;
}

size_t ValidationLog::warning_count() const {
  std::lock_guard lock(mutex_);
  return warnings_;
}

void ValidationLog::clear() {
  std::lock_guard lock(mutex_);
  messages_.clear();
  errors_ = warnings_ = 0;
}

VKAPI_ATTR VkBool32 VKAPI_CALL record_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                         VkDebugUtilsMessageTypeFlagsEXT types,
                                                         const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                         void* user_data) {
  auto* log = static_cast<ValidationLog*>(user_data);
  if (!log || !data) return VK_FALSE;
  ValidationMessage message;
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) message.severity = Severity::error;
  else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) message.severity = Severity::warning;
  else message.severity = Severity::note;
  message.id_number = data->messageIdNumber;
  if (data->pMessageIdName) message.id_name = data->pMessageIdName;
  if (data->pMessage) message.text = data->pMessage;
  log->record(std::move(message));
  return VK_FALSE;  // never abort the call: the application decides what an error means
}

VkDebugUtilsMessengerCreateInfoEXT messenger_create_info(ValidationLog* log, bool include_info) {
  VkDebugUtilsMessengerCreateInfoEXT info =
      structure<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  if (include_info) info.messageSeverity |= VK_DEBUG_UTILS_MESSAGE_SEVERITY_INFO_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = record_validation_message;
  info.pUserData = log;
  return info;
}

}  // namespace fx::vk
