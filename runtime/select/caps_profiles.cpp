// The shipped generation profiles, compiled in from profiles/*.json (see CMakeLists.txt).
#include <algorithm>
#include <nlohmann/json.hpp>

#include "fx/ascii_case.h"
#include "fx/select/caps_sources.h"

namespace fx {
namespace detail {
struct EmbeddedCapsProfile {
  const char* name;
  const char* json;
};
extern const EmbeddedCapsProfile kEmbeddedCapsProfiles[];
extern const size_t kEmbeddedCapsProfileCount;
}  // namespace detail

std::vector<std::string> caps_profile_names() {
  std::vector<std::string> names;
  for (size_t i = 0; i < detail::kEmbeddedCapsProfileCount; ++i)
    names.emplace_back(detail::kEmbeddedCapsProfiles[i].name);
  return names;
}

std::optional<DeviceCaps> load_caps_profile(std::string_view name, DiagnosticSink& sink) {
  for (size_t i = 0; i < detail::kEmbeddedCapsProfileCount; ++i) {
    const auto& p = detail::kEmbeddedCapsProfiles[i];
    if (!iequals(name, p.name)) continue;
    nlohmann::json j = nlohmann::json::parse(p.json, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) {
      sink.error("caps-json", {}, std::string("shipped caps profile '") + p.name + "' is not valid JSON");
      return std::nullopt;
    }
    return caps_from_json(j, sink);
  }
  std::vector<std::string> names = caps_profile_names();
  std::vector<std::string_view> views(names.begin(), names.end());
  std::string message = "no caps profile named '" + std::string(name) + "'";
  std::string guess = closest_match(name, views);
  if (!guess.empty()) message += "; did you mean '" + guess + "'?";
  sink.error("unknown-caps-profile", {}, message);
  return std::nullopt;
}

}  // namespace fx
