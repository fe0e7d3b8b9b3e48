// fx::DeviceCaps: what a device can do, in the vocabulary effect techniques are written in
// (D3D shader profiles, texture-stage operations, limits), plus the Vulkan facts behind it
// when the caps were read from a real device. Techniques are validated against this.
#pragma once
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fx/diagnostic.h"

namespace fx {

// The hardware generation a caps set describes; D3D generations follow the seed's history.
enum class CapsGeneration : uint8_t { dx6, dx7, dx8, dx9, dx10, dx11, vulkan };
// Stable lower-case name ("dx7", "vulkan").
const char* to_string(CapsGeneration g);
// Parses a name written by to_string; nullopt when unknown.
std::optional<CapsGeneration> parse_caps_generation(std::string_view name);

// Boolean capabilities; each row of caps_feature_table() names one member.
struct CapsFeatures {
  bool dot3 = false;      // D3DTOP_DOTPRODUCT3 texture-stage operation
  bool subtract = false;  // D3DTOP_SUBTRACT (emboss bump mapping)
  bool cube_maps = false;
  bool volume_textures = false;
  bool float_textures = false;  // sampled 16/32-bit float RGBA
  bool anisotropic_filtering = false;
  bool fixed_function_stages = false;  // D3D texture stages (ColorOp/AlphaOp...)
  bool alpha_test = false;             // AlphaTestEnable without shader emulation
  bool separate_alpha_blend = false;
  bool two_sided_stencil = false;
  friend bool operator==(const CapsFeatures&, const CapsFeatures&) = default;
};

// Numeric limits; each row of caps_limit_table() names one member.
struct CapsLimits {
  uint32_t simultaneous_textures = 0;  // textures one pass may sample at once
  uint32_t samplers = 0;
  uint32_t uniform_bytes = 0;   // largest constant/uniform block
  uint32_t interpolators = 0;   // vec4 varyings from vertex to pixel stage
  uint32_t texture_size = 0;    // largest 2D texture edge
  uint32_t render_targets = 0;  // simultaneous colour attachments (MRT count)
  friend bool operator==(const CapsLimits&, const CapsLimits&) = default;
};

// What a device can do with one Vulkan format (optimal tiling).
struct FormatSupport {
  std::string format;  // without the VK_FORMAT_ prefix, e.g. "R16G16B16A16_SFLOAT"
  bool sampled = false, filter_linear = false, color_attachment = false, blend = false, depth_stencil = false,
       storage = false;
  friend bool operator==(const FormatSupport&, const FormatSupport&) = default;
};

// Facts read from a Vulkan physical device (empty when the caps come from a D3D profile).
struct VulkanCaps {
  bool present = false;
  uint32_t api_version = 0;             // VK_MAKE_API_VERSION encoding
  std::string device_type;              // "discrete_gpu", "integrated_gpu", "cpu", ...
  std::vector<std::string> features;    // enabled-capable feature names, sorted
  std::vector<std::string> extensions;  // device extension names, sorted
  std::vector<FormatSupport> formats;   // the formats effects use, sorted by name
  friend bool operator==(const VulkanCaps&, const VulkanCaps&) = default;
};

// Everything technique validation asks of a device.
struct DeviceCaps {
  std::string name;         // "dx7" for shipped profiles, the device name for real devices
  std::string description;  // what hardware this stands for
  CapsGeneration generation = CapsGeneration::vulkan;
  std::vector<std::string> shader_profiles;  // canonical names ("ps_1_4", "glsl_450"), sorted
  CapsLimits limits;
  CapsFeatures features;
  VulkanCaps vulkan;
  friend bool operator==(const DeviceCaps&, const DeviceCaps&) = default;
};

// One named boolean capability (shared by JSON, requirements and docs).
struct CapsFeatureRow {
  const char* name;
  bool CapsFeatures::*member;
};
// One named numeric limit.
struct CapsLimitRow {
  const char* name;
  uint32_t CapsLimits::*member;
};
std::span<const CapsFeatureRow> caps_feature_table();
std::span<const CapsLimitRow> caps_limit_table();

// Canonical profile spelling: lower case, '.' -> '_' ("PS.1.4" -> "ps_1_4").
std::string canonical_shader_profile(std::string_view profile);
// True when the device can run code compiled for `shader_profile` (any spelling).
bool supports(const DeviceCaps& caps, std::string_view shader_profile);
// Support for a Vulkan format (name with or without VK_FORMAT_), or nullptr if unknown.
const FormatSupport* find_format(const DeviceCaps& caps, std::string_view format);

// Sorts and de-duplicates the list fields so equal caps compare equal.
void normalize(DeviceCaps& caps);

// nlohmann-json conversion (ADL). from_json never throws: fields of the wrong type keep
// their defaults; use caps_from_json to hear about them.
void to_json(nlohmann::json& j, const DeviceCaps& caps);
void from_json(const nlohmann::json& j, DeviceCaps& caps);
// Reads caps, reporting unknown keys and wrongly typed fields as "caps-json" diagnostics.
std::optional<DeviceCaps> caps_from_json(const nlohmann::json& j, DiagnosticSink& sink);

}  // namespace fx
