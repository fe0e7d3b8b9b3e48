// fx::CapsRequirement: one thing a technique needs from a device ("ps_1_4", "dot3",
// "textures>=4", "ext:VK_EXT_extended_dynamic_state3"), and the check that says why not.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/select/device_caps.h"

namespace fx {

struct CapsRequirement {
  enum class Kind : uint8_t {
    shader_profile,    // name = canonical profile
    feature,           // name = caps_feature_table() row
    limit,             // name = caps_limit_table() row, minimum = least value needed
    vulkan_feature,    // name = VkPhysicalDevice*Features member
    vulkan_extension,  // name = extension
    format,            // name = format, minimum unused; usage in `usage`
  };
  Kind kind = Kind::feature;
  std::string name;
  uint32_t minimum = 0;
  std::string usage;  // for formats: sampled, filter_linear, color_attachment, blend, depth_stencil, storage

  // Constructors for the common cases.
  static CapsRequirement profile(std::string_view p);
  static CapsRequirement feature(std::string_view f);
  static CapsRequirement limit(std::string_view l, uint32_t minimum);
  // The requirement as it is written in a `Requires` annotation.
  std::string spelling() const;
  friend bool operator==(const CapsRequirement&, const CapsRequirement&) = default;
};

// Parses one token of a `Requires` list:
//   ps_2_0 | vs.1.1 | glsl_450         shader profile
//   dot3 | cube_maps | ...             CapsFeatures member
//   textures>=4 | render_targets>=2    CapsLimits member ("textures" = simultaneous_textures)
//   vk:samplerAnisotropy               Vulkan feature
//   ext:VK_KHR_push_descriptor         Vulkan device extension
//   format:R16G16B16A16_SFLOAT[/usage] Vulkan format (usage defaults to sampled)
// On failure returns nullopt and sets *error to a sentence naming the problem.
std::optional<CapsRequirement> parse_caps_requirement(std::string_view token, std::string* error);
// Parses a whitespace/comma separated list; bad tokens are appended to *errors.
std::vector<CapsRequirement> parse_caps_requirements(std::string_view list, std::vector<std::string>* errors);

// Why `caps` cannot meet `req` ("ps_2_0 not supported on dx7"), or nullopt when it can.
std::optional<std::string> unmet_reason(const DeviceCaps& caps, const CapsRequirement& req);

}  // namespace fx
