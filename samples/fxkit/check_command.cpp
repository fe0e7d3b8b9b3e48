// `fxkit check [-I DIR]... [-D NAME[=VALUE]]... [--profile P] [--json] [--werror]
//  [--caps dx7|modern|FILE.json|device [--no-compile]] FILE...`
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "command.h"
#include "effect_summary.h"
#include "fx/diagnostic_render.h"
#ifdef FXKIT_HAS_RUNTIME
#include "caps_option.h"
#include "fx/select/technique_validation.h"
#endif

namespace fxkit {
namespace {

struct CheckArgs {
  FrontEndFlags front_end;
  std::vector<std::string> files;
  bool json = false;
  bool werror = false;
  std::string caps;         // --caps: validate every technique on these caps ("" = don't)
  bool no_compile = false;  // --no-compile: validate without compiling shaders
};

#ifdef FXKIT_HAS_RUNTIME
// Every technique valid or not on `caps`; false when none is (the effect cannot run there).
bool report_techniques(const fx::ParsedEffect& parsed, const std::string& file, const fx::DeviceCaps& caps,
                       const CheckArgs& args, fx::SourceManager& sm, fx::DiagnosticSink& diags,
                       nlohmann::json* json) {
  auto techniques = fx::validate_effect(parsed.ast, sm, caps, diags, !args.no_compile);
  size_t valid = 0;
  for (const auto& t : techniques) valid += t.valid ? 1 : 0;
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& t : techniques)
      list.push_back({{"name", t.name}, {"valid", t.valid}, {"reasons", fx::render_json(t.reasons, sm)}});
    (*json)["caps"] = caps.name;
    (*json)["techniques"] = std::move(list);
    (*json)["valid_techniques"] = valid;
  } else {
    std::printf("%s on %s: %zu of %zu techniques valid\n", file.c_str(), caps.name.c_str(), valid, techniques.size());
    for (const auto& t : techniques) {
      std::printf("  %-8s %s\n", t.valid ? "valid" : "invalid", t.name.c_str());
      for (const auto& r : t.reasons) std::printf("    %s\n", fx::located_reason(r, sm).c_str());
    }
  }
  return valid > 0;
}
#endif

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
  bool runnable = true;  // with --caps: every effect has a valid technique
#ifdef FXKIT_HAS_RUNTIME
  std::optional<fx::DeviceCaps> caps;
  if (!args.caps.empty()) {
    fx::DiagnosticSink caps_diags;
    caps = load_caps_option(args.caps, caps_diags);
    if (!caps) {
      std::fputs(fx::render_text(caps_diags.diagnostics(), sm).c_str(), stderr);
      return kUsageError;
    }
  }
#endif
  nlohmann::json effects = nlohmann::json::array();
  for (const std::string& f : args.files) {
    size_t first = diags.diagnostics().size();
    fx::ParsedEffect parsed = fx::parse_effect_file(f, sm, diags, options);
    if (args.json) {
      nlohmann::json e = summarize_effect(parsed.ast, sm);
      e["file"] = f;
      e["ok"] = parsed.ok;
      e["includes"] = parsed.files;
#ifdef FXKIT_HAS_RUNTIME
      if (caps && parsed.ok) runnable &= report_techniques(parsed, f, *caps, args, sm, diags, &e);
#endif
      effects.push_back(std::move(e));
    } else {
#ifdef FXKIT_HAS_RUNTIME
      if (caps && parsed.ok) runnable &= report_techniques(parsed, f, *caps, args, sm, diags, nullptr);
#endif
      std::vector<fx::Diagnostic> mine(diags.diagnostics().begin() + first, diags.diagnostics().end());
      std::fputs(fx::render_text(mine, sm).c_str(), stderr);
    }
  }
  if (args.json) {
    nlohmann::json out = {{"diagnostics", fx::render_json(diags.diagnostics(), sm)},
                          {"effects", std::move(effects)},
                          {"errors", diags.error_count()},
                          {"warnings", diags.warning_count()}};
    std::puts(json_text(out).c_str());
  } else if (diags.error_count() || diags.warning_count()) {
    std::fprintf(stderr, "%zu error(s), %zu warning(s)\n", diags.error_count(), diags.warning_count());
  }
  return diags.has_errors() || !runnable ? kInputErrors : kSuccess;
}

}  // namespace

void register_check(CLI::App& app, Runner& run) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand("check", "Preprocess, parse and check effect files");
  args->front_end.add_to(*cmd);
  cmd->add_flag("--json", args->json, "Print diagnostics and a summary as one JSON document");
  cmd->add_flag("--werror", args->werror, "Treat warnings as errors");
  cmd->add_option("FILE", args->files, "Effect files")->required();
#ifdef FXKIT_HAS_RUNTIME
  cmd->add_option("--caps", args->caps, "Validate every technique on: " + caps_option_help());
  cmd->add_flag("--no-compile", args->no_compile, "With --caps: validate without compiling shaders");
#endif
  cmd->callback([args, &run] { run = [args] { return run_check(*args); }; });
}

}  // namespace fxkit
