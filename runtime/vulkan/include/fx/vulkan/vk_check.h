// Private: small helpers every Vulkan source file uses.
#pragma once
#include <string>

#include "fx/vulkan/context.h"

namespace fx::vk {

// A zeroed Vulkan structure with its sType set (brace-init with one member trips
// -Wmissing-field-initializers).
template <class T>
T structure(VkStructureType type) {
  T value{};
  value.sType = type;
  return value;
}

// Reports "vk-call-failed" ("<what> failed: VK_ERROR_...") and returns false on failure.
inline bool check(VkResult result, DiagnosticSink& sink, const char* what) {
  if (result >= VK_SUCCESS) return true;
  sink.error("vk-call-failed", {}, std::string(what) + " failed: " + to_string(result));
  return false;
}

}  // namespace fx::vk
