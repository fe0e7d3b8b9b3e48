// Per-object technique selection cost: 10,000 objects per frame through a compiled
// SelectionPlan (with hysteresis state), against the baseline an engine would write without
// precomputation: reading the annotations of every technique for every object.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <thread>

#include "fx/select/selection.h"

namespace {

constexpr size_t kObjects = 10000;

using Ann = std::initializer_list<std::pair<std::string, fx::AnnotationValue>>;

fx::TechniqueCandidate tech(std::string name, Ann annotations, bool valid = true) {
  fx::TechniqueCandidate t;
  t.name = std::move(name);
  t.annotations = fx::AnnotationMap(annotations);
  t.valid = valid;
  return t;
}

// An effect with the usual spread: LOD bands, two schemes, costs, errors, a fallback.
std::vector<fx::TechniqueCandidate> effect() {
  return {
      tech("sm3_quality",
           {{"Scheme", std::string("quality")},
            {"MaxDistance", 15.f},
            {"CostMs", 0.02f},
            {"Fallback", std::string("sm2_near")}},
           false),
      tech("sm2_near",
           {{"Scheme", std::string("quality")}, {"MaxDistance", 25.f}, {"MaxError", 0.5f}, {"CostNsPerPixel", 0.8f}}),
      tech("sm2_mid", {{"MinDistance", 20.f}, {"MaxDistance", 80.f}, {"MaxError", 1.5f}, {"CostNsPerPixel", 0.4f}}),
      tech("perf", {{"Scheme", std::string("performance")}, {"MaxError", 3.f}, {"CostMs", 0.005f}}),
      tech("far_lut", {{"MinDistance", 70.f}, {"MaxError", 4.f}, {"MinScreenSize", 4.f}}),
      tech("billboard", {{"MaxError", 12.f}, {"MaxScreenSize", 8.f}}),
  };
}

struct Object {
  float distance, screen_size, pixels;
};

std::vector<Object> objects() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> d(0.f, 150.f);
  std::vector<Object> out(kObjects);
  for (auto& o : out) {
    o.distance = d(rng);
    o.screen_size = 2000.f / (1.f + o.distance);
    o.pixels = o.screen_size * o.screen_size;
  }
  return out;
}

// The baseline: every rule evaluated from the annotation map for every object.
uint32_t naive_select(const std::vector<fx::TechniqueCandidate>& list, const fx::SelectionCriteria& c) {
  uint32_t best = fx::kNoIndex;
  float best_error = 0.f;
  for (uint32_t i = 0; i < list.size(); ++i) {
    const fx::AnnotationMap& a = list[i].annotations;
    if (!list[i].valid) continue;
    if (auto s = a.string("Scheme"); s && !c.scheme.empty() && s->find(c.scheme) == std::string_view::npos) continue;
    if (c.distance < a.number("MinDistance").value_or(-1e30f) || c.distance >= a.number("MaxDistance").value_or(1e30f))
      continue;
    if (c.screen_size >= 0.f && (c.screen_size < a.number("MinScreenSize").value_or(-1e30f) ||
                                 c.screen_size >= a.number("MaxScreenSize").value_or(1e30f)))
      continue;
    float error = a.number("MaxError").value_or(0.f);
    float cost = a.number("CostMs").value_or(0.f) + a.number("CostNsPerPixel").value_or(0.f) * c.pixels * 1e-6f;
    if (error > c.max_error || cost > c.cost_budget_ms) continue;
    if (best == fx::kNoIndex || error < best_error) {
      best = i;
      best_error = error;
    }
  }
  return best;
}

