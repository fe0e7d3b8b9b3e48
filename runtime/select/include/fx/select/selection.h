// Technique selection: a SelectionPlan is compiled once per effect from its candidates
// (bands, interned schemes, costs, errors, fallback links, rank order) and then answers
// per object with a few compares and no allocation. Rules: docs/selection.md.
#pragma once
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/no_index.h"
#include "fx/select/technique_candidate.h"

namespace fx {

// What the application asks for this object this frame.
struct SelectionCriteria {
  float distance = 0.f;          // camera distance, world units
  float screen_size = -1.f;      // projected size in pixels; negative = unknown (bands ignored)
  float pixels = 0.f;            // covered pixels, turns CostNsPerPixel into milliseconds
  float vertices = 0.f;          // vertices drawn, turns CostNsPerVertex into milliseconds
  std::string_view scheme = {};  // "" accepts every scheme
  float cost_budget_ms = std::numeric_limits<float>::infinity();  // per object
  float max_error = std::numeric_limits<float>::infinity();       // 8-bit levels (LSB)
};

// SelectionCriteria with the scheme interned against one plan. Make one per frame with
// SelectionPlan::query, then change distance / screen_size / pixels per object.
struct SelectionQuery {
  float distance = 0.f;
  float screen_size = -1.f;
  float pixels = 0.f;
  float vertices = 0.f;
  float cost_budget_ms = std::numeric_limits<float>::infinity();
  float max_error = std::numeric_limits<float>::infinity();
  uint64_t scheme_bit = 0;       // 0 = any scheme
  std::string_view scheme = {};  // for reason texts only
};

// Per-object memory that makes band edges sticky (hysteresis).
struct SelectionState {
  uint32_t last = kNoIndex;
  uint64_t plan_key = 0;  // the plan `last` belongs to; another plan ignores it
};

// How the choice was reached.
enum class SelectionRoute : uint8_t { direct, fallback_chain, effect_fallback, none };
const char* to_string(SelectionRoute r);

// A choice with its explanation: one reason per candidate ("" for the chosen one).
struct SelectionResult {
  uint32_t chosen = kNoIndex;
  SelectionRoute route = SelectionRoute::none;
  bool kept_by_hysteresis = false;      // chosen only because its band was widened
  std::vector<uint32_t> fallback_path;  // candidate indices walked, start first
  std::vector<std::string> reasons;     // indexed like the candidates
  bool ok() const { return chosen != kNoIndex; }
};

// Plan-wide settings.
struct SelectionPlanOptions {
  std::string effect_fallback = {};  // technique used when nothing else survives ("" = none)
  float hysteresis = 0.1f;           // default band margin as a fraction of the edge value
};

// A band [lo, hi) as selection's reasons print it: "[-inf, 40)", "[0.5, 2)".
std::string band_text(float lo, float hi);

class SelectionPlan {
 public:
  SelectionPlan() = default;
  // Compiles candidates. Bad annotations, unknown fallback names and fallback cycles are
  // reported ("selection-annotation", "unknown-fallback", "fallback-cycle"); a cycle is cut
  // at the link that closes it, so selection always terminates.
  static SelectionPlan build(std::span<const TechniqueCandidate> candidates, DiagnosticSink& sink,
                             const SelectionPlanOptions& options = {});

  // Interns the criteria's scheme; an unknown scheme matches only untagged techniques.
  SelectionQuery query(const SelectionCriteria& criteria) const;
  // Chooses for one object and updates its state. No allocation.
  uint32_t select(const SelectionQuery& q, SelectionState& state) const;
  // Chooses without memory (no hysteresis).
  uint32_t select(const SelectionQuery& q) const;
  // The same choice as select(q, state) (state untouched), with a reason per candidate.
  SelectionResult explain(const SelectionQuery& q, const SelectionState* state = nullptr) const;

  size_t size() const { return entries_.size(); }
  std::string_view name(uint32_t index) const;
  // The distance band the plan tests a candidate against, as explain() prints it
  // ("[-inf, 40)", "[40, inf)"); "" when the candidate has none.
  std::string distance_band(uint32_t index) const;
  std::optional<uint32_t> index_of(std::string_view name) const;
  // Candidate indices from best to worst rank: techniques with a measured error first; among
  // them substitute groups (the Substitutes annotation: errors measured against the same
  // model) in the order their first technique is declared, lowest error first within a
  // group; then the techniques whose error is not measured; ties by priority, then
  // declaration.
  std::span<const uint32_t> rank_order() const { return order_; }
  uint64_t key() const { return key_; }

 private:
  // Everything the per-object test reads, packed together.
  struct Entry {
    float dist_min, dist_max, size_min, size_max;          // [min, max)
    float dist_min_h, dist_max_h, size_min_h, size_max_h;  // widened by hysteresis
    float error, cost_ms, cost_ns_per_pixel, cost_ns_per_vertex;
    uint64_t scheme_mask;  // 0 = any scheme
    uint32_t fallback;     // index or kNoIndex
    int32_t priority;
    uint32_t group;  // declaration index of the first technique with the same Substitutes
    bool valid;
    bool error_known;  // MaxError or MaxErrorAbs given
    bool cost_known;   // CostMs or CostNsPerPixel given
  };
  enum Failure : uint8_t {
    fail_invalid = 1,
    fail_scheme = 2,
    fail_distance = 4,
    fail_screen = 8,
    fail_error = 16,
    fail_cost = 32,
  };
  uint8_t failures(const Entry& e, const SelectionQuery& q, bool widened) const;
  static float cost_ms(const Entry& e, const SelectionQuery& q);
  // Cheaper within an error limit: lower cost_ms, then (no pixel or vertex count given,
  // so cost_ms ties) lower ns per pixel, then lower ns per vertex. Unmeasured cost: last.
  static bool cheaper(const Entry& a, const Entry& b, const SelectionQuery& q);
  // A finite error limit: unmeasured techniques fail it and the cheapest survivor wins.
  static bool has_error_limit(const SelectionQuery& q);
  // The technique the filters and ranking choose directly, or kNoIndex.
  uint32_t first_survivor(const SelectionQuery& q, uint32_t last) const;
  uint32_t choose(const SelectionQuery& q, uint32_t last, SelectionRoute* route, uint32_t* chain_start) const;
  std::string reason(uint32_t index, const SelectionQuery& q, bool widened, uint32_t chosen) const;
  // build()'s steps: each candidate's annotations read into an entry, fallback names
  // resolved, fallback cycles cut, the rank order.
  void add_candidate(const TechniqueCandidate& c, float hysteresis, DiagnosticSink& sink);
  uint64_t scheme_mask(const std::vector<std::string>& schemes, const TechniqueCandidate& c, DiagnosticSink& sink);
  void resolve_fallbacks(std::span<const TechniqueCandidate> candidates, std::string_view effect_fallback,
                         DiagnosticSink& sink);
  void cut_fallback_cycles(std::span<const TechniqueCandidate> candidates, DiagnosticSink& sink);
  void rank(std::span<const TechniqueCandidate> candidates);

  std::vector<Entry> entries_;
  std::vector<uint32_t> order_;
  std::vector<std::string> names_;
  std::vector<std::vector<std::string>> schemes_;  // per candidate, for reason texts
  std::vector<std::string> invalid_reasons_;       // per candidate, joined
  std::vector<std::string> unmeasured_reasons_;    // per candidate: its ErrorNotMeasured text
  std::vector<std::string> scheme_names_;          // bit i <-> scheme_names_[i]
  uint32_t effect_fallback_ = kNoIndex;
  uint64_t key_ = 0;
};

}  // namespace fx
