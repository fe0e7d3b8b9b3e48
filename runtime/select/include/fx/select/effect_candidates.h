// Selection for a real effect: TechniqueCandidates from validated techniques (annotations
// copied, validity and located reasons from technique validation) and the SelectionPlan
// over them. See docs/selection.md, "Validation".
#pragma once
#include <span>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/select/device_caps.h"
#include "fx/select/selection.h"
#include "fx/select/technique_candidate.h"
#include "fx/select/technique_validation.h"
#include "fx/source_manager.h"

namespace fx {

// One candidate per validated technique, in the same order. Rejection reasons read
// "file.fx:12: message" (at most `max_reasons` each, then "and N more"). The candidates
// are already validated: calling validate(candidates, caps) again would repeat the
// `Requires` reasons.
std::vector<TechniqueCandidate> effect_candidates(std::span<const TechniqueValidation> techniques,
                                                  const SourceManager& sm, size_t max_reasons = 4);

// How build_effect_selection validates and plans.
struct EffectSelectionOptions {
  bool compile = true;                       // compile passes and check them against limits
  const ShaderCompiler* compiler = nullptr;  // nullptr: a default compiler for this call
  SelectionPlanOptions plan;                 // effect fallback, hysteresis
};

// An effect's techniques on one device, ready to select per object.
struct EffectSelection {
  std::vector<TechniqueValidation> techniques;  // with every located reason
  std::vector<TechniqueCandidate> candidates;   // parallel to techniques
  SelectionPlan plan;
  // The first valid technique in declaration order (D3DX's default choice), if any.
  std::optional<size_t> first_valid() const { return find_next_valid(techniques); }
};

// Validates every technique of `effect` on `caps` (validate_effect), builds the candidates and the plan. Model
// and plan diagnostics (bad annotations, unknown fallbacks) go to `diags`.
EffectSelection build_effect_selection(EffectFile& effect, const DeviceCaps& caps, DiagnosticSink& diags,
                                       const EffectSelectionOptions& options = {});

}  // namespace fx
