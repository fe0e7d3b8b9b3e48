// Technique validation and selection for one effect version, behind a header that names
// neither the effect model nor the selection headers. The model side fills TechniqueFacts;
// the selection side (technique_choice.cpp) turns them into candidates and a SelectionPlan.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/no_index.h"
#include "fx/select/annotation_value.h"
#include "fx/select/device_caps.h"
#include "fx/source_location.h"

namespace fx {

struct SelectionCriteria;
class SelectionPlan;

// What selection needs from one technique of the model.
struct TechniqueFacts {
  std::string name;
  SourceRange range;
  // Scalar and string annotations, typed as the file writes them.
  std::vector<std::pair<std::string, AnnotationValue>> annotations;
  bool valid = true;                 // every pass compiled and linked
  std::vector<std::string> reasons;  // why not (unsupported or failed passes)
};

// Criteria kept across reloads (the scheme string is owned).
class StoredCriteria {
 public:
  StoredCriteria();
  explicit StoredCriteria(const SelectionCriteria& criteria);
  ~StoredCriteria();
  StoredCriteria(const StoredCriteria&);
  StoredCriteria& operator=(const StoredCriteria&);
  const SelectionCriteria& get() const;

 private:
  std::string scheme_;
  std::unique_ptr<SelectionCriteria> criteria_;
};

// Validated candidates and their selection plan. Immutable after build().
class TechniqueChoice {
 public:
  // Validates against `caps` (when given) and compiles the plan; plan diagnostics
  // (bad annotations, unknown fallbacks) go to `diags` as warnings or errors.
  static std::shared_ptr<const TechniqueChoice> build(std::vector<TechniqueFacts> techniques, const DeviceCaps* caps,
                                                      DiagnosticSink& diags);
  ~TechniqueChoice();

  // Chooses with per-object memory (`last`, `plan_key`: see fx::SelectionState).
  uint32_t select(const SelectionCriteria& criteria, uint32_t& last, uint64_t& plan_key) const;
  size_t size() const;
  std::string_view name(uint32_t index) const;
  // Whether the technique survived validation, and why not.
  bool valid(uint32_t index) const;
  const std::vector<std::string>& reasons(uint32_t index) const;
  // The same techniques with more reasons to reject them (`extra[i]` for technique i, empty
  // when it has none): validation against a caps profile to emulate. Valid only where both
  // this choice and the extra validation accept a technique, with both sets of reasons.
  std::shared_ptr<const TechniqueChoice> restricted(const std::vector<std::vector<std::string>>& extra) const;
  // The plan itself, for callers that include fx/select/selection.h.
  const SelectionPlan& plan() const;

 private:
  TechniqueChoice();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fx
