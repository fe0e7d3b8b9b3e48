// The compiled programs of an effect's passes, built on demand: each pass's stages are
// compiled through the ShaderCompiler (and its SPIR-V cache) the first time the pass is
// asked for, then linked into one program layout.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "fx/compile/effect_units.h"
#include "fx/compile/program_link.h"
#include "fx/compile/shader_compiler.h"
#include "fx/diagnostic.h"
#include "fx/model/texture_shader.h"
#include "fx/source_manager.h"

namespace fx {

class TaskExecutor;

// One compiled stage of a pass, with the diagnostics of its compilation.
struct StageProgram {
  ShaderStage stage = ShaderStage::vertex;
  TranslationUnit unit;   // what glslang compiled (for tools: --emit-source)
  CompiledShader shader;  // SPIR-V and reflection (bindings after linking)
  std::vector<Diagnostic> diagnostics;
  double ms = 0;        // wall time to get this stage (compile, cache or memo)
  bool reused = false;  // an identical unit of an earlier pass was reused
};

// A pass's program: its compiled stages and the layout they share.
struct PassProgram {
  const EffectPass* pass = nullptr;
  std::vector<StageProgram> stages;     // the stages that have a unit, in pipeline order
  ProgramLayout layout;                 // valid when every stage compiled
  std::vector<Diagnostic> diagnostics;  // linking (shader-link-error, varyings)
  // Why the pass cannot run as written: assembly stages, fixed-function stages, invalid
  // shader references. The legacy path may emulate some of them.
  std::vector<std::string> unsupported;
  // ConstructGSWithSO: what its stage captures into which output buffer (set when the
  // capture could be patched in; an entry it cannot capture is a link error).
  std::optional<StreamOutputLayout> stream_output;
  bool compiled = false;  // every stage with a unit compiled and linked
  double link_ms = 0;     // link_program time

  // True when the pass can be drawn with its compiled programs alone.
  bool ok() const { return compiled && unsupported.empty(); }
  const StageProgram* find(ShaderStage stage) const;
};

// Counters for tests and benchmarks.
struct EffectProgramStats {
  uint64_t stages_compiled = 0;  // compile() calls made (cache hits included)
  uint64_t stages_reused = 0;    // identical units served from this effect's memo
  double compile_ms = 0;         // wall time in ShaderCompiler::compile
  double glslang_ms = 0;         // of which glslang (parse + link + SPIR-V), 0 for cache hits
  double link_ms = 0;            // link_program
};

// Lazily compiled programs of one effect. Not thread-safe: one EffectPrograms per thread
// (compile_all spreads glslang's work over an executor's threads itself).
class EffectPrograms {
 public:
  // `units`, `compiler` and `sm` must outlive this (diagnostics are placed with `sm`).
  EffectPrograms(const EffectUnits& units, const ShaderCompiler& compiler, const SourceManager& sm);
  ~EffectPrograms();
  EffectPrograms(const EffectPrograms&) = delete;
  EffectPrograms& operator=(const EffectPrograms&) = delete;

  // The program of `pass` (one of units.passes()), compiled on the first call.
  const PassProgram& program(const EffectPass& pass);
  // The program of the named pass, or nullptr when there is no such pass.
  const PassProgram* program(std::string_view technique, std::string_view pass);
  // One stage compiled on its own, not linked into a pass: the other choices of a shader
  // array (StageUnit::choices), for tools that check every shader an effect holds. nullopt
  // when the stage has no unit (assembly, invalid).
  std::optional<StageProgram> compile_alone(const StageUnit& stage);
  // Compiles every pass's stages (and with `shader_array_choices`, the other elements of the
  // shader arrays passes index) in parallel on `executor`, then links every pass: program()
  // and compile_alone() then only look results up. Each distinct unit is compiled once;
  // diagnostics are placed on the calling thread, in pass order, as program() would.
  void compile_all(TaskExecutor& executor, bool shader_array_choices = false);
  // The effect's check unit (EffectUnits::uncalled_check), compiled on the first call, or
  // nullptr when every function is reached. program() calls it for every pass with an HLSL
  // stage: its errors fail those passes, as fxc fails the effect.
  const StageProgram* uncalled_check();
  // The program that fills a texture shader's texture (fx/compile/texture_fill_unit.h): one
  // compute stage, compiled as pass stages are (cache, workers, diagnostics located in the
  // effect) and linked; once per distinct unit. Not `compiled` when the function does not
  // compile as a compute shader (the stage's diagnostics say why) or the effect has no such
  // function (no stage).
  const PassProgram& texture_fill(const TextureShader& shader);
  // Whether `pass` has been compiled already (no compile happens).
  bool is_compiled(const EffectPass& pass) const;

  const EffectProgramStats& stats() const { return stats_; }
  const EffectUnits& units() const { return units_; }

 private:
  struct Memo {
    CompiledShader shader;  // before linking: link_program rewrites bindings per pass
    std::vector<Diagnostic> diagnostics;
  };
  StageProgram compile_stage(const StageUnit& stage, TranslationUnit unit);

  const EffectUnits& units_;
  const ShaderCompiler& compiler_;
  const SourceManager& sm_;
  std::vector<std::unique_ptr<PassProgram>> programs_;  // parallel to units_.passes()
  std::unordered_map<std::string, Memo> memo_;          // by SPIR-V cache key
  // compile_all's results not yet asked for, by SPIR-V cache key: compile_stage takes them
  // as its own compile (they count as compiled, not reused).
  std::unordered_map<std::string, CompiledShader> compiled_ahead_;
  EffectProgramStats stats_;
  std::unique_ptr<StageProgram> check_;                                  // uncalled_check(), once compiled
  std::unordered_map<std::string, std::unique_ptr<PassProgram>> fills_;  // texture_fill(), by unit key
};

}  // namespace fx
