// `fxkit bench reload [--effects DIR] [--repeats N] [--json]`: edit-to-swap latency of hot
// reload over 50 edits of the seed effects (round robin), split into detect / parse /
// compile / pipeline / first frame. Each edit appends a new function to the effect, so the
// shared shader text changes and every stage goes back through glslang (the realistic
// worst case: an edit to shader code). The baseline is glslang's own time for the same
// units; the framework's share is everything except glslang and the driver's work.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "fx/reload/effect_library.h"

namespace fxkit {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Sample {
  double edit_to_swap = 0;  // save -> poll() returned the reloaded event
  fx::ReloadTimings ms;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
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

}  // namespace

int bench_reload(const BenchArgs& args) {
  const int reloads = 50;
  fs::path scratch = fs::temp_directory_path() / ("fxkit_bench_reload_" + std::to_string(::getpid()));
  std::error_code ec;
  fs::remove_all(scratch, ec);
  fs::create_directories(scratch / "mesa_cache", ec);
  // Driver caches would hide the cost of a cold pipeline; keep them per run.
  ::setenv("MESA_SHADER_CACHE_DIR", (scratch / "mesa_cache").c_str(), 1);
  std::vector<fs::path> effects;
  for (const auto& entry : fs::directory_iterator(args.effects_dir, ec)) {
    if (entry.is_regular_file()) fs::copy_file(entry.path(), scratch / entry.path().filename(), ec);
    if (entry.path().extension() == ".fx") effects.push_back(scratch / entry.path().filename());
  }
  std::sort(effects.begin(), effects.end());
  if (effects.empty()) {
    std::fprintf(stderr, "fxkit bench reload: no .fx files in '%s'\n", args.effects_dir.c_str());
    return kUsageError;
  }

  fx::EffectLibraryOptions options;
  options.include_dirs = {scratch.string()};
  options.coalesce = std::chrono::milliseconds(0);  // latency of the machinery, not of the window
  fx::EffectLibrary lib(std::move(options));
  std::vector<fx::EffectHandle> handles;
  std::vector<std::string> texts;
  for (const fs::path& p : effects) {
    handles.push_back(lib.load(p.string()));
    texts.push_back(read(p));
    if (!handles.back().ok()) {
      std::fprintf(stderr, "fxkit bench reload: %s does not load; skipped\n", p.c_str());
    }
  }

  std::vector<Sample> samples;
  int failures = 0, timeouts = 0;
  for (int i = 0, k = 0; i < reloads && k < reloads * 4; ++k) {
    size_t e = static_cast<size_t>(k) % effects.size();
    if (!handles[e].ok()) continue;
    texts[e] += "\nfloat fxkit_bench_edit_" + std::to_string(i) + "() { return " + std::to_string(i) + ".0; }\n";
    Clock::time_point edit = Clock::now();
    save(effects[e], texts[e]);
    std::vector<fx::ReloadEvent> got;
    Clock::time_point deadline = edit + std::chrono::seconds(30);
    while (got.empty() && Clock::now() < deadline) {
      if (lib.wait(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now())))
        got = lib.poll();
    }
    Clock::time_point swapped = Clock::now();
    ++i;
    if (got.empty()) {
      ++timeouts;
      continue;
    }
    if (got[0].kind != fx::ReloadEventKind::reloaded) {
      ++failures;
      continue;
    }
    samples.push_back({std::chrono::duration<double, std::milli>(swapped - edit).count(), got[0].ms});
  }

  std::vector<double> total, detect, parse, compile, glslang, pipeline, first, framework;
  for (const Sample& s : samples) {
    total.push_back(s.edit_to_swap);
    detect.push_back(s.ms.detect);
    parse.push_back(s.ms.parse);
    compile.push_back(s.ms.compile);
    glslang.push_back(s.ms.glslang);
    pipeline.push_back(s.ms.pipeline);
    first.push_back(s.ms.first_frame);
    framework.push_back(s.edit_to_swap - s.ms.glslang - s.ms.pipeline - s.ms.first_frame);
  }
  double share = median(total) > 0 ? median(framework) / median(total) : 0;
  double ratio = median(glslang) > 0 ? median(total) / median(glslang) : 0;
  fs::remove_all(scratch, ec);

  if (args.json) {
    nlohmann::json j = {{"reloads", samples.size()},
                        {"failures", failures},
                        {"timeouts", timeouts},
                        {"effects", effects.size()},
                        {"median_ms",
                         {{"total", median(total)}, {"detect", median(detect)}, {"parse", median(parse)},
                          {"compile", median(compile)}, {"glslang", median(glslang)},
                          {"pipeline", median(pipeline)}, {"first_frame", median(first)},
                          {"framework", median(framework)}}},
                        {"max_ms", {{"total", maximum(total)}, {"framework", maximum(framework)}}},
                        {"framework_share", share},
                        {"baseline", "glslang time of the same units"},
                        {"ratio_to_baseline", ratio},
                        {"backend", "none (Vulkan effect binding not wired: pipeline and first_frame are 0)"}};
    std::printf("%s\n", json_text(j).c_str());
  } else {
    std::printf("fxkit bench reload: %zu reloads of %zu seed effects (%d failed, %d timed out), coalescing 0 ms\n",
                samples.size(), effects.size(), failures, timeouts);
    std::printf("  edit -> swap   median %7.2f ms  max %7.2f ms\n", median(total), maximum(total));
    std::printf("  detect         median %7.2f ms  max %7.2f ms\n", median(detect), maximum(detect));
    std::printf("  parse+model    median %7.2f ms  max %7.2f ms\n", median(parse), maximum(parse));
    std::printf("  compile        median %7.2f ms  max %7.2f ms  (glslang %7.2f ms median)\n", median(compile),
                maximum(compile), median(glslang));
    std::printf("  pipeline       median %7.2f ms  first frame median %7.2f ms  (no GPU backend wired)\n",
                median(pipeline), median(first));
    std::printf("  framework      median %7.2f ms  max %7.2f ms  = %.1f%% of edit -> swap (target <= 10%%)\n",
                median(framework), maximum(framework), 100 * share);
    std::printf("  baseline: glslang alone %.2f ms median; edit -> swap is %.2fx the baseline\n", median(glslang),
                ratio);
  }
  return failures || timeouts ? kInputErrors : kSuccess;
}

}  // namespace fxkit
