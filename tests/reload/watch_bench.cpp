// What watching costs: rescanning many files (stat-only vs hashing every file) and the
// delay from a save to its event with coalescing off (inotify vs polling).
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <sys/stat.h>

#include <cstdio>
#include <map>
#include <string>

#include "fx/reload/file_watcher.h"
#include "watch_test_support.h"

namespace {

using namespace std::chrono_literals;
using namespace fx::testing;

// `count` effect-sized files (4 KiB); backdated ones have settled, stat-vouched content.
void make_files(const ScratchDir& dir, fx::FileWatcher& w, int count, bool backdate) {
  std::string text(4096, 'x');
  for (int i = 0; i < count; ++i) {
    fs::path p = dir / (std::to_string(i) + ".fxh");
    save_truncate_write(p, text);
    if (backdate) {
      timespec old[2] = {{1'000'000'000, 0}, {1'000'000'000, 0}};
      utimensat(AT_FDCWD, p.c_str(), old, 0);
    }
    w.watch(p);
  }
}

void rescan(benchmark::State& state, bool settled) {
  ScratchDir dir;
  fx::FileWatcherOptions o;
  o.backend = fx::WatchBackend::polling;
  o.poll_interval = std::chrono::hours(1);
  fx::FileWatcher w(o);
  make_files(dir, w, int(state.range(0)), settled);
  size_t hashed_before = w.stats().files_hashed;
  for (auto _ : state) benchmark::DoNotOptimize(w.rescan());
  state.counters["hashed_per_rescan"] = double(w.stats().files_hashed - hashed_before) / double(state.iterations());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Baseline: files written moments ago are "racy", so every rescan must read and hash them.
void BM_RescanRecentlyWrittenFiles(benchmark::State& state) { rescan(state, false); }
// Settled files: stat alone proves them unchanged.
void BM_RescanSettledFiles(benchmark::State& state) { rescan(state, true); }
BENCHMARK(BM_RescanRecentlyWrittenFiles)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RescanSettledFiles)->Arg(200)->Unit(benchmark::kMicrosecond);

// Save -> event, coalescing window 0, so the time is the backend's own detection delay.
void BM_SaveToEvent(benchmark::State& state) {
  ScratchDir dir;
  fx::FileWatcherOptions o;
  o.backend = state.range(0) ? fx::WatchBackend::polling : fx::WatchBackend::inotify;
  o.coalesce_window = 0ms;
  o.poll_interval = 10ms;
  fx::FileWatcher w(o);
  fs::path p = dir / "a.fx";
  save_truncate_write(p, "v");
  w.watch(p);
  w.poll(0ms);
  int i = 0;
  for (auto _ : state) {
    std::string text = "v";
    text += std::to_string(++i);  // not `"v" + ...`: g++ 12 -O2 warns falsely (-Wrestrict)
    save_truncate_write(p, text);
    if (wait_for_events(w).size() != 1) state.SkipWithError("no event");
  }
  state.SetLabel(fx::to_string(o.backend));
}
BENCHMARK(BM_SaveToEvent)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

// Console output plus the ratios this benchmark exists to show.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) seconds_[r.benchmark_name()] = r.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    ratio("rescan, settled vs hash-every-file baseline", "BM_RescanSettledFiles/200",
          "BM_RescanRecentlyWrittenFiles/200");
    ratio("save-to-event, inotify vs polling baseline", "BM_SaveToEvent/0/real_time", "BM_SaveToEvent/1/real_time");
  }

 private:
  void ratio(const char* what, const std::string& fast, const std::string& baseline) {
    if (!seconds_.count(fast) || !seconds_.count(baseline)) return;
    std::printf("%s: %.1fx faster\n", what, seconds_[baseline] / seconds_[fast]);
  }
  std::map<std::string, double> seconds_;
};

int main(int argc, char** argv) {
  std::printf(
      "fxkit watcher cost: rescan of 200 x 4 KiB files (stat-only vs the hash-every-file "
      "baseline) and save-to-event delay (inotify vs polling at 10 ms), on %s\n",
      ::testing::TempDir().c_str());
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
