#include "fx/compile/translation_unit.h"

#include <cctype>

namespace fx {

const char* to_string(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::vertex: return "vertex";
    case ShaderStage::tess_control: return "tess_control";
    case ShaderStage::tess_evaluation: return "tess_evaluation";
    case ShaderStage::geometry: return "geometry";
    case ShaderStage::fragment: return "fragment";
    case ShaderStage::compute: return "compute";
  }
  return "unknown";
}

const char* to_string(ShaderLanguage language) { return language == ShaderLanguage::hlsl ? "hlsl" : "glsl"; }

std::optional<ShaderProfile> parse_profile(std::string_view p) {
  ShaderProfile out;
  if (p == "glsl") {
    out.language = ShaderLanguage::glsl;
    out.major = 4, out.minor = 5;
    return out;
  }
  // GLSL versions: "450", "460", "glsl450"; Vulkan GLSL needs 140 or later.
  std::string_view digits = p.substr(0, 4) == "glsl" ? p.substr(4) : p;
  if (digits.size() == 3 && std::isdigit(static_cast<unsigned char>(digits[0])) &&
      std::isdigit(static_cast<unsigned char>(digits[1])) && digits[2] == '0') {
    out.language = ShaderLanguage::glsl;
    out.major = digits[0] - '0', out.minor = digits[1] - '0';
    if (out.major * 10 + out.minor < 14) return std::nullopt;
    return out;
  }
  // HLSL: <stage>_<major>_<minor>[_level_9_x]
  if (p.size() < 6 || p[2] != '_' || p[4] != '_') return std::nullopt;
  std::string_view s = p.substr(0, 2);
  if (s == "vs") out.stage = ShaderStage::vertex;
  else if (s == "ps") out.stage = ShaderStage::fragment;
  else if (s == "gs") out.stage = ShaderStage::geometry;
  else if (s == "hs") out.stage = ShaderStage::tess_control;
  else if (s == "ds") out.stage = ShaderStage::tess_evaluation;
  else if (s == "cs") out.stage = ShaderStage::compute;
  else return std::nullopt;
  if (!std::isdigit(static_cast<unsigned char>(p[3]))) return std::nullopt;
  out.major = p[3] - '0';
  char minor = p[5];
  if (minor == 'x' || minor == 'X') out.minor = 0;  // "vs_2_x", "ps_2_x"
  else if (std::isdigit(static_cast<unsigned char>(minor))) out.minor = minor - '0';
  else return std::nullopt;
  std::string_view rest = p.substr(6);
  if (!rest.empty() && rest.substr(0, 6) != "_level") return std::nullopt;
  if (out.major < 1 || out.major > 6) return std::nullopt;
  // Stages that did not exist in early shader models.
  if ((s == "gs" && out.major < 4) ||
      ((s == "hs" || s == "ds" || s == "cs") && out.major < 5 && !(s == "cs" && out.major == 4)))
    return std::nullopt;
  return out;
}

}  // namespace fx
