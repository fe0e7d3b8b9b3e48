// TechniqueChoice: TechniqueFacts -> validated TechniqueCandidates -> SelectionPlan. This
// file includes the selection headers and must not include the effect model (see header).
#include "fx/reload/technique_choice.h"

#include "fx/select/selection.h"
#include "fx/select/technique_candidate.h"

namespace fx {

StoredCriteria::StoredCriteria() : criteria_(std::make_unique<SelectionCriteria>()) {}
StoredCriteria::StoredCriteria(const SelectionCriteria& criteria)
    : scheme_(criteria.scheme), criteria_(std::make_unique<SelectionCriteria>(criteria)) {
  criteria_->scheme = scheme_;
}
StoredCriteria::~StoredCriteria() = default;
StoredCriteria::StoredCriteria(const StoredCriteria& other) : StoredCriteria(other.get()) {}
StoredCriteria& StoredCriteria::operator=(const StoredCriteria& other) {
  if (this != &other) {
    scheme_ = std::string(other.get().scheme);
    *criteria_ = other.get();
    criteria_->scheme = scheme_;
  }
  return *this;
}
const SelectionCriteria& StoredCriteria::get() const { return *criteria_; }

struct TechniqueChoice::Impl {
  std::vector<TechniqueCandidate> candidates;
  SelectionPlan plan;
};

TechniqueChoice::TechniqueChoice() : impl_(std::make_unique<Impl>()) {}
TechniqueChoice::~TechniqueChoice() = default;

std::shared_ptr<const TechniqueChoice> TechniqueChoice::build(std::vector<TechniqueFacts> techniques,
                                                              const DeviceCaps* caps, DiagnosticSink& diags) {
  std::shared_ptr<TechniqueChoice> choice(new TechniqueChoice());
  for (TechniqueFacts& t : techniques) {
    TechniqueCandidate c;
    c.name = std::move(t.name);
    c.range = t.range;
    for (auto& [name, value] : t.annotations) c.annotations.set(std::move(name), std::move(value));
    c.valid = t.valid;
    c.reasons = std::move(t.reasons);
    choice->impl_->candidates.push_back(std::move(c));
  }
  if (caps) validate(choice->impl_->candidates, *caps);
  choice->impl_->plan = SelectionPlan::build(choice->impl_->candidates, diags);
  return choice;
}

std::shared_ptr<const TechniqueChoice> TechniqueChoice::restricted(
    const std::vector<std::vector<std::string>>& extra) const {
  std::shared_ptr<TechniqueChoice> choice(new TechniqueChoice());
  choice->impl_->candidates = impl_->candidates;
  for (size_t i = 0; i < extra.size() && i < choice->impl_->candidates.size(); ++i) {
    TechniqueCandidate& c = choice->impl_->candidates[i];
    for (const std::string& why : extra[i]) c.reasons.push_back(why);
    c.valid = c.valid && extra[i].empty();
  }
  DiagnosticSink ignored;  // the plan's annotation diagnostics were reported with this choice
  choice->impl_->plan = SelectionPlan::build(choice->impl_->candidates, ignored);
  return choice;
}

uint32_t TechniqueChoice::select(const SelectionCriteria& criteria, uint32_t& last, uint64_t& plan_key) const {
  SelectionState state{last, plan_key};
  uint32_t chosen = impl_->plan.select(impl_->plan.query(criteria), state);
  last = state.last;
  plan_key = state.plan_key;
  return chosen;
}

size_t TechniqueChoice::size() const { return impl_->candidates.size(); }
std::string_view TechniqueChoice::name(uint32_t index) const {
  return index < impl_->candidates.size() ? std::string_view(impl_->candidates[index].name) : std::string_view();
}
bool TechniqueChoice::valid(uint32_t index) const {
  return index < impl_->candidates.size() && impl_->candidates[index].valid;
}
const std::vector<std::string>& TechniqueChoice::reasons(uint32_t index) const {
  static const std::vector<std::string> kNone;
  return index < impl_->candidates.size() ? impl_->candidates[index].reasons : kNone;
}
const SelectionPlan& TechniqueChoice::plan() const { return impl_->plan; }

}  // namespace fx
