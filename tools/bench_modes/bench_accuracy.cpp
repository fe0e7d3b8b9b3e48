// `fxkit bench accuracy [--repeats N] [--effects DIR] [--json] [--fxh FILE]`: every
// approximation the seed effects make, its error against the double reference
// (lib/fx/shading/approximations.h) and its GPU cost in ns per pixel (Vulkan timestamps,
// empty-shader baseline subtracted); then every technique of every effect measured whole
// (fx/bench/technique_accuracy.h); --fxh writes the technique annotations from those
// (effects/generated/costs.fxh). --effect F [--merge JSON]: only F's techniques measured
// again, the rest of the table taken from an earlier JSON output.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "bench_accuracy.h"
#include "fx/bench/technique_accuracy.h"
#include "fx/diagnostic_render.h"
#include "fx/shading/approximations.h"
#include "fx/source_manager.h"
#include "fx/vulkan/context.h"

namespace fx::tools {
namespace {

constexpr uint32_t kTargetSize = 1024;

// The GPU kernel that carries an error entry's cost: the same id, or the id without the
// parts the shader does not see (exponent baked into the table, term of the same fetch).
std::string kernel_for(const fx::shading::ApproximationError& e) {
  using fx::shading::param;
  if (e.family == "strand_lut")
    return "strand_lut/" + param(e, "index") + "/" + param(e, "format") + "/s" + param(e, "size");
  if (e.family == "strand_mapping") {
    if (param(e, "size") != "256") return {};
    if (param(e, "mapping") == "texel_centre") return "strand_lut/dot/unorm8/s256";
    return "strand_mapping/" + param(e, "mapping") + "/s256";
  }
  if (e.family == "strand_analytic") return "strand_analytic/" + param(e, "form");
  if (e.family == "ln_hn" && param(e, "lobe") == "blinn_phong") return e.id;
  if (e.family == "hemisphere" && param(e, "form") != "cosine_double") return e.id;
  if (e.family == "specular_power" || e.family == "per_vertex" || e.family == "gaussian") return e.id;
  return {};
}

nlohmann::json technique_json(const fx::bench::TechniqueAccuracy& t) {
  nlohmann::json r = {{"effect", t.effect},     {"technique", t.technique}, {"scheme", t.scheme},
                      {"drawable", t.drawable}, {"measured", t.measured},   {"precision_model", t.precision_model}};
  if (!t.emulation.empty()) r["emulation"] = t.emulation;
  if (!t.measured) r["reason"] = t.reason;
  if (t.measured) {
    r["model"] = t.model;
    r["substitutes"] = t.substitutes;
    r["max_error_lsb"] = t.max_error_lsb;
    r["p99_error_lsb"] = t.p99_error_lsb;
    r["rmse_lsb"] = t.rmse_lsb;
    r["pixels_compared"] = t.pixels_compared;
    if (t.precision_model) {
      r["banding_max_lsb"] = t.banding_max_lsb;
      r["banding_rmse_lsb"] = t.banding_rmse_lsb;
    }
  }
  if (t.timed) {
    r["ns_per_pixel"] = t.ns_per_pixel;
    r["ns_per_vertex"] = t.ns_per_vertex;
  }
  return r;
}

// The row technique_json wrote (rows of an earlier run kept by --merge).
fx::bench::TechniqueAccuracy technique_from_json(const nlohmann::json& r) {
  fx::bench::TechniqueAccuracy t;
  t.effect = r.value("effect", "");
  t.technique = r.value("technique", "");
  t.scheme = r.value("scheme", "");
  t.drawable = r.value("drawable", false);
  t.measured = r.value("measured", false);
  t.precision_model = r.value("precision_model", false);
  t.emulation = r.value("emulation", "");
  t.reason = r.value("reason", "");
  t.model = r.value("model", "");
  t.substitutes = r.value("substitutes", "");
  t.max_error_lsb = r.value("max_error_lsb", 0.0);
  t.p99_error_lsb = r.value("p99_error_lsb", 0.0);
  t.rmse_lsb = r.value("rmse_lsb", 0.0);
  t.pixels_compared = r.value("pixels_compared", size_t(0));
  t.banding_max_lsb = r.value("banding_max_lsb", 0.0);
  t.banding_rmse_lsb = r.value("banding_rmse_lsb", 0.0);
  t.timed = r.contains("ns_per_pixel");
  t.ns_per_pixel = r.value("ns_per_pixel", 0.0);
  t.ns_per_vertex = r.value("ns_per_vertex", 0.0);
  return t;
}

// The earlier run's technique rows with the effects measured now replaced by the new rows
// (at the place of the effect's first old row; an effect new to the table at the end).
std::vector<fx::bench::TechniqueAccuracy> merged_rows(const nlohmann::json& earlier,
                                                      const std::vector<fx::bench::TechniqueAccuracy>& now,
                                                      const std::vector<std::string>& effects) {
  std::vector<fx::bench::TechniqueAccuracy> out;
  auto remeasured = [&](const std::string& e) { return std::find(effects.begin(), effects.end(), e) != effects.end(); };
  std::vector<std::string> placed;
  auto place = [&](const std::string& effect) {
    if (std::find(placed.begin(), placed.end(), effect) != placed.end()) return;
    placed.push_back(effect);
    for (const auto& t : now)
      if (t.effect == effect) out.push_back(t);
  };
  for (const nlohmann::json& r : earlier["techniques"]) {
    const std::string effect = r.value("effect", "");
    if (remeasured(effect)) place(effect);
    else out.push_back(technique_from_json(r));
  }
  for (const std::string& e : effects) place(e);
  return out;
}

// "1.23 4.56 7.89": the 1, 5 and 15 minute load averages (the machine may be shared while
// timing); "" where /proc/loadavg does not exist.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return in ? a + " " + b + " " + c : std::string();
}

// The annotation macros: COST_<technique> for every technique of every effect.
void write_fxh(const std::string& path, const std::vector<fx::bench::TechniqueAccuracy>& techniques,
               const std::string& device, const fx::bench::TechniqueAccuracyOptions& o) {
  std::ofstream f(path);
  f << "// GENERATED by `scripts/accuracy-report` (fxkit bench accuracy --fxh); do not edit.\n"
       "// Per technique (fxkit bench accuracy --json, `techniques`): cost on "
    << device
    << ", GPU ns per\n"
       "// covered pixel (pixel stage) and per vertex (vertex stage), medians of "
    << o.repeats
    << " timed frames of\n"
       "// "
    << o.draws
    << " draws, the empty technique subtracted; error: max |technique - double reference|\n"
       "// in 8-bit levels, both clamped to [0,1] as a UNORM target stores them, over the scene set\n"
       "// (docs/accuracy.md). A technique that could not be\n"
       "// measured carries ErrorNotMeasured with the reason, and selection treats its error as unknown.\n"
       "// Substitutes: the techniques measured against the same model (errors rank within it).\n"
       "// Ps1xPrecision*: the same technique compiled with the ps.1.x precision model (informative;\n"
       "// selection ranks the technique as compiled by default).\n"
       "#ifndef FXKIT_GENERATED_COSTS_FXH\n#define FXKIT_GENERATED_COSTS_FXH\n";
  for (const fx::bench::TechniqueAccuracy& t : techniques) {
    // A precision-model row is the technique under a compile option: its figures go beside
    // the default row's, which selection reads.
    if (t.precision_model) continue;
    f << "// " << t.effect << " " << t.technique << "\n";
    if (t.measured && t.timed) {
      char line[320];
      std::snprintf(line, sizeof line,
                    "#define COST_%s float CostNsPerPixel = %.3f; float CostNsPerVertex = %.3f; float MaxError = %.2f;",
                    t.technique.c_str(), std::max(0.0, t.ns_per_pixel), std::max(0.0, t.ns_per_vertex),
                    t.max_error_lsb);
      f << line;
      if (!t.substitutes.empty()) f << " string Substitutes = \"" << t.substitutes << "\";";
      for (const fx::bench::TechniqueAccuracy& p : techniques)
        if (p.precision_model && p.measured && p.timed && p.effect == t.effect && p.technique == t.technique) {
          std::snprintf(line, sizeof line,
                        " float Ps1xPrecisionMaxError = %.2f; float Ps1xPrecisionCostNsPerPixel = %.3f;",
                        p.max_error_lsb, std::max(0.0, p.ns_per_pixel));
          f << line;
        }
      f << "\n";
    } else {
      std::string reason = t.measured ? std::string("not timed") : t.reason;
      for (char& c : reason)
        if (c == '"' || c == '\n') c = '\'';
      f << "#define COST_" << t.technique << " string ErrorNotMeasured = \"" << reason << "\";\n";
    }
  }
  f << "#endif\n";
}

nlohmann::json stats_json(const fx::shading::ErrorStats& s) {
  return {{"count", s.count},
          {"non_finite", s.non_finite},
          {"max_abs", s.max_abs},
          {"rmse", s.rmse},
          {"max_lsb8", s.max_lsb8}};
}

}  // namespace

