// Candidates and a selection plan from an effect's validated techniques.
#include "fx/select/effect_candidates.h"

#include "fx/compile/effect_file.h"

namespace fx {

std::vector<TechniqueCandidate> effect_candidates(std::span<const TechniqueValidation> techniques,
                                                  const SourceManager& sm, size_t max_reasons) {
  std::vector<TechniqueCandidate> out;
  out.reserve(techniques.size());
  for (const TechniqueValidation& t : techniques) {
    TechniqueCandidate c;
    c.name = t.name;
    c.range = t.range;
    c.valid = t.valid;
    for (const TechniqueAnnotation& a : t.annotations)
      std::visit([&](const auto& v) { c.annotations.set(a.first, AnnotationValue(v)); }, a.second);
    for (size_t i = 0; i < t.reasons.size() && i < max_reasons; ++i)
      c.reasons.push_back(located_reason(t.reasons[i], sm));
    if (t.reasons.size() > max_reasons)
      c.reasons.push_back("and " + std::to_string(t.reasons.size() - max_reasons) + " more");
    out.push_back(std::move(c));
  }
  return out;
}

EffectSelection build_effect_selection(EffectFile& effect, const DeviceCaps& caps, DiagnosticSink& diags,
                                       const EffectSelectionOptions& options) {
  EffectSelection s;
  s.techniques = validate_effect(effect, caps, diags, options.compile, options.compiler);
  s.candidates = effect_candidates(s.techniques, effect.sources);
  s.plan = SelectionPlan::build(s.candidates, diags, options.plan);
  return s;
}

}  // namespace fx
