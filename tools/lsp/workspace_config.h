// What the front end needs to read a workspace's effects: include folders, defines and the
// effect profile, from the client's initializationOptions or settings and from a
// `fxkit.json` at the workspace root (docs/editor.md).
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fx/frontend.h"

namespace fx::tools::lsp {

struct WorkspaceConfig {
  std::vector<std::string> include_dirs;  // absolute, or relative to the server's folder
  std::vector<std::string> defines;       // NAME or NAME=VALUE
  std::string profile = "auto";
  std::vector<std::string> caps_profiles;  // shipped caps profiles techniques are validated on

  // The caps profiles code lenses report: those given, or dx8, dx9 and modern.
  std::vector<std::string> validation_profiles() const;

  // Adds the settings of one source, `{"includeDirs": [..], "defines": [..], "profile": "..",
  // "capsProfiles": [..]}`;
  // relative folders are taken against `root`. A malformed entry adds a line to `problems`.
  void merge(const nlohmann::json& settings, const std::string& root, std::vector<std::string>& problems);
  // The front end's options for the document at `path` as the editor holds the workspace:
  // included files are read from `open` (paths to the texts of the open documents, which
  // must outlive the options) first and from disk otherwise; a header (not `.fx`) needs no
  // technique of its own.
  fx::FrontEndOptions document_options(const std::string& path, const std::map<std::string, std::string>& open) const;
};

// The configuration file at the root of a workspace.
inline constexpr const char* kWorkspaceFile = "fxkit.json";
// Merges `root/fxkit.json` into `config` when it exists; a file that is no JSON object adds
// a line to `problems`.
void merge_workspace_file(const std::string& root, WorkspaceConfig& config, std::vector<std::string>& problems);

}  // namespace fx::tools::lsp
