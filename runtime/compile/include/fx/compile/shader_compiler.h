// Compiles one translation unit (HLSL or GLSL) to SPIR-V with glslang and reflects it.
#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "fx/compile/shader_message.h"
#include "fx/compile/shader_reflection.h"
#include "fx/compile/translation_unit.h"

namespace fx {

class CompileWorkers;
class SpirvCache;

// The result of compiling one stage. `ok` is false when glslang reported errors (see
// `messages`) or the unit was rejected before glslang ran (bad profile or stage).
struct CompiledShader {
  bool ok = false;
  std::vector<uint32_t> spirv;  // SPIR-V words; empty unless ok
  std::string entry_point;      // OpEntryPoint name: the unit's entry point, unchanged
  ShaderReflection reflection;
  std::vector<ShaderMessage> messages;             // parsed from info_log, in log order
  std::string info_log;                            // glslang's raw parse + link + SPIR-V log
  double parse_ms = 0, link_ms = 0, total_ms = 0;  // wall time of this call
  bool from_cache = false;                         // true when no glslang work was done
  // False for HLSL that was valid without spirv-opt's legalization and skipped it (most
  // shaders; it costs ten times the rest of a compile). Its code still loads every input it
  // declares: link_program legalizes it when the stage before does not write one of them.
  bool legalized = true;
};

// Compiles translation units. compile() is safe to call from several threads at once:
// each call owns its glslang TShader/TProgram, and glslang's process-wide tables are
// initialised once (and released at exit); with workers, each call takes a worker process.
class ShaderCompiler {
 public:
  // `cache` (optional, not owned) is consulted before glslang and filled after it.
  // `workers` (optional, not owned): glslang runs in those processes instead of this one
  // (fx/compile/compile_workers.h).
  explicit ShaderCompiler(CompileOptions options = {}, SpirvCache* cache = nullptr, CompileWorkers* workers = nullptr);

  // Compiles `unit`; never throws. Errors are in the result's messages.
  CompiledShader compile(const TranslationUnit& unit) const;

  const CompileOptions& options() const { return options_; }
  CompileWorkers* workers() const { return workers_; }
  // How many times this compiler ran glslang, here or in a worker (cache hits do not count).
  uint64_t glslang_runs() const { return glslang_runs_.load(); }

  // Whether this process has initialised glslang (its process tables; the built-in symbol
  // tables follow per stage and version). It happens on the first compile that is not a
  // cache hit, never before: a process whose every shader comes from the SPIR-V cache never
  // starts glslang.
  static bool glslang_started();

  // "glslang 12.0.0": part of every cache key, so an upgrade invalidates old entries.
  static std::string glslang_version();

 private:
  CompiledShader run_glslang(const TranslationUnit& unit, const ShaderProfile& profile) const;

  CompileOptions options_;
  SpirvCache* cache_ = nullptr;
  CompileWorkers* workers_ = nullptr;
  mutable std::atomic<uint64_t> glslang_runs_{0};
};

// Compiles and reports: the common path for the effect compiler. Diagnostics are placed
// with `resolve` (see resolver_for) and written to `sink`.
CompiledShader compile_and_report(const ShaderCompiler& compiler, const TranslationUnit& unit,
                                  const ShaderLocationResolver& resolve, DiagnosticSink& sink);

}  // namespace fx
