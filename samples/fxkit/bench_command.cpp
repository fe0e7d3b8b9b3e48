// `fxkit bench frontend [--size-mb N] [--repeats N] [--json]`
#include <cstdio>

#include "bench.h"

namespace fxkit {

void register_bench(CLI::App& app, Runner& run) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Benchmarks: fxkit against a baseline, as a ratio");
  cmd->add_option("MODE", args->mode, "What to measure: frontend")
      ->required()
      ->check(CLI::IsMember({"frontend"}));
  cmd->add_option("--size-mb", args->size_mb, "frontend: size of the generated effect in MB")
      ->capture_default_str();
  cmd->add_option("--repeats", args->repeats, "Repetitions (the median is reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--json", args->json, "Print the results as JSON");
  cmd->callback([args, &run] {
    run = [args] { return bench_frontend(*args); };
  });
}

}  // namespace fxkit
