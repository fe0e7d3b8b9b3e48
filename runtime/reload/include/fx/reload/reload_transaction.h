// One effect version and the transaction that builds it: parse, effect model, translation
// units, programs (through the shared SPIR-V cache, so only changed units reach glslang),
// technique candidates and selection plan, parameter store, backend GPU objects. The
// result is all-or-nothing: either a complete version or the diagnostics of the failure.
#pragma once
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "fx/compile/shader_compiler.h"
#include "fx/diagnostic.h"
#include "fx/frontend.h"
#include "fx/reload/effect_backend.h"
#include "fx/reload/reload_event.h"
#include "fx/reload/technique_choice.h"
#include "fx/select/device_caps.h"
#include "fx/source_manager.h"

namespace fx {

// Declared, not included, so users of a transaction need not include every layer; members
// are shared_ptrs.
struct EffectFile;
struct EffectModel;
class EffectUnits;
class TaskExecutor;
class EffectPrograms;
class ParameterStore;

// A complete, successfully built effect. Never moved once built: the model, programs and
// parameter store point into the parsed tree and the source manager. Immutable once
// built, except `params`, which only the thread calling EffectLibrary::poll() touches.
struct EffectVersion {
  EffectVersion();
  ~EffectVersion();
  EffectVersion(const EffectVersion&) = delete;
  EffectVersion& operator=(const EffectVersion&) = delete;

  std::string path;                  // the effect file
  uint64_t serial = 0;               // 1 for the first good load, +1 per swap
  std::shared_ptr<EffectFile> file;  // the effect as every consumer builds it (fx/compile/effect_file.h)
  // The file's pieces, sharing its ownership: a holder of one keeps the whole build alive.
  std::shared_ptr<SourceManager> sources;
  std::shared_ptr<EffectModel> model;
  std::shared_ptr<EffectUnits> units;        // nullptr when built without a compiler
  std::shared_ptr<EffectPrograms> programs;  // every pass compiled
  std::shared_ptr<ParameterStore> params;
  std::shared_ptr<const TechniqueChoice> techniques;  // indexed like model->techniques
  std::shared_ptr<BackendEffect> gpu;                 // nullptr without a backend
  std::vector<Diagnostic> warnings;                   // of the build that produced it

  // Versions alive in this process (tests check that soaks return to the baseline).
  static size_t live_count();

 private:
  static std::atomic<size_t> live_;
};

// What a transaction needs; everything referenced must outlive the call.
struct ReloadTransactionInput {
  std::string path;
  const FrontEndOptions* front_end = nullptr;
  const ShaderCompiler* compiler = nullptr;  // thread-safe, shares the SPIR-V cache
  TaskExecutor* executor = nullptr;          // compiles the stages in parallel; nullptr: in turn
  std::mutex* backend_mutex = nullptr;       // held around backend->prepare when given
  const DeviceCaps* caps = nullptr;          // nullptr: no device requirement checks
  EffectBackend* backend = nullptr;          // nullptr: no GPU objects
  uint64_t serial = 0;                       // given to the version on success
};

// The outcome: `version` on success; otherwise nullptr and at least one error.
struct ReloadTransactionResult {
  std::unique_ptr<EffectVersion> version;
  std::vector<Diagnostic> diagnostics;     // everything reported (errors and warnings)
  std::shared_ptr<SourceManager> sources;  // what `diagnostics` point into
  std::vector<std::string> files;          // files read (effect first), even on failure
  std::vector<std::string> recompiled;     // "technique.pass.stage" compiled by glslang
  ReloadTimings ms;                        // parse, compile, glslang, pipeline, first_frame
  bool ok() const { return version != nullptr; }
};

// Runs the whole transaction on the calling thread. Never throws.
ReloadTransactionResult run_reload_transaction(const ReloadTransactionInput& input);

}  // namespace fx
