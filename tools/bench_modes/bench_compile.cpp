// `fxkit bench compile [--effects DIR] [--repeats N] [--json]`: loading the project's
// effects (front end, translation units, glslang, linking) split by phase, the framework's
// overhead against glslang's own time, and a second load of the unchanged effects (SPIR-V
// cache hits) against the first.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "fx/compile/effect_file.h"
#include "fx/compile/effect_programs.h"
#include "fx/compile/spirv_cache.h"
#include "fx/frontend.h"

namespace fx::tools {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct LoadTimes {
  double front_end = 0, units = 0, glslang = 0, link = 0, compile_wall = 0, total = 0;
  size_t shaders = 0, failed = 0;
  double rest() const { return std::max(0.0, compile_wall - glslang - link) + units; }
  double overhead() const { return total - glslang; }  // everything but glslang
  LoadTimes& operator+=(const LoadTimes& o) {
    front_end += o.front_end, units += o.units, glslang += o.glslang, link += o.link;
    compile_wall += o.compile_wall, total += o.total, shaders += o.shaders, failed += o.failed;
    return *this;
  }
};

// One full load: parse, build units, compile and link every pass.
LoadTimes load(const std::string& path, const fx::ShaderCompiler& compiler) {
  LoadTimes t;
  Clock::time_point start = Clock::now();
  fx::DiagnosticSink diags;
  fx::FrontEndOptions options;
  options.preprocessor.include_dirs = {std::filesystem::path(path).parent_path().string()};
  std::unique_ptr<fx::EffectFile> effect = fx::EffectFile::parse(path, options, diags);
  t.front_end = ms_since(start);
  Clock::time_point u0 = Clock::now();
  effect->build_programs(diags, &compiler);
  t.units = ms_since(u0);
  Clock::time_point c0 = Clock::now();
  fx::EffectPrograms& programs = *effect->programs;
  for (const fx::EffectPass& p : effect->units->passes()) {
    const fx::PassProgram& prog = programs.program(p);
    t.shaders += prog.stages.size();
    for (const fx::StageProgram& s : prog.stages) t.failed += !s.shader.ok;
  }
  t.compile_wall = ms_since(c0);
  t.glslang = programs.stats().glslang_ms;
  t.link = programs.stats().link_ms;
  t.total = ms_since(start);
  return t;
}

nlohmann::json to_json(const LoadTimes& t) {
  return {{"front_end_ms", t.front_end}, {"glslang_ms", t.glslang}, {"link_ms", t.link}, {"rest_ms", t.rest()},
          {"total_ms", t.total},         {"shaders", t.shaders},    {"failed", t.failed}};
}

}  // namespace

int bench_compile(const BenchArgs& args) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(args.effects_dir, ec))
    if (e.path().extension() == ".fx") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::fprintf(stderr, "fxkit bench compile: no .fx files in '%s'\n", args.effects_dir.c_str());
    return kUsageError;
  }
  // glslang's first parse in a process builds its built-in symbol tables (~100 ms): pay it
  // before timing, and report it apart.
  Clock::time_point w0 = Clock::now();
  {
    fx::ShaderCompiler warm;
    fx::TranslationUnit u;
    u.source = "float4 main(float4 p : POSITION) : POSITION { return p; }";
    u.profile = "vs_2_0";
    u.entry_point = "main";
    warm.compile(u);
  }
  double warmup = ms_since(w0);

  std::vector<LoadTimes> first_runs, second_runs;
  std::vector<std::pair<std::string, LoadTimes>> per_effect;
  for (int r = 0; r < args.repeats; ++r) {
    LoadTimes first, second;
    for (const std::string& f : files) {
      fx::SpirvCache cache;  // a fresh cache: the first load compiles everything
      fx::ShaderCompiler compiler({}, &cache);
      LoadTimes a = load(f, compiler);
      LoadTimes b = load(f, compiler);  // unchanged effect: every stage is a cache hit
      first += a, second += b;
      if (r == 0) per_effect.emplace_back(f, a);
    }
    first_runs.push_back(first), second_runs.push_back(second);
  }
  auto median = [](std::vector<LoadTimes> v) {
    std::sort(v.begin(), v.end(), [](const LoadTimes& a, const LoadTimes& b) { return a.total < b.total; });
    return v[v.size() / 2];
  };
  LoadTimes first = median(first_runs), second = median(second_runs);
  double overhead_ratio = first.glslang > 0 ? first.overhead() / first.glslang : 0;
  double reload_speedup = second.total > 0 ? first.total / second.total : 0;

  if (args.json) {
    nlohmann::json effects = nlohmann::json::array();
    for (const auto& [f, t] : per_effect) {
      nlohmann::json j = to_json(t);
      j["file"] = f;
      effects.push_back(std::move(j));
    }
    nlohmann::json out = {{"effects_dir", args.effects_dir},
                          {"files", files.size()},
                          {"repeats", args.repeats},
                          {"glslang_warmup_ms", warmup},
                          {"first_load", to_json(first)},
                          {"second_load", to_json(second)},
                          {"overhead_ratio", overhead_ratio},
                          {"overhead_target", 0.10},
                          {"reload_speedup", reload_speedup},
                          {"reload_target", 20.0},
                          {"effects", effects}};
    std::puts(json_text(out).c_str());
  } else {
    std::printf("fxkit bench compile: %zu effect(s) in %s, median of %d run(s); glslang warm-up %.1f ms (excluded)\n",
                files.size(), args.effects_dir.c_str(), args.repeats, warmup);
    for (const auto& [f, t] : per_effect)
      std::printf("  %-40s %3zu shader(s) %2zu failed  front end %7.2f  glslang %8.2f  link %6.2f  rest %6.2f ms\n",
                  f.c_str(), t.shaders, t.failed, t.front_end, t.glslang, t.link, t.rest());
    std::printf("first load:  %.2f ms = front end %.2f + glslang %.2f + link/reflection %.2f + rest %.2f\n",
                first.total, first.front_end, first.glslang, first.link, first.rest());
    std::printf("framework overhead (all but glslang): %.2f ms = %.1f%% of glslang's %.2f ms (target <= 10%%)\n",
                first.overhead(), 100 * overhead_ratio, first.glslang);
    std::printf("second load (unchanged, cache hits): %.3f ms vs first %.2f ms: %.0fx faster (target >= 20x)\n",
                second.total, first.total, reload_speedup);
  }
  return kSuccess;
}

}  // namespace fx::tools
