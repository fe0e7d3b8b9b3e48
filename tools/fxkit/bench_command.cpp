// `fxkit bench MODE [--size-mb N] [--repeats N] [--processes N] [--json] [--effect F]... [--merge JSON]`
#include <cstdio>

#include "bench.h"

namespace fx::tools {

void register_bench(CLI::App& app, Runner& run) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Benchmarks: fxkit against a baseline, as a ratio");
  cmd->add_option("MODE", args->mode, "What to measure: frontend, compile, check, reload, accuracy, apply")
      ->required()
      ->check(CLI::IsMember({"frontend", "compile", "check", "reload", "accuracy", "apply"}));
  cmd->add_option("--effects", args->effects_dir, "compile, check: folder of .fx files to load or check")
      ->capture_default_str();
  cmd->add_option("--seeds", args->seeds_dir, "check: folder of .fx files loaded through the library")
      ->capture_default_str();
  cmd->add_option("--size-mb", args->size_mb, "frontend: size of the generated effect in MB")->capture_default_str();
  cmd->add_option("--repeats", args->repeats, "Repetitions (the median is reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--fxh", args->fxh, "accuracy: write technique cost/error annotations to FILE");
  cmd->add_option("--effect", args->only_effects,
                  "accuracy: measure only this effect's techniques (a file name in --effects; repeatable)");
  cmd->add_option("--merge", args->merge,
                  "accuracy: an earlier --json output (docs/accuracy.json): its approximation rows and the "
                  "other effects' technique rows are kept, the measured effects' rows replaced");
  cmd->add_option("--processes", args->processes,
                  "Run the benchmark in N fresh processes and report the median ratio (one process "
                  "measures one memory layout)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  cmd->add_flag("--json", args->json, "Print the results as JSON");
  cmd->callback([args, &run] {
#ifndef FXKIT_HAS_RUNTIME
    run = [] {
      std::fprintf(stderr,
                   "fxkit bench: this fxkit was built without the runtime (FXKIT_VULKAN=OFF); "
                   "every benchmark's baseline is glslang or Vulkan\n");
      return kUsageError;
    };
    return;
#endif
    if (args->processes > 1) {
      run = [args] { return bench_processes(*args); };
      return;
    }
#ifdef FXKIT_HAS_RUNTIME
    if (args->mode == "apply") {
      run = [args] { return bench_apply(*args); };
      return;
    }
    if (args->mode == "reload") {
      run = [args] { return bench_reload(*args); };
      return;
    }
    if (args->mode == "accuracy") {
      run = [args] { return bench_accuracy(*args); };
      return;
    }
    if (args->mode == "check") {
      run = [args] { return bench_check(*args); };
      return;
    }
    if (args->mode == "compile") {
      run = [args] { return bench_compile(*args); };
      return;
    }
    run = [args] { return bench_frontend(*args); };
#endif
  });
}

}  // namespace fx::tools
