// Choosing a physical device: a pure function over candidate descriptions, so the policy
// is testable without the GPUs it ranks.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/diagnostic.h"

namespace fx::vk {

// What selection needs to know about one physical device.
struct DeviceCandidate {
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t api_version = 0;
  bool has_graphics_queue = false;
};

// Environment variable that forces a device: an index or a name substring.
inline constexpr const char* kDeviceEnvVar = "FXKIT_DEVICE";

// Picks a device index. `request` (index or case-insensitive name substring) wins if set;
// otherwise ranks discrete > integrated > virtual > CPU > other among devices with
// Vulkan >= 1.3 and a graphics queue, keeping enumeration order on ties. Reports
// "vk-device-not-found" or "vk-no-suitable-device" (listing the devices) on failure.
std::optional<uint32_t> select_device(const std::vector<DeviceCandidate>& candidates, std::string_view request,
                                      DiagnosticSink& sink);

// The request in effect: `option` if non-empty, else $FXKIT_DEVICE, else "".
std::string device_request(std::string_view option);

}  // namespace fx::vk
