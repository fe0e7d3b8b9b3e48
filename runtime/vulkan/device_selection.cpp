// Device ranking and the FXKIT_DEVICE override.
#include "fx/vulkan/device_selection.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>

#include "fx/vulkan/context.h"

namespace fx::vk {
namespace {

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
  }
}

bool usable(const DeviceCandidate& c) { return c.has_graphics_queue && c.api_version >= VK_API_VERSION_1_3; }

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string describe(const std::vector<DeviceCandidate>& candidates) {
  if (candidates.empty()) return "no Vulkan devices were found";
  std::string out = "available devices:";
  for (size_t i = 0; i < candidates.size(); ++i) {
    const DeviceCandidate& c = candidates[i];
    out += "\n  " + std::to_string(i) + ": " + c.name + " (" + to_string(c.type) + ", Vulkan " +
           std::to_string(VK_API_VERSION_MAJOR(c.api_version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(c.api_version)) + (c.has_graphics_queue ? "" : ", no graphics queue") +
           ")";
  }
  return out;
}

// Why a forced device cannot be used, or "" if it can.
std::string unusable_reason(const DeviceCandidate& c) {
  if (!c.has_graphics_queue) return "it has no graphics queue";
  if (c.api_version < VK_API_VERSION_1_3) return "it does not support Vulkan 1.3";
  return "";
}

}  // namespace

std::optional<uint32_t> select_device(const std::vector<DeviceCandidate>& candidates, std::string_view request,
                                      DiagnosticSink& sink) {
  if (!request.empty()) {
    std::optional<uint32_t> chosen;
    uint32_t index = 0;
    auto [end, ec] = std::from_chars(request.data(), request.data() + request.size(), index);
    if (ec == std::errc() && end == request.data() + request.size()) {
      if (index < candidates.size()) chosen = index;
    } else {
      std::string needle = lower(request);
      for (uint32_t i = 0; i < candidates.size() && !chosen; ++i)
        if (lower(candidates[i].name).find(needle) != std::string::npos) chosen = i;
    }
    if (!chosen) {
      sink.error("vk-device-not-found", {},
                 "no Vulkan device matches '" + std::string(request) + "'; " + describe(candidates));
      return std::nullopt;
    }
    std::string why = unusable_reason(candidates[*chosen]);
    if (!why.empty()) {
      sink.error("vk-no-suitable-device", {}, "device '" + candidates[*chosen].name + "' was requested but " + why);
      return std::nullopt;
    }
    return chosen;
  }
  std::optional<uint32_t> best;
  for (uint32_t i = 0; i < candidates.size(); ++i) {
    if (!usable(candidates[i])) continue;
    if (!best || type_rank(candidates[i].type) > type_rank(candidates[*best].type)) best = i;
  }
  if (!best)
    sink.error("vk-no-suitable-device", {},
               "no device supports Vulkan 1.3 with a graphics queue; " + describe(candidates));
  return best;
}

std::string device_request(std::string_view option) {
  if (!option.empty()) return std::string(option);
  const char* env = std::getenv(kDeviceEnvVar);
  return env ? std::string(env) : std::string();
}

}  // namespace fx::vk
