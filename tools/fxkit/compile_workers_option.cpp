#include "compile_workers_option.h"

#include <cstdio>

namespace fx::tools {

void CompileWorkersFlag::add_to(CLI::App& command) {
  command.add_flag("--in-process", in_process,
                   "Run glslang in this process, not in compile worker processes (a glslang crash then ends fxkit)");
}

std::optional<fx::CompileWorkerOptions> CompileWorkersFlag::options(unsigned jobs) const {
  if (in_process) return std::nullopt;
  return fx::CompileWorkerOptions{.workers = jobs};
}

std::unique_ptr<fx::CompileWorkers> CompileWorkersFlag::start(const char* command, unsigned jobs) const {
  std::optional<fx::CompileWorkerOptions> o = options(jobs);
  if (!o) return nullptr;
  std::string error;
  std::unique_ptr<fx::CompileWorkers> pool = fx::CompileWorkers::start(*o, error);
  if (!pool)
    std::fprintf(stderr, "fxkit %s: warning: compiling in this process: %s [compile-workers-unavailable]\n", command,
                 error.c_str());
  return pool;
}

}  // namespace fx::tools
