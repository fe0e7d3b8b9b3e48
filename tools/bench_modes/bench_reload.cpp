// `fxkit bench reload [--effects DIR] [--repeats N] [--json]`: edit-to-first-new-frame
// latency of hot reload over 50 edits of the seed effects (round robin), split into detect /
// parse / compile / pipeline / first frame, with the Vulkan backend building each new
// version's pipelines and a headless frame drawn with it; once with glslang in this process
// and once in compile worker processes (the default of the tools and of fxkit::Device), in
// the same run (alternating series of 25 edits), with the difference of their medians. Each edit appends a new function
// to the effect, so the shared shader text changes and every stage goes back through
// glslang (the realistic worst case: an edit to shader code). The baseline is glslang's own
// time for the same units; the framework's share is everything except glslang and the
// driver's work (pipeline creation and the first draw).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>
#include <optional>

#include "bench.h"
#include "fx/binding/effect_preview.h"
#include "fx/compile/compile_workers.h"
#include "fx/mesh.h"
#include "fx/model/parameter_store.h"
#include "fx/reload/effect_library.h"
#include "fx/reload/reload_transaction.h"
#include "fx/reload/vulkan_reload_backend.h"

namespace fx::tools {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Sample {
  double edit_to_frame = 0;  // save -> the first frame drawn with the new version
  fx::ReloadTimings ms;      // first_frame filled in here: the render thread draws it
};

double maximum(const std::vector<double>& v) { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); }

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Write a temp sibling and rename it over: one MOVED_TO, as most editors save.
void save(const fs::path& file, const std::string& text) {
  fs::path temp = file;
  temp += ".bench-tmp";
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out << text;
  }
  fs::rename(temp, file);
}

// One series of edits, with glslang where `workers` says.
struct ReloadRun {
  std::vector<Sample> samples;
  int failures = 0, timeouts = 0;
  size_t effects = 0;
  std::string device;
  double worker_start_ms = 0, worker_warm_up_ms = 0;  // the pool's last worker start, and its warm-up
};