int bench_accuracy(const BenchArgs& args) {
  fx::DiagnosticSink sink;
  nlohmann::json out;
  // --merge: the approximation rows and the other effects' technique rows come from an
  // earlier run; only the named effects' techniques are measured again.
  nlohmann::json earlier;
  if (!args.merge.empty()) {
    std::ifstream in(args.merge);
    earlier = nlohmann::json::parse(in, nullptr, false);
    if (!in || earlier.is_discarded() || !earlier.contains("techniques") || !earlier.contains("approximations")) {
      std::fprintf(stderr, "fxkit bench accuracy: --merge %s is not an earlier --json output\n", args.merge.c_str());
      return kUsageError;
    }
    if (args.only_effects.empty()) {
      std::fprintf(stderr, "fxkit bench accuracy: --merge needs --effect (the effects to measure again)\n");
      return kUsageError;
    }
    for (const char* key : {"command", "device", "samples", "approximations", "kernels", "technique_runs"})
      if (earlier.contains(key)) out[key] = earlier[key];
  } else {
    fx::shading::ApproximationOptions options;
    std::vector<fx::shading::ApproximationError> errors = fx::shading::measure_approximations(options);
    std::optional<GpuRun> gpu = time_kernels(accuracy_kernels(kTargetSize), kTargetSize, args.repeats, sink);
    if (!gpu || sink.error_count() > 0 || gpu->validation_messages > 0) {
      std::fprintf(stderr, "%s", fx::render_text(sink.diagnostics(), fx::SourceManager{}).c_str());
      return 1;
    }
    std::map<std::string, const GpuTiming*> timing;
    for (const GpuTiming& t : gpu->timings) timing[t.id] = &t;
    out["command"] = "fxkit bench accuracy --repeats " + std::to_string(args.repeats) + " --json";
    out["device"] = {{"name", gpu->device},
                     {"target", std::to_string(gpu->width) + "x" + std::to_string(gpu->height)},
                     {"draws_per_pass", gpu->draws},
                     {"repeats", gpu->repeats},
                     {"timestamp_period_ns", gpu->timestamp_period_ns},
                     {"timestamp_valid_bits", gpu->timestamp_valid_bits},
                     {"validation_messages", gpu->validation_messages}};
    out["samples"] = {{"uniform", options.samples.uniform},
                      {"near_degenerate_angles", "1e-1 .. 1e-8 rad, 2 per decade"}};
    nlohmann::json& rows = out["approximations"];
    rows = nlohmann::json::array();
    for (const auto& e : errors) {
      nlohmann::json r = {{"id", e.id},
                          {"family", e.family},
                          {"description", e.description},
                          {"error", stats_json(e.all)},
                          {"near_degenerate", stats_json(e.near_degenerate)}};
      for (const auto& [k, v] : e.params) r["params"][k] = v;
      std::string k = kernel_for(e);
      if (auto it = timing.find(k); !k.empty() && it != timing.end()) {
        r["kernel"] = k;
        r["ns_per_pixel"] = it->second->ns_per_pixel;
      } else {
        r["ns_per_pixel"] = nullptr;
      }
      rows.push_back(std::move(r));
    }
    nlohmann::json& kernels = out["kernels"];
    kernels = nlohmann::json::array();
    for (const GpuTiming& t : gpu->timings)
      kernels.push_back(
          {{"id", t.id}, {"median_ms", t.median_ms}, {"baseline_ms", t.baseline_ms}, {"ns_per_pixel", t.ns_per_pixel}});
    out["technique_runs"] = nlohmann::json::array();
  }
  fx::bench::TechniqueAccuracyOptions topt;
  topt.effects_dir = args.effects_dir;
  topt.repeats = args.repeats;
  topt.only = args.only_effects;
  const std::string load_before = load_average();
  std::optional<std::vector<fx::bench::TechniqueAccuracy>> techniques;
  {
    fx::vk::ContextOptions co;
    co.validation = true;
    auto ctx = fx::vk::Context::headless(co, sink);
    if (ctx) techniques = fx::bench::measure_techniques(*ctx, topt, sink);
    if (ctx && ctx->validation_messages().size() > 0) ctx->drain_validation_into(sink);
  }
  if (!techniques || sink.error_count() > 0) {
    std::fprintf(stderr, "%s", fx::render_text(sink.diagnostics(), fx::SourceManager{}).c_str());
    return 1;
  }
  if (!earlier.is_null()) *techniques = merged_rows(earlier, *techniques, args.only_effects);
  out["technique_runs"].push_back(
      {{"effects", args.only_effects.empty() ? nlohmann::json("all") : nlohmann::json(args.only_effects)},
       {"repeats", args.repeats},
       {"load_average_before", load_before},
       {"load_average_after", load_average()}});

  nlohmann::json& trows = out["techniques"];
  trows = nlohmann::json::array();
  for (const auto& t : *techniques) trows.push_back(technique_json(t));
  out["technique_scenes"] = {
      {"scene_set", fx::bench::describe_scene_set()},
      {"error_target", std::to_string(topt.error_size) + "x" + std::to_string(topt.error_size)},
      {"timing_target", std::to_string(topt.timing_size) + "x" + std::to_string(topt.timing_size)},
      {"draws_per_frame", topt.draws},
      {"repeats", topt.repeats}};
  if (!args.fxh.empty()) write_fxh(args.fxh, *techniques, out["device"].value("name", ""), topt);

  if (args.json) {
    std::printf("%s\n", json_text(out, 1).c_str());
    return 0;
  }
  const nlohmann::json& device = out["device"];
  std::printf("accuracy: %zu approximations on %s (%s, %d draws/pass, median of %d)\n", out["approximations"].size(),
              device.value("name", "").c_str(), device.value("target", "").c_str(), device.value("draws_per_pass", 0),
              device.value("repeats", 0));
  std::printf("%-44s %11s %11s %9s %9s\n", "approximation", "max-abs", "rmse", "LSB8", "ns/pixel");
  for (const nlohmann::json& r : out["approximations"]) {
    char cost[32] = "-";
    if (!r["ns_per_pixel"].is_null()) std::snprintf(cost, sizeof cost, "%.3f", r["ns_per_pixel"].get<double>());
    std::printf("%-44s %11.3g %11.3g %9.2f %9s\n", r["id"].get<std::string>().c_str(),
                r["error"]["max_abs"].get<double>(), r["error"]["rmse"].get<double>(),
                r["error"]["max_lsb8"].get<double>(), cost);
  }
  std::printf("\n%-24s %-34s %9s %9s %9s %9s %9s\n", "effect", "technique", "max LSB", "p99 LSB", "RMSE LSB",
              "ns/pixel", "ns/vertex");
  for (const auto& t : *techniques) {
    if (!t.measured) {
      std::printf("%-24s %-34s not measured: %s\n", t.effect.c_str(), t.technique.c_str(), t.reason.c_str());
      continue;
    }
    const std::string name = t.technique + (t.precision_model ? " (ps.1.x precision)" : "");
    std::printf("%-24s %-34s %9.2f %9.2f %9.2f %9.3f %9.3f\n", t.effect.c_str(), name.c_str(), t.max_error_lsb,
                t.p99_error_lsb, t.rmse_lsb, t.ns_per_pixel, t.ns_per_vertex);
  }
  return 0;
}

}  // namespace fx::tools
