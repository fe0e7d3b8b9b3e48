// Where DeviceCaps come from: a live VkPhysicalDevice, a saved `vulkaninfo --json` report,
// or one of the shipped generation profiles (dx6, dx7, dx8, dx8_1, dx9, dx9c, modern).
#pragma once
#include <vulkan/vulkan.h>

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/select/device_caps.h"

namespace fx {

// Queries a physical device. HLSL profiles are the ones glslang compiles (SM 2.0-5.0);
// shader model 1 assembly and fixed-function texture stages are not offered.
DeviceCaps caps_from_physical_device(VkPhysicalDevice device);

// Reads the Vulkan-profiles JSON that `vulkaninfo --json` writes. Missing sections are
// reported as "caps-vulkaninfo" errors; nullopt when the document has no device at all.
std::optional<DeviceCaps> caps_from_vulkaninfo_json(const nlohmann::json& report, DiagnosticSink& sink);
// Same without diagnostics.
std::optional<DeviceCaps> caps_from_vulkaninfo_json(const nlohmann::json& report);

// Names of the shipped profiles, in generation order.
std::vector<std::string> caps_profile_names();
// A shipped profile by name (case-insensitive); reports "unknown-caps-profile" with a
// did-you-mean when there is none.
std::optional<DeviceCaps> load_caps_profile(std::string_view name, DiagnosticSink& sink);

}  // namespace fx
