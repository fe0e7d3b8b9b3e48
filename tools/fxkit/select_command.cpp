// `fxkit select FILE --caps X [--distance D] [--screen-size S] [--pixels P] [--vertices V] [--scheme S]
//  [--budget-ms B] [--max-error E] [--fallback T] [--no-compile] [--json]`: the technique the
// effect would run for one object on one device, and why every other one was not chosen.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

#include <nlohmann/json.hpp>

#include "caps_option.h"
#include "command.h"
#include "fx/compile/effect_file.h"
#include "fx/diagnostic_render.h"
#include "fx/select/effect_candidates.h"

namespace fx::tools {
namespace {

struct SelectArgs {
  FrontEndFlags front_end;
  std::string file;
  std::string caps = "modern";
  float distance = 0.f;
  float screen_size = -1.f;
  float pixels = 0.f;
  float vertices = 0.f;
  std::string scheme;
  float budget_ms = std::numeric_limits<float>::infinity();
  float max_error = std::numeric_limits<float>::infinity();
  std::string fallback;
  bool no_compile = false;
  bool json = false;
};

nlohmann::json number_or_null(float x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

int run_select(const SelectArgs& args) {
  fx::FrontEndOptions options;
  std::string error;
  if (!args.front_end.to_options(options, error)) {
    std::fprintf(stderr, "fxkit select: %s\n", error.c_str());
    return kUsageError;
  }
  if (!std::filesystem::is_regular_file(args.file)) {
    std::fprintf(stderr, "fxkit select: cannot read '%s'\n", args.file.c_str());
    return kUsageError;
  }
  fx::DiagnosticSink diags;
  auto caps = load_caps_option(args.caps, diags);
  if (!caps) {
    std::fputs(fx::render_text(diags.diagnostics(), fx::SourceManager()).c_str(), stderr);
    return kUsageError;
  }
  std::unique_ptr<fx::EffectFile> effect = fx::EffectFile::parse(args.file, options, diags);
  const fx::ParsedEffect& parsed = effect->parsed;
  const fx::SourceManager& sm = effect->sources;
  fx::EffectSelectionOptions sel_options;
  sel_options.compile = !args.no_compile;
  sel_options.plan.effect_fallback = args.fallback;
  fx::EffectSelection sel;
  if (parsed.ok) sel = fx::build_effect_selection(*effect, *caps, diags, sel_options);

  fx::SelectionCriteria criteria{.distance = args.distance,
                                 .screen_size = args.screen_size,
                                 .pixels = args.pixels,
                                 .vertices = args.vertices,
                                 .scheme = args.scheme,
                                 .cost_budget_ms = args.budget_ms,
                                 .max_error = args.max_error};
  fx::SelectionResult result = sel.plan.explain(sel.plan.query(criteria));
  // An effect with errors does not load (render, the viewer and EffectLibrary refuse it), so
  // none of its techniques is valid or chosen, whatever its passes would need.
  const bool loads = parsed.ok && !diags.has_errors();
  const bool ok = loads && result.ok();
  const std::string not_loaded = "the effect has errors, so it does not load";

  if (args.json) {
    nlohmann::json techniques = nlohmann::json::array();
    for (size_t i = 0; i < sel.techniques.size(); ++i) {
      const fx::TechniqueValidation& t = sel.techniques[i];
      techniques.push_back({{"name", t.name},
                            {"valid", loads && t.valid},
                            {"chosen", ok && i == result.chosen},
                            {"reason", !loads                      ? not_loaded
                                       : i < result.reasons.size() ? result.reasons[i]
                                                                   : std::string()},
                            {"emulation", t.emulation},
                            {"rejections", fx::render_json(t.reasons, sm)}});
    }
    nlohmann::json path = nlohmann::json::array();
    for (uint32_t i : result.fallback_path) path.push_back(std::string(sel.plan.name(i)));
    nlohmann::json out = {
        {"file", args.file},
        {"caps", caps->name},
        {"criteria",
         {{"distance", args.distance},
          {"screen_size", args.screen_size},
          {"pixels", args.pixels},
          {"vertices", args.vertices},
          {"scheme", args.scheme},
          {"budget_ms", number_or_null(args.budget_ms)},
          {"max_error", number_or_null(args.max_error)}}},
        {"chosen", ok ? nlohmann::json(std::string(sel.plan.name(result.chosen))) : nlohmann::json(nullptr)},
        {"route", fx::to_string(result.route)},
        {"fallback_path", std::move(path)},
        {"techniques", std::move(techniques)},
        {"diagnostics", fx::render_json(diags.diagnostics(), sm)},
    };
    std::puts(json_text(out).c_str());
  } else {
    std::fputs(fx::render_text(diags.diagnostics(), sm).c_str(), stderr);
    std::string name = std::filesystem::path(args.file).filename().string();
    auto emulation = [&](size_t i) {
      std::string out;
      if (i < sel.techniques.size())
        for (const std::string& e : sel.techniques[i].emulation) out += " [" + e + "]";
      return out;
    };
    if (ok)
      std::printf("%s on %s: %s (%s)%s\n", name.c_str(), caps->name.c_str(),
                  std::string(sel.plan.name(result.chosen)).c_str(), fx::to_string(result.route),
                  emulation(result.chosen).c_str());
    else
      std::printf("%s on %s: no technique%s\n", name.c_str(), caps->name.c_str(),
                  loads ? "" : (" (" + not_loaded + ")").c_str());
    for (size_t i = 0; i < sel.techniques.size(); ++i) {
      if (!loads) break;
      if (i == result.chosen) continue;
      std::printf("  %s: %s%s\n", sel.techniques[i].name.c_str(),
                  i < result.reasons.size() ? result.reasons[i].c_str() : "", emulation(i).c_str());
    }
  }
  return ok ? kSuccess : kInputErrors;
}

}  // namespace

void register_select(CLI::App& app, Runner& run) {
  auto args = std::make_shared<SelectArgs>();
  CLI::App* cmd = app.add_subcommand("select", "Choose an effect's technique for a device and scene, with reasons");
  args->front_end.add_to(*cmd);
  cmd->add_option("FILE", args->file, "Effect file")->required();
  cmd->add_option("--caps", args->caps, caps_option_help())->capture_default_str();
  cmd->add_option("--distance", args->distance, "Camera distance of the object");
  cmd->add_option("--screen-size", args->screen_size, "Projected size in pixels (negative: unknown)");
  cmd->add_option("--pixels", args->pixels, "Covered pixels (for CostNsPerPixel)");
  cmd->add_option("--vertices", args->vertices, "Vertices drawn (for CostNsPerVertex)");
  cmd->add_option("--scheme", args->scheme, "Scheme asked for (quality, performance, ...)");
  cmd->add_option("--budget-ms", args->budget_ms, "Cost budget per object in milliseconds");
  cmd->add_option("--max-error", args->max_error, "Largest acceptable error in 8-bit levels");
  cmd->add_option("--fallback", args->fallback, "Effect-level fallback technique");
  cmd->add_flag("--no-compile", args->no_compile, "Validate without compiling shaders");
  cmd->add_flag("--json", args->json, "Print the choice and every reason as JSON");
  cmd->callback([args, &run] { run = [args] { return run_select(*args); }; });
}

}  // namespace fx::tools
