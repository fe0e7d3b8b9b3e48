// --in-process, and the compile worker pool the commands that compile shaders share:
// glslang runs in fxkit-compile-worker processes unless the flag says otherwise.
#pragma once
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>

#include "fx/compile/compile_workers.h"

namespace fx::tools {

struct CompileWorkersFlag {
  bool in_process = false;

  void add_to(CLI::App& command);
  // The pool's options (`jobs` workers; 0: one per core), or nullopt with --in-process.
  std::optional<fx::CompileWorkerOptions> options(unsigned jobs) const;
  // The pool, or null with --in-process or when it cannot start (a warning on stderr:
  // `command` then compiles in this process).
  std::unique_ptr<fx::CompileWorkers> start(const char* command, unsigned jobs) const;
};

}  // namespace fx::tools
