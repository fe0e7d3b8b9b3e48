// `fxkit bench MODE --processes N`: the same benchmark in N fresh processes, one after
// another, and the median of their ratios. One process measures one memory layout (heap,
// code and cache placement), and on lavapipe the apply ratio moves by up to 2x between
// processes of the same binary; only a median over processes says where it stands.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "bench.h"

extern char** environ;

namespace fx::tools {
namespace {

// The child's command line: this binary, the same mode and options, one process, JSON.
std::vector<std::string> child_args(const BenchArgs& args) {
  return {"/proc/self/exe",
          "bench",
          args.mode,
          "--repeats",
          std::to_string(args.repeats),
          "--size-mb",
          std::to_string(args.size_mb),
          "--effects",
          args.effects_dir,
          "--json"};
}

// Runs the command and returns what it printed; false when it could not start or did not
// exit with 0 or 1 (1: the benchmark ran and reported errors, which the JSON says too).
bool run_child(const std::vector<std::string>& args, std::string& out) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return false;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[1]);
  char buf[4096];
  ssize_t n;
  while ((n = read(pipe_fds[0], buf, sizeof buf)) > 0) out.append(buf, static_cast<size_t>(n));
  close(pipe_fds[0]);
  if (spawned != 0) return false;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return false;
  return WEXITSTATUS(status) == kSuccess || WEXITSTATUS(status) == kInputErrors;
}

// The ratio a benchmark's JSON reports: "ratio" (apply), "ratio_mb_per_s" (frontend).
const char* ratio_key(const nlohmann::json& j) {
  for (const char* key : {"ratio", "ratio_mb_per_s"})
    if (j.contains(key) && j[key].is_number()) return key;
  return nullptr;
}

}  // namespace

int bench_processes(const BenchArgs& args) {
  if (!args.fxh.empty()) {
    std::fprintf(stderr, "fxkit bench: --processes and --fxh do not go together (N processes would write one file)\n");
    return kUsageError;
  }
  std::vector<nlohmann::json> runs;
  std::vector<double> ratios;
  const char* key = nullptr;
  int status = kSuccess;
  for (int p = 0; p < args.processes; ++p) {
    std::string out;
    if (!run_child(child_args(args), out)) {
      std::fprintf(stderr, "fxkit bench: process %d of %d failed\n", p + 1, args.processes);
      return kUsageError;
    }
    nlohmann::json j = nlohmann::json::parse(out, nullptr, false);
    key = j.is_discarded() ? nullptr : ratio_key(j);
    if (!key) {
      std::fprintf(stderr, "fxkit bench %s reports no ratio to take the median of\n", args.mode.c_str());
      return kUsageError;
    }
    ratios.push_back(j[key].get<double>());
    if (j.value("errors", 0) != 0 || (j.contains("front_end") && j["front_end"].value("errors", 0) != 0))
      status = kInputErrors;
    runs.push_back(std::move(j));
  }
  const double median = interpolated_median(ratios);
  const auto [lowest, highest] = std::minmax_element(ratios.begin(), ratios.end());
  if (args.json) {
    nlohmann::json j = {{"benchmark", args.mode},
                        {"processes", args.processes},
                        {key, median},
                        {std::string(key) + "_min", *lowest},
                        {std::string(key) + "_max", *highest},
                        {"ratios", ratios},
                        {"runs", runs}};
    std::printf("%s\n", json_text(j).c_str());
    return status;
  }
  std::printf("fxkit bench %s in %d fresh processes (the ratio moves with each process's memory layout)\n",
              args.mode.c_str(), args.processes);
  std::printf("  %s: median %.3f, min %.3f, max %.3f", key, median, *lowest, *highest);
  if (runs.front().contains("target_ratio"))
    std::printf(" (target <= %.2f)", runs.front()["target_ratio"].get<double>());
  std::printf("\n  per process:");
  for (double r : ratios) std::printf(" %.3f", r);
  std::printf("\n");
  return status;
}

}  // namespace fx::tools
