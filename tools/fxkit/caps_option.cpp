// Resolves `--caps dx7|modern|FILE.json|device` (see caps_option.h).
#include "caps_option.h"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "fx/binding/context_caps.h"
#include "fx/select/caps_sources.h"
#include "fx/vulkan/context.h"

namespace fx::tools {

std::string caps_option_help() {
  std::string names;
  for (const std::string& n : fx::caps_profile_names()) names += (names.empty() ? "" : "|") + n;
  return "Device caps: " + names + ", a caps or `vulkaninfo --json` FILE.json, or 'device' (the live Vulkan device)";
}

std::optional<fx::DeviceCaps> load_caps_option(const std::string& value, fx::DiagnosticSink& sink) {
  if (value == "device") {
    auto ctx = fx::vk::Context::headless({}, sink);
    if (!ctx) return std::nullopt;
    return fx::vk::context_caps(*ctx);
  }
  bool looks_like_file =
      value.find('/') != std::string::npos || value.ends_with(".json") || std::filesystem::is_regular_file(value);
  if (!looks_like_file) return fx::load_caps_profile(value, sink);
  std::ifstream in(value);
  if (!in) {
    sink.error("caps-file", {}, "cannot read caps file '" + value + "'");
    return std::nullopt;
  }
  nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) {
    sink.error("caps-file", {}, "caps file '" + value + "' is not valid JSON");
    return std::nullopt;
  }
  // A saved DeviceCaps has shader_profiles; anything else is read as a vulkaninfo report.
  if (j.is_object() && j.contains("shader_profiles")) return fx::caps_from_json(j, sink);
  return fx::caps_from_vulkaninfo_json(j, sink);
}

}  // namespace fx::tools
