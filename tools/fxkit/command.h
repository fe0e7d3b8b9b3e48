// Shared pieces of the fxkit subcommands: the front-end flags every command takes, and the
// exit codes and JSON text of tool_output.h (tools/check).
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "fx/frontend.h"
#include "tool_output.h"

namespace fx::tools {

// -I, -D and --profile, as every command that reads effects takes them.
struct FrontEndFlags {
  std::vector<std::string> include_dirs;
  std::vector<std::string> defines;
  std::string profile = "auto";

  void add_to(CLI::App& command);
  // The options for the front end; false (and a message in `error`) for a bad --profile.
  bool to_options(fx::FrontEndOptions& options, std::string& error) const;
};

// Each subcommand registers itself and sets *run to what to execute when it is chosen.
using Runner = std::function<int()>;
void register_check(CLI::App& app, Runner& run);
void register_bench(CLI::App& app, Runner& run);
void register_lsp(CLI::App& app, Runner& run);
void register_compile(CLI::App& app, Runner& run);
void register_info(CLI::App& app, Runner& run);
void register_watch(CLI::App& app, Runner& run);
void register_select(CLI::App& app, Runner& run);
void register_render(CLI::App& app, Runner& run);

}  // namespace fx::tools
