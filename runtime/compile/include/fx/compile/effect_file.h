// fx::EffectFile: one effect built the way every consumer builds it: the front end (with
// the semantic model's findings), then on request the effect model with its parameters,
// and the translation units (with the unit options the front-end options imply) with their
// programs, compiled lazily or all at once. `fxkit check`, `compile`, `info`, `select`,
// `render` and `lsp`, technique validation, hot reload (one EffectFile per version) and
// the benches run these steps and differ only in where they stop and what they print.
#pragma once
#include <memory>
#include <string>

#include "fx/compile/effect_programs.h"
#include "fx/compile/effect_units.h"
#include "fx/compile/shader_compiler.h"
#include "fx/frontend.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"
#include "fx/source_manager.h"

namespace fx {

// The translation-unit options of an effect compiled with `options`. Its preprocessor
// defines are not among them: the front end expanded them, and glslang gets preprocessed
// text only. The macro FXKIT_PS1X_PRECISION among them turns on ps1x_precision (what
// `fxkit render --ps1x-precision` defines), so reloads and tools see the same option.
EffectUnitOptions effect_unit_options(const FrontEndOptions& options);
inline constexpr const char* kPs1xPrecisionMacro = "FXKIT_PS1X_PRECISION";

struct EffectFile {
  std::string path;
  FrontEndOptions options;
  SourceManager sources;
  ParsedEffect parsed;
  std::unique_ptr<EffectModel> model;        // after build_model
  std::unique_ptr<ParameterStore> params;    // after a build_model without errors
  std::unique_ptr<EffectUnits> units;        // after build_programs
  std::unique_ptr<ShaderCompiler> compiler;  // the own compiler, when build_programs was given none
  std::unique_ptr<EffectPrograms> programs;  // after build_programs

  // The front end and the semantic model on the file at `path` (or on `text` named `path`;
  // includes read by options.preprocessor.loader) into `sink`; parsed.ok: no front-end error.
  static std::unique_ptr<EffectFile> parse(const std::string& path, const FrontEndOptions& options,
                                           DiagnosticSink& sink);
  static std::unique_ptr<EffectFile> parse_text(const std::string& path, std::string text,
                                                const FrontEndOptions& options, DiagnosticSink& sink);
  // The effect model, then the parameter store; false (and no store) when the model
  // reported errors.
  bool build_model(DiagnosticSink& sink);
  // The translation units and their (lazily compiled) programs, compiled by `shared`, or by
  // an own compiler when null. The units' diagnostics go to `sink`.
  void build_programs(DiagnosticSink& sink, const ShaderCompiler* shared = nullptr);

  // parse + build_model + build_programs: what rendering starts from. Null when the front
  // end or the model reported errors (in `sink`); then `located`, when given, receives them
  // as `file:line:col: error: ...` text, since the sources their ranges point into end with
  // the failed load.
  static std::unique_ptr<EffectFile> load(const std::string& path, const FrontEndOptions& options, DiagnosticSink& sink,
                                          std::string* located = nullptr);
  // The same for effect text in memory named `name` (an effect a tool carries, such as the
  // preview's test scene).
  static std::unique_ptr<EffectFile> load_text(const std::string& name, std::string text,
                                               const FrontEndOptions& options, DiagnosticSink& sink);
  // The technique named `name`, or kNoIndex (after build_model).
  uint32_t find_technique(std::string_view name) const;
};

}  // namespace fx
