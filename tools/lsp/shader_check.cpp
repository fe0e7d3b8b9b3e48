// Compiled-shader diagnostics of a document snapshot (shader_check.h).
#include "shader_check.h"

#include "effect_check.h"
#include "fx/compile/compile_workers.h"
#include "fx/compile/shader_compiler.h"
#include "fx/shown_once.h"
#include "language_features.h"

namespace fx::tools::lsp {

ShaderCheck::ShaderCheck(std::unique_ptr<fx::CompileWorkers> workers)
    : workers_(std::move(workers)), compiler_(std::make_unique<fx::ShaderCompiler>(fx::CompileOptions{}, nullptr,
                                                                                   workers_.get())) {}

ShaderCheck::~ShaderCheck() = default;

json ShaderCheck::diagnostics(const CompileSnapshot& snapshot) const {
  const DocumentAnalysis analysis(snapshot.document, snapshot.config, snapshot.open);
  for (const fx::Diagnostic& d : analysis.diagnostics())
    if (d.severity >= fx::Severity::error) return json::array();
  EffectCheckSettings settings;
  settings.front_end = snapshot.config.front_end_options();
  settings.compiler = compiler_.get();
  fx::DiagnosticSink units;
  fx::ShownOnce shown;
  check_shaders(analysis.parsed(), settings, analysis.sources(), units, shown);
  return document_diagnostics(analysis, shown.diagnostics());
}

}  // namespace fx::tools::lsp
