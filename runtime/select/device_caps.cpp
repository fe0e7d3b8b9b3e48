// DeviceCaps tables, profile spelling and JSON conversion.
#include "fx/select/device_caps.h"

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>

#include "fx/ascii_case.h"

namespace fx {
namespace {

constexpr std::array<const char*, 7> kGenerationNames = {"dx6", "dx7", "dx8", "dx9", "dx10", "dx11", "vulkan"};

constexpr CapsFeatureRow kFeatureRows[] = {
    {"dot3", &CapsFeatures::dot3},
    {"subtract", &CapsFeatures::subtract},
    {"cube_maps", &CapsFeatures::cube_maps},
    {"volume_textures", &CapsFeatures::volume_textures},
    {"float_textures", &CapsFeatures::float_textures},
    {"anisotropic_filtering", &CapsFeatures::anisotropic_filtering},
    {"fixed_function_stages", &CapsFeatures::fixed_function_stages},
    {"alpha_test", &CapsFeatures::alpha_test},
    {"separate_alpha_blend", &CapsFeatures::separate_alpha_blend},
    {"two_sided_stencil", &CapsFeatures::two_sided_stencil},
};

constexpr CapsLimitRow kLimitRows[] = {
    {"simultaneous_textures", &CapsLimits::simultaneous_textures},
    {"samplers", &CapsLimits::samplers},
    {"uniform_bytes", &CapsLimits::uniform_bytes},
    {"interpolators", &CapsLimits::interpolators},
    {"texture_size", &CapsLimits::texture_size},
    {"render_targets", &CapsLimits::render_targets},
};

struct FormatUsageRow {
  const char* name;
  bool FormatSupport::*member;
};
constexpr FormatUsageRow kFormatUsages[] = {
    {"sampled", &FormatSupport::sampled},
    {"filter_linear", &FormatSupport::filter_linear},
    {"color_attachment", &FormatSupport::color_attachment},
    {"blend", &FormatSupport::blend},
    {"depth_stencil", &FormatSupport::depth_stencil},
    {"storage", &FormatSupport::storage},
};

void sort_unique(std::vector<std::string>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Reads JSON without ever throwing; complaints go to an optional sink.
class CapsReader {
 public:
  explicit CapsReader(DiagnosticSink* sink) : sink_(sink) {}

  void complain(const std::string& message) {
    if (sink_) sink_->error("caps-json", {}, message);
  }

  void read_u32(const nlohmann::json& j, const char* key, uint32_t& out, const std::string& where) {
    if (!j.is_number_integer() && !j.is_number_unsigned()) {
      complain(where + "." + key + " must be a non-negative integer");
      return;
    }
    int64_t v = j.get<int64_t>();
    if (v < 0 || v > int64_t(UINT32_MAX)) {
      complain(where + "." + key + " is out of range");
      return;
    }
    out = uint32_t(v);
  }

  void read_strings(const nlohmann::json& j, std::vector<std::string>& out, const std::string& where) {
    if (!j.is_array()) {
      complain(where + " must be an array of strings");
      return;
    }
    for (const auto& s : j) {
      if (s.is_string()) out.push_back(s.get<std::string>());
      else complain(where + " holds a non-string entry");
    }
  }

  void read(const nlohmann::json& j, DeviceCaps& caps) {
    if (!j.is_object()) {
      complain("caps must be a JSON object");
      return;
    }
    for (const auto& [key, value] : j.items()) {
      if (key == "name" || key == "description") {
        if (!value.is_string()) {
          complain(key + " must be a string");
          continue;
        }
        (key == "name" ? caps.name : caps.description) = value.get<std::string>();
      } else if (key == "generation") {
        auto g = value.is_string() ? parse_caps_generation(value.get<std::string>()) : std::nullopt;
        if (g) caps.generation = *g;
        else complain("generation must be one of dx6, dx7, dx8, dx9, dx10, dx11, vulkan");
      } else if (key == "shader_profiles") {
        std::vector<std::string> raw;
        read_strings(value, raw, key);
        for (const auto& p : raw) caps.shader_profiles.push_back(canonical_shader_profile(p));
      } else if (key == "limits") {
        read_table(value, key, caps.limits);
      } else if (key == "features") {
        read_table(value, key, caps.features);
      } else if (key == "vulkan") {
        read_vulkan(value, caps.vulkan);
      } else {
        complain("unknown caps key '" + key + "'");
      }
    }
    normalize(caps);
  }

 private:
  void read_table(const nlohmann::json& j, const std::string& where, CapsLimits& limits) {
    if (!j.is_object()) return complain(where + " must be an object");
    for (const auto& item : j.items()) {  // no structured binding: clang 14 cannot capture one
      const std::string& key = item.key();
      const nlohmann::json& value = item.value();
      auto row = std::find_if(std::begin(kLimitRows), std::end(kLimitRows),
                              [&](const CapsLimitRow& r) { return key == r.name; });
      if (row == std::end(kLimitRows)) {
        complain("unknown limit '" + key + "'");
        continue;
      }
      read_u32(value, row->name, limits.*(row->member), where);
    }
  }

  void read_table(const nlohmann::json& j, const std::string& where, CapsFeatures& features) {
    if (!j.is_object()) return complain(where + " must be an object");
    for (const auto& item : j.items()) {
      const std::string& key = item.key();
      const nlohmann::json& value = item.value();
      auto row = std::find_if(std::begin(kFeatureRows), std::end(kFeatureRows),
                              [&](const CapsFeatureRow& r) { return key == r.name; });
      if (row == std::end(kFeatureRows)) {
        complain("unknown feature '" + key + "'");
        continue;
      }
      if (!value.is_boolean()) {
        complain(where + "." + key + " must be true or false");
        continue;
      }
      features.*(row->member) = value.get<bool>();
    }
  }

  void read_vulkan(const nlohmann::json& j, VulkanCaps& vk) {
    if (!j.is_object()) return complain("vulkan must be an object");
    vk.present = true;
    for (const auto& [key, value] : j.items()) {
      if (key == "api_version") {
        read_u32(value, "api_version", vk.api_version, "vulkan");
      } else if (key == "device_type") {
        if (value.is_string()) vk.device_type = value.get<std::string>();
        else complain("vulkan.device_type must be a string");
      } else if (key == "features") {
        read_strings(value, vk.features, "vulkan.features");
      } else if (key == "extensions") {
        read_strings(value, vk.extensions, "vulkan.extensions");
      } else if (key == "formats") {
        if (!value.is_object()) {
          complain("vulkan.formats must map format names to usage lists");
          continue;
        }
        for (const auto& [format, usages] : value.items()) {
          FormatSupport fs{.format = format};
          std::vector<std::string> list;
          read_strings(usages, list, "vulkan.formats." + format);
          for (const auto& u : list) {
            auto row = std::find_if(std::begin(kFormatUsages), std::end(kFormatUsages),
                                    [&](const FormatUsageRow& r) { return u == r.name; });
            if (row == std::end(kFormatUsages)) complain("unknown format usage '" + u + "' for " + format);
            else fs.*(row->member) = true;
          }
          vk.formats.push_back(std::move(fs));
        }
      } else {
        complain("unknown vulkan key '" + key + "'");
      }
    }
  }

  DiagnosticSink* sink_;
};

}  // namespace

const char* to_string(CapsGeneration g) { return kGenerationNames[size_t(g)]; }

std::optional<CapsGeneration> parse_caps_generation(std::string_view name) {
  for (size_t i = 0; i < kGenerationNames.size(); ++i)
    if (name == kGenerationNames[i]) return CapsGeneration(i);
  return std::nullopt;
}

std::span<const CapsFeatureRow> caps_feature_table() { return kFeatureRows; }
std::span<const CapsLimitRow> caps_limit_table() { return kLimitRows; }

std::string canonical_shader_profile(std::string_view profile) {
  std::string out;
  out.reserve(profile.size());
  for (char c : profile) {
    out.push_back(c == '.' ? '_' : ascii_lower(c));
  }
  return out;
}

bool supports(const DeviceCaps& caps, std::string_view shader_profile) {
  std::string want = canonical_shader_profile(shader_profile);
  return std::binary_search(caps.shader_profiles.begin(), caps.shader_profiles.end(), want);
}

const FormatSupport* find_format(const DeviceCaps& caps, std::string_view format) {
  if (format.starts_with("VK_FORMAT_")) format.remove_prefix(10);
  auto it = std::lower_bound(caps.vulkan.formats.begin(), caps.vulkan.formats.end(), format,
                             [](const FormatSupport& f, std::string_view n) { return f.format < n; });
  return it != caps.vulkan.formats.end() && it->format == format ? &*it : nullptr;
}

void normalize(DeviceCaps& caps) {
  sort_unique(caps.shader_profiles);
  sort_unique(caps.vulkan.features);
  sort_unique(caps.vulkan.extensions);
  auto& f = caps.vulkan.formats;
  std::sort(f.begin(), f.end(), [](const auto& a, const auto& b) { return a.format < b.format; });
  f.erase(std::unique(f.begin(), f.end(), [](const auto& a, const auto& b) { return a.format == b.format; }), f.end());
}

void to_json(nlohmann::json& j, const DeviceCaps& caps) {
  j = nlohmann::json::object();
  j["name"] = caps.name;
  if (!caps.description.empty()) j["description"] = caps.description;
  j["generation"] = to_string(caps.generation);
  j["shader_profiles"] = caps.shader_profiles;
  nlohmann::json limits = nlohmann::json::object(), features = nlohmann::json::object();
  for (const auto& row : kLimitRows) limits[row.name] = caps.limits.*(row.member);
  for (const auto& row : kFeatureRows) features[row.name] = caps.features.*(row.member);
  j["limits"] = std::move(limits);
  j["features"] = std::move(features);
  if (caps.vulkan.present) {
    nlohmann::json vk = nlohmann::json::object();
    vk["api_version"] = caps.vulkan.api_version;
    vk["device_type"] = caps.vulkan.device_type;
    vk["features"] = caps.vulkan.features;
    vk["extensions"] = caps.vulkan.extensions;
    nlohmann::json formats = nlohmann::json::object();
    for (const auto& fs : caps.vulkan.formats) {
      nlohmann::json usages = nlohmann::json::array();
      for (const auto& row : kFormatUsages)
        if (fs.*(row.member)) usages.push_back(row.name);
      formats[fs.format] = std::move(usages);
    }
    vk["formats"] = std::move(formats);
    j["vulkan"] = std::move(vk);
  }
}

void from_json(const nlohmann::json& j, DeviceCaps& caps) {
  caps = DeviceCaps{};
  CapsReader(nullptr).read(j, caps);
}

std::optional<DeviceCaps> caps_from_json(const nlohmann::json& j, DiagnosticSink& sink) {
  size_t errors_before = sink.error_count();
  DeviceCaps caps;
  CapsReader(&sink).read(j, caps);
  if (sink.error_count() != errors_before) return std::nullopt;
  return caps;
}

}  // namespace fx
