// fx::EffectFile: one effect file loaded for rendering without hot reload: parsed,
// modelled, split into translation units, compiled lazily, with its parameter values.
// What `fxkit render`, `fxkit bench apply` and the rendering tests start from. Hot reload
// builds the same pieces per version (fx/reload, shared and cached), with the same unit
// options (effect_unit_options).
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
  SourceManager sources;
  ParsedEffect parsed;
  std::unique_ptr<EffectModel> model;
  std::unique_ptr<EffectUnits> units;
  std::unique_ptr<ShaderCompiler> compiler;
  std::unique_ptr<EffectPrograms> programs;
  std::unique_ptr<ParameterStore> params;

  // Loads `path`; null when the front end or the model reported errors (in `sink`). Then
  // `located`, when given, receives them as `file:line:col: error: ...` text: the sources
  // their ranges point into end with the failed load.
  static std::unique_ptr<EffectFile> load(const std::string& path, const FrontEndOptions& options, DiagnosticSink& sink,
                                          std::string* located = nullptr);
  // The same for effect text in memory named `name` (an effect a tool carries, such as the
  // preview's test scene).
  static std::unique_ptr<EffectFile> load_text(const std::string& name, std::string text,
                                               const FrontEndOptions& options, DiagnosticSink& sink);
  // The technique named `name`, or kNoIndex.
  uint32_t find_technique(std::string_view name) const;
};

}  // namespace fx
