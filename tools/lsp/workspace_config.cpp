// Workspace configuration for the language server (workspace_config.h).
#include "workspace_config.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fx::tools::lsp {

void WorkspaceConfig::merge(const nlohmann::json& settings, const std::string& root,
                            std::vector<std::string>& problems) {
  if (!settings.is_object()) return;
  auto strings = [&](const char* key, auto&& add) {
    auto it = settings.find(key);
    if (it == settings.end()) return;
    if (!it->is_array()) {
      problems.push_back(std::string(key) + " must be an array of strings");
      return;
    }
    for (const auto& v : *it) {
      if (v.is_string()) add(v.get<std::string>());
      else problems.push_back(std::string(key) + " holds a value that is no string");
    }
  };
  strings("includeDirs", [&](std::string dir) {
    std::filesystem::path p(dir);
    if (p.is_relative() && !root.empty()) p = std::filesystem::path(root) / p;
    include_dirs.push_back(p.lexically_normal().generic_string());
  });
  strings("defines", [&](std::string d) { defines.push_back(std::move(d)); });
  strings("capsProfiles", [&](std::string name) { caps_profiles.push_back(std::move(name)); });
  if (auto it = settings.find("profile"); it != settings.end()) {
    if (it->is_string() && (it->get<std::string>() == "auto" || fx::parse_effect_profile(it->get<std::string>())))
      profile = it->get<std::string>();
    else problems.push_back("profile must be auto, fx_2_0, fx_4_0, fx_4_1 or fx_5_0");
  }
}

std::vector<std::string> WorkspaceConfig::validation_profiles() const {
  if (caps_profiles.empty()) return {"dx8", "dx9", "modern"};
  return caps_profiles;
}

fx::FrontEndOptions WorkspaceConfig::document_options(const std::string& path,
                                                      const std::map<std::string, std::string>& open) const {
  fx::FrontEndOptions options;
  options.preprocessor.include_dirs = include_dirs;
  for (const std::string& d : defines) options.preprocessor.defines.push_back(fx::parse_define(d));
  options.check.profile = fx::parse_effect_profile(profile).value_or(fx::EffectProfile::automatic);
  fx::FileLoader disk = fx::disk_file_loader();
  options.preprocessor.loader = [&open, disk](const std::string& file) -> std::optional<std::string> {
    if (auto it = open.find(file); it != open.end()) return it->second;
    return disk(file);
  };
  options.preprocessor.lister = fx::disk_directory_lister();
  options.check.require_technique = path.ends_with(".fx");  // an include library needs none
  return options;
}

void merge_workspace_file(const std::string& root, WorkspaceConfig& config, std::vector<std::string>& problems) {
  if (root.empty()) return;
  const std::filesystem::path file = std::filesystem::path(root) / kWorkspaceFile;
  std::ifstream in(file);
  if (!in) return;
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json settings = nlohmann::json::parse(text.str(), nullptr, false);
  if (!settings.is_object()) {
    problems.push_back(file.string() + " is no JSON object");
    return;
  }
  config.merge(settings, root, problems);
}

}  // namespace fx::tools::lsp
