// SelectionPlan::explain: the same choice as select(), with a sentence per candidate.
// Kept apart from selection_plan.cpp because it allocates and the hot path must not.
#include <cmath>
#include <cstdio>

#include "fx/select/selection.h"

namespace fx {
namespace {

// Band edges and positions: "20", "0.5", "inf".
std::string number(float x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(x));
  return buf;
}

// Milliseconds keep one decimal when that is exact enough ("1.0 ms", "1.8 ms").
std::string millis(float x) {
  if (std::isinf(x)) return "inf";
  char buf[32];
  double tenths = double(x) * 10.0;
  if (std::fabs(tenths - std::round(tenths)) < 1e-4) std::snprintf(buf, sizeof buf, "%.1f", double(x));
  else std::snprintf(buf, sizeof buf, "%.3g", double(x));
  return buf;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

std::string band_text(float lo, float hi) {
  // Appended, not "[" + ...: g++ 12 warns (-Wrestrict) on operator+ of a literal and a temporary.
  std::string out = "[";
  out.append(number(lo)).append(", ").append(number(hi)).append(")");
  return out;
}

std::string SelectionPlan::distance_band(uint32_t index) const {
  if (index >= entries_.size()) return {};
  const Entry& e = entries_[index];
  return std::isinf(e.dist_min) && std::isinf(e.dist_max) ? std::string() : band_text(e.dist_min, e.dist_max);
}

const char* to_string(SelectionRoute r) {
  switch (r) {
    case SelectionRoute::direct: return "direct";
    case SelectionRoute::fallback_chain: return "fallback chain";
    case SelectionRoute::effect_fallback: return "effect fallback";
    case SelectionRoute::none: return "none";
  }
  return "none";
}

std::string SelectionPlan::reason(uint32_t index, const SelectionQuery& q, bool widened, uint32_t chosen) const {
  const Entry& e = entries_[index];
  uint8_t f = failures(e, q, widened);
  std::string suffix = widened ? " (band widened by hysteresis)" : "";
  if (f & fail_invalid) return invalid_reasons_[index].empty() ? "invalid" : "invalid: " + invalid_reasons_[index];
  if (f & fail_scheme) return "scheme '" + join(schemes_[index]) + "' not in '" + std::string(q.scheme) + "'";
  if (f & fail_distance) {
    float lo = widened ? e.dist_min_h : e.dist_min, hi = widened ? e.dist_max_h : e.dist_max;
    return "outside distance band " + band_text(lo, hi) + " at " + number(q.distance) + suffix;
  }
  if (f & fail_screen) {
    float lo = widened ? e.size_min_h : e.size_min, hi = widened ? e.size_max_h : e.size_max;
    return "outside screen-size band " + band_text(lo, hi) + " at " + number(q.screen_size) + suffix;
  }
  if (f & fail_error) {
    if (!e.error_known && !unmeasured_reasons_[index].empty())
      return "error not measured (" + unmeasured_reasons_[index] + ") under limit " + number(q.max_error) + " LSB";
    if (!e.error_known)
      return "error not measured (no MaxError annotation) under limit " + number(q.max_error) + " LSB";
    return "error " + number(e.error) + " LSB over limit " + number(q.max_error) + " LSB";
  }
  if (f & fail_cost) return "cost " + millis(cost_ms(e, q)) + " ms over budget " + millis(q.cost_budget_ms) + " ms";
  if (chosen == kNoIndex) return "passed";
  // It passed every filter: it lost on rank to the chosen technique. Each comparison names
  // whose figure is whose: the chosen technique's first, then this one's.
  const Entry& c = entries_[chosen];
  const std::string theirs = "'" + names_[chosen] + "' ";
  auto versus = [&](const std::string& chosen_figure, const std::string& this_figure) {
    return theirs + chosen_figure + ", this one " + this_figure;
  };
  std::string why;
  if (has_error_limit(q) && c.cost_known && !e.cost_known)
    why = "cheaper within the error limit: " + theirs + millis(cost_ms(c, q)) + " ms, this one's cost not measured";
  else if (has_error_limit(q) && cost_ms(c, q) != cost_ms(e, q))
    why = "cheaper within the error limit: " + versus(millis(cost_ms(c, q)) + " ms", millis(cost_ms(e, q)) + " ms");
  else if (has_error_limit(q) && c.cost_ns_per_pixel != e.cost_ns_per_pixel)
    why = "cheaper within the error limit: " +
          versus(number(c.cost_ns_per_pixel) + " ns per pixel", number(e.cost_ns_per_pixel) + " ns per pixel");
  else if (has_error_limit(q) && c.cost_ns_per_vertex != e.cost_ns_per_vertex)
    why = "cheaper within the error limit: " +
          versus(number(c.cost_ns_per_vertex) + " ns per vertex", number(e.cost_ns_per_vertex) + " ns per vertex");
  else if (c.error_known != e.error_known)
    why = "error measured: " + theirs + number(c.error) + " LSB, this one's not measured";
  else if (c.group != e.group) why = "its substitute group is declared first";
  else if (c.error != e.error) why = "lower error: " + versus(number(c.error) + " LSB", number(e.error) + " LSB");
  else if (c.priority != e.priority)
    why = "priority: " + versus(std::to_string(c.priority), std::to_string(e.priority));
  else why = "declared earlier";
  return "ranks below '" + names_[chosen] + "' (" + why + ")";
}

SelectionResult SelectionPlan::explain(const SelectionQuery& q, const SelectionState* state) const {
  SelectionResult result;
  uint32_t last = state && state->plan_key == key_ ? state->last : kNoIndex;
  uint32_t start = kNoIndex;
  result.chosen = choose(q, last, &result.route, &start);
  if (result.chosen != kNoIndex && result.chosen == last && failures(entries_[last], q, false) != 0)
    result.kept_by_hysteresis = true;
  if (result.route == SelectionRoute::fallback_chain) {
    for (uint32_t t = start; t != kNoIndex && result.fallback_path.size() <= entries_.size();
         t = entries_[t].fallback) {
      result.fallback_path.push_back(t);
      if (t == result.chosen) break;
    }
  }
  result.reasons.resize(entries_.size());
  for (uint32_t i = 0; i < entries_.size(); ++i) {
    if (i == result.chosen) continue;
    result.reasons[i] = reason(i, q, i == last, result.chosen);
    if (i == start) result.reasons[i] += "; fell back to '" + names_[result.chosen] + "'";
  }
  return result;
}

}  // namespace fx
