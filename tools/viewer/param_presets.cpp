// Parameter presets through nlohmann::json.
#include "param_presets.h"

#include <fstream>
#include <nlohmann/json.hpp>

bool save_params(const fxkit::Effect& effect, const std::string& path, std::string& error) {
  nlohmann::json params = nlohmann::json::object();
  for (const fxkit::ParamInfo& p : effect.params()) {
    if (p.kind != fxkit::ParamKind::numeric || !p.settable) continue;
    if (p.scalar == fxkit::ScalarKind::float32) {
      std::vector<float> v(p.components);
      if (effect.get(p.handle, v)) params[p.name] = v;
    } else {
      std::vector<int32_t> v(p.components);
      if (effect.get(p.handle, v)) params[p.name] = v;
    }
  }
  std::ofstream out(path);
  out << nlohmann::json{{"effect", effect.path()}, {"params", params}}.dump(2) << "\n";
  if (!out) return error = "cannot write " + path, false;
  return true;
}

bool load_params(fxkit::Effect& effect, const std::string& path, std::string& error) {
  std::ifstream in(path);
  if (!in) return error = "cannot read " + path, false;
  const nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);
  if (doc.is_discarded() || !doc.contains("params") || !doc["params"].is_object())
    return error = path + ": not a parameter file (wants {\"params\": {NAME: [values]}})", false;
  const std::vector<fxkit::ParamInfo> params = effect.params();
  for (const auto& item : doc["params"].items()) {
    const std::string& name = item.key();  // not a structured binding: clang cannot capture one
    const nlohmann::json& value = item.value();
    auto p = std::find_if(params.begin(), params.end(), [&](const fxkit::ParamInfo& i) { return i.name == name; });
    bool set = false;
    if (p != params.end() && value.is_array() && value.size() == p->components) {
      if (p->scalar == fxkit::ScalarKind::float32)
        set = effect.set(p->handle, std::span<const float>(value.get<std::vector<float>>()));
      else set = effect.set(p->handle, std::span<const int32_t>(value.get<std::vector<int32_t>>()));
    }
    if (!set) error += (error.empty() ? path + ": not applied: " : ", ") + name;
  }
  return true;
}
