// `fxkit bench MODE`: benchmarks that measure fxkit against a baseline in the same run and
// print both and their ratio.
#pragma once
#include <algorithm>
#include <vector>

#include "tool_output.h"

namespace fx::tools {

struct BenchArgs {
  std::string mode;     // frontend, ...
  double size_mb = 10;  // frontend: size of the generated effect
  int repeats = 5;
  bool json = false;
  std::string effects_dir = "effects";    // compile, check: the effects to load or check
  std::string seeds_dir = "effects";      // check: the effects loaded through the library
  std::string fxh;                        // accuracy: write technique cost/error annotations here
  std::vector<std::string> only_effects;  // accuracy: measure only these effects' techniques
  std::string merge;                      // accuracy: an earlier --json output the new technique rows replace theirs in
  int processes = 1;                      // > 1: the benchmark in that many fresh processes, median ratio
};

// The middle sample after sorting (the upper of the two for an even count); 0 for none.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
// The median with an even count's two middle samples averaged; 0 for none.
inline double interpolated_median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int bench_frontend(const BenchArgs& args);
// `fxkit bench compile`: effect load time by phase, overhead vs glslang, cached reload.
int bench_compile(const BenchArgs& args);
// `fxkit bench check`: check --compile with 2 jobs vs 1, --cache second run vs first,
// library loads with 2 compile threads vs 1.
int bench_check(const BenchArgs& args);
// `fxkit bench reload`: edit-to-swap latency of hot reload by phase, framework share.
int bench_reload(const BenchArgs& args);
// `fxkit bench apply`: EffectBinding recording vs hand-written Vulkan, ratio, pipeline counts.
int bench_apply(const BenchArgs& args);
// `fxkit bench accuracy`: error vs double reference and GPU ns/pixel per approximation.
int bench_accuracy(const BenchArgs& args);
// `fxkit bench MODE --processes N`: MODE in N fresh processes, the median of their ratios.
int bench_processes(const BenchArgs& args);

}  // namespace fx::tools
