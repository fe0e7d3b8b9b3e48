// Reload transaction, compile side: translation units and every pass's program, through
// the shared SPIR-V cache so that only changed units reach glslang.
#include "fx/compile/effect_file.h"
#include "fx/compile/effect_programs.h"
#include "fx/compile/effect_units.h"
#include "fx/shown_once.h"
#include "fx/worker_pool.h"
#include "version_steps.h"

namespace fx {

bool build_version_programs(EffectVersion& version, const ShaderCompiler& compiler, TaskExecutor* executor,
                            DiagnosticSink& sink, ProgramOutcome& outcome) {
  size_t errors = sink.error_count();
  version.file->build_programs(sink, &compiler);
  version.units = std::shared_ptr<EffectUnits>(version.file, version.file->units.get());
  version.programs = std::shared_ptr<EffectPrograms>(version.file, version.file->programs.get());
  // Every pass, not just the selected technique's: a broken fallback must not be
  // discovered the day the fallback is chosen.
  if (executor) version.programs->compile_all(*executor);
  // A function several passes call reports its error in each: one error, with a note naming
  // the other passes, as `fxkit check` reports it.
  ShownOnce shown;
  for (const EffectPass& pass : version.units->passes()) {
    const PassProgram& program = version.programs->program(pass);
    const std::string name = pass.technique + "." + pass.pass;
    for (const StageProgram& s : program.stages) {
      shown.add(s.diagnostics, name + " " + to_string(s.stage));
      if (!s.shader.from_cache && !s.reused)
        outcome.recompiled.push_back(pass.technique + "." + pass.pass + "." + to_string(s.stage));
    }
    shown.add(program.diagnostics, name);
    for (const std::string& why : program.unsupported)
      outcome.rejections.push_back({pass.technique_index, pass.technique, pass.pass + ": " + why});
    if (!program.compiled && !program.stages.empty())
      outcome.rejections.push_back({pass.technique_index, pass.technique, pass.pass + ": did not compile"});
  }
  for (const Diagnostic& d : shown.diagnostics()) forward(d, sink);
  outcome.glslang_ms = version.programs->stats().glslang_ms;
  return sink.error_count() == errors;
}

}  // namespace fx
