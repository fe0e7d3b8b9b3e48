// Shader compilation in worker processes: glslang runs in `fxkit-compile-worker` processes
// that stay alive between compiles, so a glslang crash, hang or memory blow-up on what an
// effect contains is a `compiler-crashed` error on that shader, not the end of the
// application. Engines compile out of process for the same reason (Unreal's
// ShaderCompileWorker, Unity's UnityShaderCompiler). docs/shader-compilation.md has the
// trade-offs against compiling in-process.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "fx/compile/shader_compiler.h"

namespace fx {

struct CompileWorkerOptions {
  // The worker executable; "": $FXKIT_COMPILE_WORKER, then `fxkit-compile-worker` beside
  // the running program (where `fxkit` is installed), then the build tree's.
  std::string executable{};
  uint32_t workers = 0;                  // processes; 0: one per core
  uint32_t time_limit_ms = 120'000;      // per compile; past it the worker is killed
  uint32_t memory_limit_mb = 4096;       // address space of each worker (RLIMIT_AS); 0: none
  std::vector<std::string> arguments{};  // passed to every worker (tests: --abort-on TEXT)
};

// Counters for tests, benches and `--stats`.
struct CompileWorkerStats {
  uint64_t started = 0;    // processes started, replacements included
  uint64_t compiles = 0;   // units answered by a worker
  uint64_t crashed = 0;    // units whose worker died (signal or exit) or sent garbage
  uint64_t timed_out = 0;  // units whose worker passed the time limit and was killed
  double start_ms = 0;     // the last start: spawn to the worker running (wall time)
  double warm_up_ms = 0;   // then its glslang warm-up (built-in tables), before its first unit
};

// A pool of worker processes. compile() is thread-safe: a call takes an idle worker (or
// waits for one), so at most `workers` compiles run at once. A worker starts with the first
// compile that needs it (a run served by the SPIR-V cache starts none) and stays alive; one
// that dies or passes the time limit is replaced at once, before the next compile needs it.
class CompileWorkers {
 public:
  // Finds the executable; nullptr with `error` saying why when none is runnable. A program
  // there that does not answer as a worker makes each compile a `compiler-crashed` error.
  static std::unique_ptr<CompileWorkers> start(const CompileWorkerOptions& options, std::string& error);
  ~CompileWorkers();
  CompileWorkers(const CompileWorkers&) = delete;
  CompileWorkers& operator=(const CompileWorkers&) = delete;

  // Compiles `unit` in a worker. A worker failure gives a result with one located error
  // (`compiler-crashed`, at the unit's entry point) saying what happened.
  CompiledShader compile(const TranslationUnit& unit, const CompileOptions& options);

  uint32_t size() const { return static_cast<uint32_t>(slots_.size()); }
  const std::string& executable() const { return executable_; }
  CompileWorkerStats stats() const;

  // The executable `options` name or the default places hold; "" when none is runnable.
  // `searched` (optional) gets the places looked at, for an error message.
  static std::string find_executable(const CompileWorkerOptions& options, std::vector<std::string>* searched = nullptr);

 private:
  struct Process;
  CompileWorkers(std::string executable, const CompileWorkerOptions& options);
  bool spawn(Process& p, std::string& error);
  int retire(Process& p);  // stops and reaps it; its wait status
  size_t acquire();
  void release(size_t slot);

  std::string executable_;
  CompileWorkerOptions options_;
  std::vector<std::unique_ptr<Process>> slots_;
  std::vector<size_t> idle_;
  mutable std::mutex mutex_;
  std::condition_variable idle_changed_;
  CompileWorkerStats stats_;
};

}  // namespace fx
