// The two halves of a reload transaction, one per layer (see
// fx/reload/reload_transaction.h): the model side and the compile side.
#pragma once
#include <string>
#include <vector>

#include "fx/reload/reload_transaction.h"

namespace fx {

// Both run the steps of the version's EffectFile.

// Model side (version_model.cpp): effect model, parameter store, technique facts (names,
// annotations). Returns false when the model reported errors.
bool build_version_model(EffectVersion& version, DiagnosticSink& sink, std::vector<TechniqueFacts>& facts);

// What the compile side learned.
struct ProgramOutcome {
  struct Rejection {
    uint32_t technique_index = 0;
    std::string technique, reason;
  };
  std::vector<Rejection> rejections;    // per pass that cannot run (unsupported or failed)
  std::vector<std::string> recompiled;  // "technique.pass.stage" that glslang compiled
  double glslang_ms = 0;
};

// Compile side (version_programs.cpp): translation units and every pass's program, the
// stages spread over `executor` when given. Stage and link diagnostics go to `sink`.
// Returns false when any of them is an error.
bool build_version_programs(EffectVersion& version, const ShaderCompiler& compiler, TaskExecutor* executor,
                            DiagnosticSink& sink, ProgramOutcome& outcome);

// Copies a diagnostic into a sink (keeping its severity, id, range, notes and fix-its).
inline void forward(const Diagnostic& d, DiagnosticSink& sink) {
  Diagnostic& copy = sink.report(d.severity, d.id, d.range, d.message);
  copy.notes = d.notes;
  copy.fixits = d.fixits;
}

}  // namespace fx