void BM_SelectPlan10k(benchmark::State& state) {
  auto list = effect();
  fx::DiagnosticSink sink;
  fx::SelectionPlan plan = fx::SelectionPlan::build(list, sink);
  std::vector<Object> objs = objects();
  std::vector<fx::SelectionState> states(kObjects);
  fx::SelectionQuery q = plan.query({.scheme = "quality", .cost_budget_ms = 0.5f});
  for (auto _ : state) {
    uint64_t sum = 0;
    for (size_t i = 0; i < kObjects; ++i) {
      q.distance = objs[i].distance;
      q.screen_size = objs[i].screen_size;
      q.pixels = objs[i].pixels;
      sum += plan.select(q, states[i]);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kObjects);
}
BENCHMARK(BM_SelectPlan10k)->Unit(benchmark::kMicrosecond);

void BM_NaiveAnnotations10k(benchmark::State& state) {
  auto list = effect();
  std::vector<Object> objs = objects();
  for (auto _ : state) {
    uint64_t sum = 0;
    for (size_t i = 0; i < kObjects; ++i) {
      fx::SelectionCriteria c{.distance = objs[i].distance,
                              .screen_size = objs[i].screen_size,
                              .pixels = objs[i].pixels,
                              .scheme = "quality",
                              .cost_budget_ms = 0.5f};
      sum += naive_select(list, c);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kObjects);
}
BENCHMARK(BM_NaiveAnnotations10k)->Unit(benchmark::kMicrosecond);

void BM_Explain10k(benchmark::State& state) {
  auto list = effect();
  fx::DiagnosticSink sink;
  fx::SelectionPlan plan = fx::SelectionPlan::build(list, sink);
  std::vector<Object> objs = objects();
  fx::SelectionQuery q = plan.query({.scheme = "quality", .cost_budget_ms = 0.5f});
  for (auto _ : state) {
    size_t chars = 0;
    for (size_t i = 0; i < kObjects; ++i) {
      q.distance = objs[i].distance;
      q.screen_size = objs[i].screen_size;
      q.pixels = objs[i].pixels;
      for (const auto& r : plan.explain(q).reasons) chars += r.size();
    }
    benchmark::DoNotOptimize(chars);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kObjects);
}
BENCHMARK(BM_Explain10k)->Unit(benchmark::kMicrosecond);

// Remembers each benchmark's real time per iteration (microseconds) for the summary.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const auto& r : runs)
      if (r.run_type == Run::RT_Iteration) {
        micros[r.benchmark_name()] = r.GetAdjustedRealTime();
        cpu_micros[r.benchmark_name()] = r.GetAdjustedCPUTime();
      }
  }
  // Wall time suffers when other processes share the cores; CPU time is this thread's own.
  std::map<std::string, double> micros, cpu_micros;
};

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

}  // namespace

int main(int argc, char** argv) {
  // The plan and the baseline must agree, or the ratio means nothing.
  auto list = effect();
  fx::DiagnosticSink sink;
  fx::SelectionPlan plan = fx::SelectionPlan::build(list, sink);
  for (const Object& o : objects()) {
    fx::SelectionCriteria c{.distance = o.distance,
                            .screen_size = o.screen_size,
                            .pixels = o.pixels,
                            .scheme = "quality",
                            .cost_budget_ms = 0.5f};
    uint32_t fast = plan.select(plan.query(c)), naive = naive_select(list, c);
    // The naive baseline has no fallback chains; compare only where it found something.
    if (naive != fx::kNoIndex && fast != naive) {
      std::fprintf(stderr, "plan and baseline disagree at distance %g\n", double(o.distance));
      return 1;
    }
  }

  benchmark::Initialize(&argc, argv);
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  auto get = [&](const char* name) {
    auto it = reporter.cpu_micros.find(name);
    return it == reporter.cpu_micros.end() ? 0.0 : it->second;
  };
  double plan_us = get("BM_SelectPlan10k"), naive_us = get("BM_NaiveAnnotations10k"), explain_us = get("BM_Explain10k");
  std::printf("\nfxkit_select_bench on %s (%u hardware threads, one used); CPU time per frame\n", cpu_model().c_str(),
              std::thread::hardware_concurrency());
  if (auto it = reporter.micros.find("BM_SelectPlan10k"); it != reporter.micros.end())
    std::printf("  (wall time of select: %.1f us/frame; higher when the cores are shared)\n", it->second);
  if (plan_us > 0) {
    std::printf("  SelectionPlan::select, 10k objects, 6 techniques: %.1f us/frame (%.1f ns/object; budget 1000 us)\n",
                plan_us, plan_us * 1000.0 / kObjects);
    if (naive_us > 0)
      std::printf("  baseline (annotations read per object): %.1f us/frame -> plan is %.1fx faster\n", naive_us,
                  naive_us / plan_us);
    if (explain_us > 0)
      std::printf("  SelectionPlan::explain (reason texts, allocates): %.1f us/frame (%.1fx select)\n", explain_us,
                  explain_us / plan_us);
  }
  return 0;
}