// Appends `reloads` edits' samples to `run`.
bool measure_reloads(const BenchArgs& args, const std::optional<fx::CompileWorkerOptions>& workers, int reloads,
                     ReloadRun& run) {
  fs::path scratch = fs::temp_directory_path() / ("fxkit_bench_reload_" + std::to_string(::getpid()));
  std::error_code ec;
  fs::remove_all(scratch, ec);
  fs::create_directories(scratch / "mesa_cache", ec);
  // Driver caches would hide the cost of a cold pipeline; keep them per run.
  ::setenv("MESA_SHADER_CACHE_DIR", (scratch / "mesa_cache").c_str(), 1);
  std::vector<fs::path> effects;
  // The whole folder: effects include headers from it and its subfolders.
  fs::copy(args.effects_dir, scratch, fs::copy_options::recursive | fs::copy_options::overwrite_existing, ec);
  for (const auto& entry : fs::directory_iterator(scratch, ec))
    if (entry.is_regular_file() && entry.path().extension() == ".fx") effects.push_back(entry.path());
  std::sort(effects.begin(), effects.end());
  if (effects.empty()) {
    std::fprintf(stderr, "fxkit bench reload: no .fx files in '%s'\n", args.effects_dir.c_str());
    return false;
  }

  fx::EffectLibraryOptions options;
  options.include_dirs = {scratch.string()};
  options.coalesce = std::chrono::milliseconds(0);  // latency of the machinery, not of the window
  options.compile_workers = workers;
  // The GPU side: a headless device, a sphere framed by the camera, a binding per version.
  fx::DiagnosticSink gpu_sink;
  auto mesh = fx::make_mesh("sphere", gpu_sink);
  std::optional<fx::vk::Context> ctx;
  if (mesh) ctx = fx::vk::Context::headless({}, gpu_sink);
  std::unique_ptr<fx::vk::EffectPreview> preview;
  if (ctx) preview = fx::vk::EffectPreview::create(*ctx, *mesh, {}, gpu_sink);
  if (!preview) {
    for (const fx::Diagnostic& d : gpu_sink.diagnostics())
      std::fprintf(stderr, "fxkit bench reload: %s [%s]\n", d.message.c_str(), d.id.c_str());
    return false;
  }
  fx::vk::EffectPreview* p = preview.get();
  fx::vk::ReloadBackend backend(
      *ctx, preview->textures(), preview->frames(),
      fx::vk::ReloadBackendDesc{preview->formats(), preview->binding_desc(),
                                [p](std::span<const fx::InterfaceVariable> in) { return p->vertex_layout(in); }});
  options.backend = &backend;
  fx::EffectLibrary lib(std::move(options));
  if (workers && !lib.compile_workers()) {
    std::fprintf(stderr, "fxkit bench reload: compile workers: %s\n", lib.compile_workers_error().c_str());
    return false;
  }
  // Draws one frame of an effect's live version; false if it has nothing drawable.
  auto draw = [&](fx::EffectHandle& effect) {
    auto version = effect.version();
    fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
    if (!binding) return false;
    uint32_t technique = effect.technique();
    if (!binding->technique_ok(technique)) technique = binding->first_ok_technique();
    if (technique == fx::kNoIndex) return false;
    fx::vk::set_standard_semantics(*effect.params(), *version->model, preview->scene());
    fx::DiagnosticSink sink;
    return preview->render(*binding, technique, 0, sink).has_value();
  };
  std::vector<fx::EffectHandle> handles;
  std::vector<std::string> texts;
  for (const fs::path& p : effects) {
    handles.push_back(lib.load(p.string()));
    texts.push_back(read(p));
    if (!handles.back().ok()) {
      std::fprintf(stderr, "fxkit bench reload: %s does not load; skipped\n", p.c_str());
    } else {
      handles.back().select();
      draw(handles.back());  // the first version's pipelines and draw, outside the timing
    }
  }

  std::vector<Sample>& samples = run.samples;
  int& failures = run.failures;
  int& timeouts = run.timeouts;
  for (int i = 0, k = 0; i < reloads && k < reloads * 4; ++k) {
    size_t e = static_cast<size_t>(k) % effects.size();
    if (!handles[e].ok()) continue;
    texts[e] += "\nfloat fxkit_bench_edit_" + std::to_string(i) + "() { return " + std::to_string(i) + ".0; }\n";
    Clock::time_point edit = Clock::now();
    save(effects[e], texts[e]);
    std::vector<fx::ReloadEvent> got;
    Clock::time_point deadline = edit + std::chrono::seconds(30);
    while (got.empty() && Clock::now() < deadline) {
      if (lib.wait(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()))) got = lib.poll();
    }
    ++i;
    if (got.empty()) {
      ++timeouts;
      continue;
    }
    if (got[0].kind != fx::ReloadEventKind::reloaded) {
      ++failures;
      continue;
    }
    Clock::time_point swapped = Clock::now();
    if (!draw(handles[e])) {
      ++failures;
      continue;
    }
    Clock::time_point drawn = Clock::now();
    Sample s{std::chrono::duration<double, std::milli>(drawn - edit).count(), got[0].ms};
    s.ms.first_frame = std::chrono::duration<double, std::milli>(drawn - swapped).count();
    samples.push_back(s);
  }
  run.effects = effects.size();
  run.device = ctx->info().name;
  if (lib.compile_workers()) {
    run.worker_start_ms = lib.compile_workers()->stats().start_ms;
    run.worker_warm_up_ms = lib.compile_workers()->stats().warm_up_ms;
  }
  fs::remove_all(scratch, ec);
  return true;
}

// The medians of one run, as JSON.
struct Medians {
  std::vector<double> total, detect, parse, compile, glslang, pipeline, first, framework;

  explicit Medians(const std::vector<Sample>& samples) {
    for (const Sample& s : samples) {
      total.push_back(s.edit_to_frame);
      detect.push_back(s.ms.detect);
      parse.push_back(s.ms.parse);
      compile.push_back(s.ms.compile);
      glslang.push_back(s.ms.glslang);
      pipeline.push_back(s.ms.pipeline);
      first.push_back(s.ms.first_frame);
      framework.push_back(s.edit_to_frame - s.ms.glslang - s.ms.pipeline - s.ms.first_frame);
    }
  }
  double share() const { return median(total) > 0 ? median(framework) / median(total) : 0; }
  double ratio() const { return median(glslang) > 0 ? median(total) / median(glslang) : 0; }
};

