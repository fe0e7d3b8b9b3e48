// Parsing `Requires` tokens and checking them against DeviceCaps.
#include "fx/select/caps_requirement.h"

#include <algorithm>
#include <charconv>

namespace fx {
namespace {

const CapsFeatureRow* find_feature(std::string_view name) {
  for (const auto& row : caps_feature_table())
    if (name == row.name) return &row;
  return nullptr;
}

// "textures" and "mrt" are the names effect authors reach for first.
const CapsLimitRow* find_limit(std::string_view name) {
  if (name == "textures") name = "simultaneous_textures";
  if (name == "mrt") name = "render_targets";
  for (const auto& row : caps_limit_table())
    if (name == row.name) return &row;
  return nullptr;
}

constexpr std::string_view kUsages[] = {"sampled", "filter_linear", "color_attachment",
                                        "blend",   "depth_stencil", "storage"};

bool looks_like_profile(std::string_view p) {
  // vs_1_1, ps.2.0, gs_4_0, glsl_450: letters, then digits joined by '_' or '.'.
  if (p.starts_with("glsl_")) return p.size() > 5;
  size_t us = p.find_first_of("_.");
  if (us != 2 || p.size() < 5) return false;
  static constexpr std::string_view stages[] = {"vs", "ps", "gs", "hs", "ds", "cs"};
  return std::find(std::begin(stages), std::end(stages), p.substr(0, 2)) != std::end(stages);
}

bool has(const std::vector<std::string>& sorted, std::string_view name) {
  return std::binary_search(sorted.begin(), sorted.end(), name);
}

}  // namespace

CapsRequirement CapsRequirement::profile(std::string_view p) {
  return {Kind::shader_profile, canonical_shader_profile(p), 0, {}};
}
CapsRequirement CapsRequirement::feature(std::string_view f) { return {Kind::feature, std::string(f), 0, {}}; }
CapsRequirement CapsRequirement::limit(std::string_view l, uint32_t minimum) {
  const CapsLimitRow* row = find_limit(l);
  return {Kind::limit, row ? row->name : std::string(l), minimum, {}};
}

std::string CapsRequirement::spelling() const {
  switch (kind) {
    case Kind::shader_profile:
    case Kind::feature: return name;
    case Kind::limit: return name + ">=" + std::to_string(minimum);
    case Kind::vulkan_feature: return "vk:" + name;
    case Kind::vulkan_extension: return "ext:" + name;
    case Kind::format: return "format:" + name + "/" + usage;
  }
  return name;
}

std::optional<CapsRequirement> parse_caps_requirement(std::string_view token, std::string* error) {
  auto fail = [&](std::string message) -> std::optional<CapsRequirement> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  if (token.empty()) return fail("empty requirement");
  if (token.starts_with("vk:") && token.size() > 3)
    return CapsRequirement{CapsRequirement::Kind::vulkan_feature, std::string(token.substr(3)), 0, {}};
  if (token.starts_with("ext:") && token.size() > 4)
    return CapsRequirement{CapsRequirement::Kind::vulkan_extension, std::string(token.substr(4)), 0, {}};
  if (token.starts_with("format:") && token.size() > 7) {
    std::string_view rest = token.substr(7);
    std::string usage = "sampled";
    if (size_t slash = rest.find('/'); slash != std::string_view::npos) {
      usage = std::string(rest.substr(slash + 1));
      rest = rest.substr(0, slash);
      if (std::find(std::begin(kUsages), std::end(kUsages), usage) == std::end(kUsages))
        return fail("unknown format usage '" + usage + "'");
    }
    if (rest.starts_with("VK_FORMAT_")) rest.remove_prefix(10);
    return CapsRequirement{CapsRequirement::Kind::format, std::string(rest), 0, usage};
  }
  if (size_t ge = token.find(">="); ge != std::string_view::npos) {
    std::string_view name = token.substr(0, ge), number = token.substr(ge + 2);
    uint32_t value = 0;
    auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (ec != std::errc() || end != number.data() + number.size()) {
      // Appended piecewise: g++ 12 warns falsely (-Wrestrict) on "'" + std::string(...).
      std::string message = "'";
      message.append(number).append("' is not a whole number in '").append(token).append("'");
      return fail(std::move(message));
    }
    if (!find_limit(name)) return fail("unknown limit '" + std::string(name) + "'");
    return CapsRequirement::limit(name, value);
  }
  if (find_feature(token)) return CapsRequirement::feature(token);
  std::string profile = canonical_shader_profile(token);
  if (looks_like_profile(profile)) return CapsRequirement::profile(profile);
  return fail("unknown requirement '" + std::string(token) + "'");
}

std::vector<CapsRequirement> parse_caps_requirements(std::string_view list, std::vector<std::string>* errors) {
  std::vector<CapsRequirement> out;
  size_t i = 0;
  while (i < list.size()) {
    size_t start = list.find_first_not_of(" \t\r\n,;", i);
    if (start == std::string_view::npos) break;
    size_t end = list.find_first_of(" \t\r\n,;", start);
    if (end == std::string_view::npos) end = list.size();
    std::string error;
    if (auto req = parse_caps_requirement(list.substr(start, end - start), &error)) out.push_back(std::move(*req));
    else if (errors) errors->push_back(std::move(error));
    i = end;
  }
  return out;
}

std::optional<std::string> unmet_reason(const DeviceCaps& caps, const CapsRequirement& req) {
  const std::string on = " on " + (caps.name.empty() ? std::string("this device") : caps.name);
  switch (req.kind) {
    case CapsRequirement::Kind::shader_profile:
      if (supports(caps, req.name)) return std::nullopt;
      return req.name + " not supported" + on;
    case CapsRequirement::Kind::feature: {
      const CapsFeatureRow* row = find_feature(req.name);
      if (!row) return "unknown feature '" + req.name + "'";
      if (caps.features.*(row->member)) return std::nullopt;
      return req.name + " not supported" + on;
    }
    case CapsRequirement::Kind::limit: {
      const CapsLimitRow* row = find_limit(req.name);
      if (!row) return "unknown limit '" + req.name + "'";
      uint32_t have = caps.limits.*(row->member);
      if (have >= req.minimum) return std::nullopt;
      return "needs " + std::to_string(req.minimum) + " " + req.name + ", " +
             (caps.name.empty() ? std::string("device") : caps.name) + " has " + std::to_string(have);
    }
    case CapsRequirement::Kind::vulkan_feature:
      if (has(caps.vulkan.features, req.name)) return std::nullopt;
      return "Vulkan feature " + req.name + " not supported" + on;
    case CapsRequirement::Kind::vulkan_extension:
      if (has(caps.vulkan.extensions, req.name)) return std::nullopt;
      return "extension " + req.name + " not supported" + on;
    case CapsRequirement::Kind::format: {
      const FormatSupport* fs = find_format(caps, req.name);
      bool ok = false;
      if (fs) {
        if (req.usage == "sampled") ok = fs->sampled;
        else if (req.usage == "filter_linear") ok = fs->filter_linear;
        else if (req.usage == "color_attachment") ok = fs->color_attachment;
        else if (req.usage == "blend") ok = fs->blend;
        else if (req.usage == "depth_stencil") ok = fs->depth_stencil;
        else if (req.usage == "storage") ok = fs->storage;
      }
      if (ok) return std::nullopt;
      return "format " + req.name + " not usable for " + req.usage + on;
    }
  }
  return std::nullopt;
}

}  // namespace fx
