// Compiled-shader findings of a document snapshot (shader_check.h).
#include "shader_check.h"

#include "effect_check.h"
#include "fx/compile/compile_workers.h"
#include "fx/compile/effect_file.h"
#include "fx/compile/shader_compiler.h"
#include "fx/compile/spirv_cache.h"
#include "fx/select/caps_sources.h"
#include "fx/select/technique_validation.h"
#include "fx/shown_once.h"
#include "language_features.h"

namespace fx::tools::lsp {
namespace {

// "valid on dx9, modern; dx8: ps_2_0 not supported" per technique, from validating it on
// each profile (unknown profile names are left out), with the command that shows every
// reason of every profile.
json technique_lenses(fx::EffectFile& effect, const DocumentPlaces& places, const std::vector<std::string>& profiles) {
  fx::DiagnosticSink model_sink;  // the front end reported what the model would repeat
  effect.build_model(model_sink);
  struct Lens {
    std::string technique;
    fx::SourceRange range;
    std::string valid, invalid, details;
  };
  std::vector<Lens> lenses;
  for (const std::string& profile : profiles) {
    fx::DiagnosticSink ignored;
    const std::optional<fx::DeviceCaps> caps = fx::load_caps_profile(profile, ignored);
    if (!caps) continue;
    const std::vector<fx::TechniqueValidation> techniques =
        fx::validate_techniques(*effect.model, *caps, {.programs = effect.programs.get()});
    if (lenses.empty())
      for (const fx::TechniqueValidation& t : techniques) lenses.push_back({t.name, t.range, "", "", ""});
    for (size_t i = 0; i < techniques.size() && i < lenses.size(); ++i) {
      const fx::TechniqueValidation& t = techniques[i];
      Lens& l = lenses[i];
      l.details += "\n" + profile + ": " + (t.valid ? "valid" : "invalid");
      for (const fx::Diagnostic& reason : t.reasons) l.details += "\n  " + reason.message;
      if (t.valid) l.valid += (l.valid.empty() ? "" : ", ") + profile;
      else l.invalid += "; " + profile + ": " + (t.reasons.empty() ? "invalid" : t.reasons.front().message);
    }
  }
  json out = json::array();
  for (const Lens& l : lenses) {
    if (!l.range.begin.valid() || !places.in_document(l.range.begin)) continue;
    std::string title = l.valid.empty() ? "valid on none" : "valid on " + l.valid;
    title += l.invalid;
    const json details = {{"technique", l.technique}, {"message", "technique '" + l.technique + "'" + l.details}};
    out.push_back({{"range", places.range_json({l.range.begin, l.range.begin})},
                   {"command", {{"title", title}, {"command", kTechniqueValidityCommand}, {"arguments", {details}}}}});
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
  // The effect built as every consumer builds it, reading the open documents' buffers.
  const std::string& path = snapshot.document.path;
  EffectCheckSettings settings;
  settings.front_end = snapshot.config.document_options(path, snapshot.open);
  settings.compiler = compiler_.get();
  fx::DiagnosticSink front_end;  // the analysis published these already
  std::unique_ptr<fx::EffectFile> effect =
      fx::EffectFile::parse_text(path, snapshot.document.text, settings.front_end, front_end);
  if (front_end.has_errors()) return {};
  fx::DiagnosticSink units_sink;
  effect->build_programs(units_sink, compiler_.get());
  fx::ShownOnce shown;
  check_shaders(*effect->units, *effect->programs, settings, units_sink, shown);
  const DocumentPlaces places(effect->sources, path);
  return {document_diagnostics(places, shown.diagnostics()),
          technique_lenses(*effect, places, snapshot.config.validation_profiles())};
}

}  // namespace fx::tools::lsp
