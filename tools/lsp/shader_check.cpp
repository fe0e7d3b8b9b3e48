// Compiled-shader findings of a document snapshot (shader_check.h).
#include "shader_check.h"

#include "effect_check.h"
#include "fx/compile/compile_workers.h"
#include "fx/compile/effect_file.h"
#include "fx/compile/effect_programs.h"
#include "fx/compile/effect_units.h"
#include "fx/compile/shader_compiler.h"
#include "fx/compile/spirv_cache.h"
#include "fx/model/effect_model.h"
#include "fx/select/caps_sources.h"
#include "fx/select/technique_validation.h"
#include "fx/shown_once.h"
#include "language_features.h"

namespace fx::tools::lsp {
namespace {

// "valid on dx9, modern; dx8: ps_2_0 not supported" per technique, from validating it on
// each profile; unknown profile names are left out.
json technique_lenses(const DocumentAnalysis& a, const std::vector<std::string>& profiles,
                      fx::EffectPrograms& programs) {
  fx::DiagnosticSink model_sink;  // the front end reported what the model would repeat
  const fx::EffectModel model = fx::build_effect_model(a.parsed(), a.sources(), model_sink);
  struct Lens {
    fx::SourceRange range;
    std::string valid, invalid;
  };
  std::vector<Lens> lenses;
  for (const std::string& profile : profiles) {
    fx::DiagnosticSink ignored;
    const std::optional<fx::DeviceCaps> caps = fx::load_caps_profile(profile, ignored);
    if (!caps) continue;
    const std::vector<fx::TechniqueValidation> techniques =
        fx::validate_techniques(model, *caps, {.programs = &programs});
    if (lenses.empty())
      for (const fx::TechniqueValidation& t : techniques) lenses.push_back({t.range, "", ""});
    for (size_t i = 0; i < techniques.size() && i < lenses.size(); ++i) {
      const fx::TechniqueValidation& t = techniques[i];
      if (t.valid) lenses[i].valid += (lenses[i].valid.empty() ? "" : ", ") + profile;
      else lenses[i].invalid += "; " + profile + ": " + (t.reasons.empty() ? "invalid" : t.reasons.front().message);
    }
  }
  json out = json::array();
  for (const Lens& l : lenses) {
    if (!l.range.begin.valid() || !a.in_document(l.range.begin)) continue;
    std::string title = l.valid.empty() ? "valid on none" : "valid on " + l.valid;
    title += l.invalid;
    out.push_back(
        {{"range", a.range_json({l.range.begin, l.range.begin})}, {"command", {{"title", title}, {"command", ""}}}});
  }
  return out;
}

}  // namespace

ShaderCheck::ShaderCheck(std::unique_ptr<fx::CompileWorkers> workers)
    : workers_(std::move(workers)),
      cache_(std::make_unique<fx::SpirvCache>()),
      compiler_(std::make_unique<fx::ShaderCompiler>(fx::CompileOptions{}, cache_.get(), workers_.get())) {}

ShaderCheck::~ShaderCheck() = default;

CompileFindings ShaderCheck::check(const CompileSnapshot& snapshot) const {
  const DocumentAnalysis analysis(snapshot.document, snapshot.config, snapshot.open);
  for (const fx::Diagnostic& d : analysis.diagnostics())
    if (d.severity >= fx::Severity::error) return {};
  EffectCheckSettings settings;
  settings.front_end = snapshot.config.front_end_options();
  settings.compiler = compiler_.get();
  // The snapshot's own parse (its open include buffers) split into units as EffectFile
  // splits a file, with the same unit options.
  fx::DiagnosticSink units_sink;
  fx::EffectUnits units(analysis.parsed().ast, analysis.sources(), units_sink,
                        fx::effect_unit_options(settings.front_end));
  fx::EffectPrograms programs(units, *compiler_, analysis.sources());
  fx::ShownOnce shown;
  check_shaders(units, programs, settings, units_sink, shown);
  return {document_diagnostics(analysis, shown.diagnostics()),
          technique_lenses(analysis, snapshot.config.validation_profiles(), programs)};
}

}  // namespace fx::tools::lsp