nlohmann::json run_json(const ReloadRun& run) {
  Medians m(run.samples);
  return {{"reloads", run.samples.size()},
          {"failures", run.failures},
          {"timeouts", run.timeouts},
          {"effects", run.effects},
          {"median_ms",
           {{"total", median(m.total)},
            {"detect", median(m.detect)},
            {"parse", median(m.parse)},
            {"compile", median(m.compile)},
            {"glslang", median(m.glslang)},
            {"pipeline", median(m.pipeline)},
            {"first_frame", median(m.first)},
            {"framework", median(m.framework)}}},
          {"max_ms", {{"total", maximum(m.total)}, {"framework", maximum(m.framework)}}},
          {"framework_share", m.share()},
          {"baseline", "glslang time of the same units"},
          {"ratio_to_baseline", m.ratio()},
          {"device", run.device}};
}

void print_run(const char* where, const ReloadRun& run) {
  Medians m(run.samples);
  std::printf("glslang %s: %zu reloads of %zu seed effects (%d failed, %d timed out)\n", where, run.samples.size(),
              run.effects, run.failures, run.timeouts);
  std::printf("  edit -> frame  median %7.2f ms  max %7.2f ms\n", median(m.total), maximum(m.total));
  std::printf("  detect         median %7.2f ms  max %7.2f ms\n", median(m.detect), maximum(m.detect));
  std::printf("  parse+model    median %7.2f ms  max %7.2f ms\n", median(m.parse), maximum(m.parse));
  std::printf("  compile        median %7.2f ms  max %7.2f ms  (glslang %7.2f ms median)\n", median(m.compile),
              maximum(m.compile), median(m.glslang));
  std::printf("  pipeline       median %7.2f ms  first frame median %7.2f ms\n", median(m.pipeline), median(m.first));
  std::printf("  framework      median %7.2f ms  max %7.2f ms  = %.1f%% of edit -> frame (target <= 10%%)\n",
              median(m.framework), maximum(m.framework), 100 * m.share());
  std::printf("  baseline: glslang alone %.2f ms median; edit -> frame is %.2fx the baseline\n", median(m.glslang),
              m.ratio());
}

}  // namespace

int bench_reload(const BenchArgs& args) {
  ReloadRun here, workers;
  // 50 edits each way, in alternating series of 25, so a change in the machine's load during
  // the run falls on both.
  for (int series = 0; series < 2; ++series)
    if (!measure_reloads(args, std::nullopt, 25, here) ||
        !measure_reloads(args, fx::CompileWorkerOptions{}, 25, workers))
      return kUsageError;
  const double difference = median(Medians(workers.samples).total) - median(Medians(here.samples).total);
  // The part the workers change (the rest is the same code on both sides).
  const double compile_difference = median(Medians(workers.samples).compile) - median(Medians(here.samples).compile);
  if (args.json) {
    nlohmann::json j = run_json(workers);
    j["in_process"] = run_json(here);
    j["workers_minus_in_process_ms"] = difference;
    j["workers_minus_in_process_compile_ms"] = compile_difference;
    j["worker_start_ms"] = workers.worker_start_ms;
    j["worker_warm_up_ms"] = workers.worker_warm_up_ms;
    std::printf("%s\n", json_text(j).c_str());
  } else {
    std::printf("fxkit bench reload on %s, coalescing 0 ms\n", workers.device.c_str());
    print_run("in this process", here);
    print_run("in compile workers", workers);
    std::printf("  workers - in-process: %+.2f ms median edit -> frame (target within 2 ms), %+.2f ms median compile\n",
                difference, compile_difference);
    std::printf("  a worker starts in %.1f ms, then warms glslang up in %.1f ms (once, at the first compile)\n",
                workers.worker_start_ms, workers.worker_warm_up_ms);
  }
  const bool failed = here.failures || here.timeouts || workers.failures || workers.timeouts;
  return failed ? kInputErrors : kSuccess;
}

}  // namespace fx::tools
