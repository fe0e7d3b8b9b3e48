// `fxkit bench check [--effects DIR] [--seeds DIR] [--repeats N] [--json]`: the validator
// at scale, three ratios measured in one process after a glslang warm-up:
//   1. `fxkit check --compile` over every effect in --effects DIR with 2 jobs against 1;
//   2. a second `--cache` run over the unchanged folder against the first (cold) one;
//   3. loading the effects in --seeds DIR through fx::EffectLibrary with a compile pool of
//      2 threads against 1 (no GPU backend: parse, model, glslang, linking, selection).
// Every compile starts from an empty SPIR-V cache, so each run does all of glslang's work.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "check_cache.h"
#include "check_inputs.h"
#include "effect_check.h"
#include "fx/compile/spirv_cache.h"
#include "fx/reload/effect_library.h"
#include "fx/worker_pool.h"

namespace fx::tools {
namespace {

using BenchClock = std::chrono::steady_clock;
double seconds_since(BenchClock::time_point t) { return std::chrono::duration<double>(BenchClock::now() - t).count(); }

// One `fxkit check --compile --jobs N [--cache DIR]` over `files`, in seconds.
double timed_check(const std::vector<std::string>& files, size_t jobs, CheckCache* cache, size_t* failed = nullptr) {
  fx::SpirvCache spirv(cache ? cache->spirv_directory() : std::filesystem::path());
  fx::ShaderCompiler compiler({}, &spirv);
  fx::WorkerPool pool(jobs);
  EffectCheckSettings settings;
  settings.compiler = &compiler;
  settings.executor = &pool;
  std::vector<EffectCheck> results;
  BenchClock::time_point start = BenchClock::now();
  check_effects(files, settings, cache, results);
  double s = seconds_since(start);
  if (failed) {
    *failed = 0;
    for (const EffectCheck& c : results) *failed += c.failed() ? 1 : 0;
  }
  return s;
}

// Every effect of `files` loaded through a fresh library with `threads` compile threads.
double timed_library_load(const std::vector<std::string>& files, uint32_t threads, size_t* ok = nullptr) {
  BenchClock::time_point start = BenchClock::now();
  fx::EffectLibraryOptions options;
  options.watch = false;
  options.compile_threads = threads;
  fx::EffectLibrary library(std::move(options));
  std::vector<fx::EffectHandle> handles = library.load(files);
  double s = seconds_since(start);
  if (ok) {
    *ok = 0;
    for (const fx::EffectHandle& h : handles) *ok += h.ok() ? 1 : 0;
  }
  return s;
}

struct Ratio {
  double baseline = 0, measured = 0, target = 0;
  double value() const { return measured > 0 ? baseline / measured : 0; }
  nlohmann::json json() const {
    return {{"baseline_s", baseline}, {"measured_s", measured}, {"ratio", value()}, {"target", target}};
  }
};

}  // namespace

int bench_check(const BenchArgs& args) {
  CheckInputs corpus, seeds;
  std::string error;
  if (!find_check_inputs({args.effects_dir}, {}, corpus, error) ||
      !find_check_inputs({args.seeds_dir}, {}, seeds, error)) {
    std::fprintf(stderr, "fxkit bench check: %s\n", error.c_str());
    return kUsageError;
  }
  size_t failed = 0, loaded = 0;
  timed_check(corpus.files, 2, nullptr, &failed);  // glslang's process-wide tables, once
  std::vector<double> one, two, cold, warm, lib_one, lib_two;
  for (int r = 0; r < args.repeats; ++r) {
    one.push_back(timed_check(corpus.files, 1, nullptr));
    two.push_back(timed_check(corpus.files, 2, nullptr));
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("fxkit-bench-check-" + std::to_string(::getpid()) + "-" + std::to_string(r));
    std::filesystem::remove_all(dir);
    CheckCache first(dir, "bench", uint64_t{1} << 30), second(dir, "bench", uint64_t{1} << 30);
    cold.push_back(timed_check(corpus.files, 2, &first));
    warm.push_back(timed_check(corpus.files, 2, &second));
    std::filesystem::remove_all(dir);
    lib_one.push_back(timed_library_load(seeds.files, 1, &loaded));
    lib_two.push_back(timed_library_load(seeds.files, 2));
  }
  Ratio jobs{median(one), median(two), 1.8}, cache{median(cold), median(warm), 20},
      library{median(lib_one), median(lib_two), 1.7};
  if (args.json) {
    nlohmann::json out = {{"effects_dir", args.effects_dir},
                          {"files", corpus.files.size()},
                          {"files_failing", failed},
                          {"seeds_dir", args.seeds_dir},
                          {"seed_effects", seeds.files.size()},
                          {"seed_effects_loaded", loaded},
                          {"repeats", args.repeats},
                          {"jobs_2_vs_1", jobs.json()},
                          {"cache_second_vs_first", cache.json()},
                          {"library_pool_2_vs_1", library.json()}};
    std::puts(json_text(out).c_str());
    return kSuccess;
  }
  std::printf(
      "fxkit bench check: %zu effect(s) in %s (%zu failing), %zu seed effect(s) in %s (%zu load), "
      "median of %d run(s), %zu hardware thread(s)\n",
      corpus.files.size(), args.effects_dir.c_str(), failed, seeds.files.size(), args.seeds_dir.c_str(), loaded,
      args.repeats, fx::WorkerPool::hardware_threads());
  std::printf("check --compile --jobs 2: %.3f s vs --jobs 1 %.3f s: %.2fx (target >= %.1fx)\n", jobs.measured,
              jobs.baseline, jobs.value(), jobs.target);
  std::printf("check --cache, second run (unchanged): %.4f s vs first %.3f s: %.1fx (target >= %.0fx)\n",
              cache.measured, cache.baseline, cache.value(), cache.target);
  std::printf("EffectLibrary::load, compile_threads 2: %.3f s vs 1 %.3f s: %.2fx (target >= %.1fx)\n", library.measured,
              library.baseline, library.value(), library.target);
  return kSuccess;
}

}  // namespace fx::tools
