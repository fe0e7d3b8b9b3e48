// `fxkit check [-I DIR]... [-D NAME[=VALUE]]... [--profile P] [--json] [--werror] FILE...`
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "command.h"
#include "effect_summary.h"
#include "fx/diagnostic_render.h"

namespace fxkit {
namespace {

struct CheckArgs {
  FrontEndFlags front_end;
  std::vector<std::string> files;
  bool json = false;
  bool werror = false;
};

int run_check(const CheckArgs& args) {
  fx::FrontEndOptions options;
  std::string error;
  if (!args.front_end.to_options(options, error)) {
    std::fprintf(stderr, "fxkit check: %s\n", error.c_str());
    return kUsageError;
  }
  for (const std::string& f : args.files) {
    if (!std::filesystem::is_regular_file(f)) {
      std::fprintf(stderr, "fxkit check: cannot read '%s'\n", f.c_str());
      return kUsageError;
    }
  }
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  diags.set_warnings_as_errors(args.werror);
  nlohmann::json effects = nlohmann::json::array();
  for (const std::string& f : args.files) {
    size_t first = diags.diagnostics().size();
    fx::ParsedEffect parsed = fx::parse_effect_file(f, sm, diags, options);
    if (args.json) {
      nlohmann::json e = summarize_effect(parsed.ast, sm);
      e["file"] = f;
      e["ok"] = parsed.ok;
      e["includes"] = parsed.files;
      effects.push_back(std::move(e));
    } else {
      std::vector<fx::Diagnostic> mine(diags.diagnostics().begin() + first, diags.diagnostics().end());
      std::fputs(fx::render_text(mine, sm).c_str(), stderr);
    }
  }
  if (args.json) {
    nlohmann::json out = {{"diagnostics", fx::render_json(diags.diagnostics(), sm)},
                          {"effects", std::move(effects)},
                          {"errors", diags.error_count()},
                          {"warnings", diags.warning_count()}};
    std::puts(out.dump(2).c_str());
  } else if (diags.error_count() || diags.warning_count()) {
    std::fprintf(stderr, "%zu error(s), %zu warning(s)\n", diags.error_count(), diags.warning_count());
  }
  return diags.has_errors() ? kInputErrors : kSuccess;
}

}  // namespace

void register_check(CLI::App& app, Runner& run) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand("check", "Preprocess, parse and check effect files");
  args->front_end.add_to(*cmd);
  cmd->add_flag("--json", args->json, "Print diagnostics and a summary as one JSON document");
  cmd->add_flag("--werror", args->werror, "Treat warnings as errors");
  cmd->add_option("FILE", args->files, "Effect files")->required();
  cmd->callback([args, &run] { run = [args] { return run_check(*args); }; });
}

}  // namespace fxkit
