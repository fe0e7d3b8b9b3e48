// SelectionPlan: compiling candidates into packed entries, and the per-object choice.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fx/select/selection.h"

namespace fx {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kMaxSchemes = 63;  // bit 63 stands for "a scheme no technique declares"
constexpr uint64_t kUnknownSchemeBit = uint64_t(1) << 63;

std::vector<std::string> split_list(std::string_view list) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < list.size()) {
    size_t start = list.find_first_not_of(" \t,;|", i);
    if (start == std::string_view::npos) break;
    size_t end = list.find_first_of(" \t,;|", start);
    if (end == std::string_view::npos) end = list.size();
    out.emplace_back(list.substr(start, end - start));
    i = end;
  }
  return out;
}

// Widens [lo, hi) by `fraction` of each edge's magnitude (an infinite edge stays put).
void widen(float lo, float hi, float fraction, float& lo_out, float& hi_out) {
  lo_out = std::isfinite(lo) ? lo - std::fabs(lo) * fraction : lo;
  hi_out = std::isfinite(hi) ? hi + std::fabs(hi) * fraction : hi;
}

// A technique's annotations as selection reads them: a wrong type is a warning and the
// annotation is ignored.
struct AnnotationReader {
  const TechniqueCandidate& c;
  DiagnosticSink& sink;

  void bad_type(std::string_view ann, const char* want) const {
    sink.warning("selection-annotation", c.range,
                 "annotation '" + std::string(ann) + "' of technique '" + c.name + "' must be " + want + "; ignored");
  }
  // The first of `names` given as a number, else `fallback`.
  float number(std::initializer_list<std::string_view> names, float fallback) const {
    for (std::string_view ann : names) {
      if (!c.annotations.find(ann)) continue;
      if (auto v = c.annotations.number(ann)) return *v;
      bad_type(ann, "a number");
    }
    return fallback;
  }
  // The string annotation `name` ("" when absent or not a string).
  std::string text(std::string_view name) const {
    const AnnotationValue* v = c.annotations.find(name);
    if (!v) return {};
    if (const auto* s = std::get_if<std::string>(v)) return *s;
    bad_type(name, "a string");
    return {};
  }
};

}  // namespace

SelectionPlan SelectionPlan::build(std::span<const TechniqueCandidate> candidates, DiagnosticSink& sink,
                                   const SelectionPlanOptions& options) {
  SelectionPlan plan;
  plan.entries_.reserve(candidates.size());
  uint64_t key = 1469598103934665603ull;  // FNV-1a over the names: stale states are ignored
  for (const TechniqueCandidate& c : candidates) {
    plan.add_candidate(c, options.hysteresis, sink);
    for (char ch : c.name + '\n') key = (key ^ uint8_t(ch)) * 1099511628211ull;
  }
  plan.key_ = key ? key : 1;
  plan.resolve_fallbacks(candidates, options.effect_fallback, sink);
  plan.cut_fallback_cycles(candidates, sink);
  plan.rank(candidates);
  return plan;
}

void SelectionPlan::add_candidate(const TechniqueCandidate& c, float hysteresis, DiagnosticSink& sink) {
  const AnnotationMap& a = c.annotations;
  const AnnotationReader read{c, sink};
  Entry e{};
  e.dist_min = read.number({"MinDistance", "LodMin"}, -kInf);
  e.dist_max = read.number({"MaxDistance", "LodMax"}, kInf);
  e.size_min = read.number({"MinScreenSize"}, -kInf);
  e.size_max = read.number({"MaxScreenSize"}, kInf);
  for (auto [lo, hi, what] :
       {std::tuple{e.dist_min, e.dist_max, "distance"}, std::tuple{e.size_min, e.size_max, "screen-size"}}) {
    if (lo >= hi)
      sink.error("selection-annotation", c.range,
                 std::string(what) + " band of technique '" + c.name +
                     "' is empty (minimum not below maximum); it never matches");
  }
  float h = read.number({"Hysteresis"}, hysteresis);
  if (!(h >= 0.f)) h = 0.f;
  widen(e.dist_min, e.dist_max, h, e.dist_min_h, e.dist_max_h);
  widen(e.size_min, e.size_max, h, e.size_min_h, e.size_max_h);
  // A technique without a measured error never passes an error budget (the budget is a
  // promise the annotation has to back) and ranks after every measured one: its error is
  // unknown, not zero. ErrorNotMeasured (costs.fxh) says why.
  e.error_known = a.find("MaxError") || a.find("MaxErrorAbs");
  e.error = read.number({"MaxError"}, 0.f);
  if (!a.find("MaxError")) e.error = read.number({"MaxErrorAbs"}, 0.f) * 255.f;  // absolute -> LSB
  e.cost_known = a.find("CostMs") || a.find("CostNsPerPixel") || a.find("CostNsPerVertex");
  e.cost_ns_per_vertex = read.number({"CostNsPerVertex"}, 0.f);
  e.cost_ms = read.number({"CostMs"}, 0.f);
  e.cost_ns_per_pixel = read.number({"CostNsPerPixel"}, 0.f);
  e.priority = 0;
  if (a.find("Priority")) {
    if (auto p = a.integer("Priority")) e.priority = *p;
    else read.bad_type("Priority", "an int");
  }
  e.valid = c.valid;
  e.fallback = kNoIndex;
  std::vector<std::string> schemes = split_list(read.text("Scheme"));
  e.scheme_mask = scheme_mask(schemes, c, sink);
  std::string invalid;
  for (const auto& r : c.reasons) invalid.append(invalid.empty() ? "" : "; ").append(r);
  entries_.push_back(e);
  names_.push_back(c.name);
  schemes_.push_back(std::move(schemes));
  invalid_reasons_.push_back(std::move(invalid));
  unmeasured_reasons_.push_back(read.text("ErrorNotMeasured"));
}

uint64_t SelectionPlan::scheme_mask(const std::vector<std::string>& schemes, const TechniqueCandidate& c,
                                    DiagnosticSink& sink) {
  uint64_t mask = 0;
  for (const auto& s : schemes) {
    auto it = std::find(scheme_names_.begin(), scheme_names_.end(), s);
    size_t bit = size_t(it - scheme_names_.begin());
    if (it == scheme_names_.end()) {
      if (scheme_names_.size() == kMaxSchemes) {
        sink.error("selection-annotation", c.range, "more than 63 distinct schemes; scheme '" + s + "' ignored");
        continue;
      }
      scheme_names_.push_back(s);
    }
    mask |= uint64_t(1) << bit;
  }
  return mask;
}

// Fallback names resolve after every candidate is known (a fallback may come later).
void SelectionPlan::resolve_fallbacks(std::span<const TechniqueCandidate> candidates, std::string_view effect_fallback,
                                      DiagnosticSink& sink) {
  std::vector<std::string_view> name_views(names_.begin(), names_.end());
  auto resolve = [&](std::string_view target, const TechniqueCandidate* from) -> uint32_t {
    if (auto idx = index_of(target)) return *idx;
    std::string message = "fallback technique '" + std::string(target) + "' does not exist";
    if (from) message = "technique '" + from->name + "': " + message;
    std::string guess = closest_match(target, name_views);
    if (!guess.empty()) message += "; did you mean '" + guess + "'?";
    sink.error("unknown-fallback", from ? from->range : SourceRange{}, message);
    return kNoIndex;
  };
  for (size_t i = 0; i < candidates.size(); ++i) {
    const AnnotationValue* f = candidates[i].annotations.find("Fallback");
    if (!f) continue;
    if (const auto* target = std::get_if<std::string>(f)) entries_[i].fallback = resolve(*target, &candidates[i]);
    else AnnotationReader{candidates[i], sink}.bad_type("Fallback", "a string");
  }
  if (!effect_fallback.empty()) effect_fallback_ = resolve(effect_fallback, nullptr);
}

// Walks each chain once, colouring nodes; a link into a node on the current walk closes a
// cycle and is cut.
void SelectionPlan::cut_fallback_cycles(std::span<const TechniqueCandidate> candidates, DiagnosticSink& sink) {
  const size_t n = candidates.size();
  std::vector<uint8_t> colour(n, 0);  // 0 new, 1 on the current walk, 2 finished
  for (size_t start = 0; start < n; ++start) {
    std::vector<uint32_t> walk;
    uint32_t i = uint32_t(start);
    while (i != kNoIndex && colour[i] == 0) {
      colour[i] = 1;
      walk.push_back(i);
      uint32_t next = entries_[i].fallback;
      if (next != kNoIndex && colour[next] == 1) {
        std::string path;
        auto from = std::find(walk.begin(), walk.end(), next);
        for (auto it = from; it != walk.end(); ++it) path += "'" + names_[*it] + "' -> ";
        path += "'" + names_[next] + "'";
        sink.error("fallback-cycle", candidates[i].range,
                   "fallback cycle " + path + "; the link from '" + names_[i] + "' is ignored");
        entries_[i].fallback = kNoIndex;
        next = kNoIndex;
      }
      i = next;
    }
    for (uint32_t w : walk) colour[w] = 2;
  }
}

// Errors compare only within a substitute group (the same reference model); the groups
// keep the order in which the effect declares them.
void SelectionPlan::rank(std::span<const TechniqueCandidate> candidates) {
  const size_t n = candidates.size();
  std::vector<std::string> groups(n);
  for (size_t i = 0; i < n; ++i) {
    if (const AnnotationValue* g = candidates[i].annotations.find("Substitutes"))
      if (const auto* text = std::get_if<std::string>(g)) groups[i] = *text;
    entries_[i].group = uint32_t(std::find(groups.begin(), groups.begin() + i + 1, groups[i]) - groups.begin());
  }
  order_.resize(n);
  for (size_t i = 0; i < n; ++i) order_[i] = uint32_t(i);
  std::stable_sort(order_.begin(), order_.end(), [&](uint32_t x, uint32_t y) {
    const Entry &a = entries_[x], &b = entries_[y];
    if (a.error_known != b.error_known) return a.error_known;
    if (a.error_known && a.group != b.group) return a.group < b.group;
    if (a.error != b.error) return a.error < b.error;
    return a.priority > b.priority;
  });
}

SelectionQuery SelectionPlan::query(const SelectionCriteria& c) const {
  SelectionQuery q;
  q.distance = c.distance;
  q.screen_size = c.screen_size;
  q.pixels = c.pixels;
  q.vertices = c.vertices;
  q.cost_budget_ms = c.cost_budget_ms;
  q.max_error = c.max_error;
  q.scheme = c.scheme;
  if (!c.scheme.empty()) {
    auto it = std::find(scheme_names_.begin(), scheme_names_.end(), c.scheme);
    q.scheme_bit = it == scheme_names_.end() ? kUnknownSchemeBit : uint64_t(1) << (it - scheme_names_.begin());
  }
  return q;
}

uint8_t SelectionPlan::failures(const Entry& e, const SelectionQuery& q, bool widened) const {
  uint8_t f = 0;
  if (!e.valid) f |= fail_invalid;
  if (q.scheme_bit && e.scheme_mask && !(e.scheme_mask & q.scheme_bit)) f |= fail_scheme;
  // Written as "outside" tests so an unknown (NaN) distance passes every band.
  float dmin = widened ? e.dist_min_h : e.dist_min, dmax = widened ? e.dist_max_h : e.dist_max;
  if (q.distance < dmin || q.distance >= dmax) f |= fail_distance;
  if (q.screen_size >= 0.f) {
    float smin = widened ? e.size_min_h : e.size_min, smax = widened ? e.size_max_h : e.size_max;
    if (q.screen_size < smin || q.screen_size >= smax) f |= fail_screen;
  }
  if (e.error > q.max_error || (!e.error_known && has_error_limit(q))) f |= fail_error;
  if (cost_ms(e, q) > q.cost_budget_ms) f |= fail_cost;
  return f;
}

float SelectionPlan::cost_ms(const Entry& e, const SelectionQuery& q) {
  return e.cost_ms + e.cost_ns_per_pixel * q.pixels * 1e-6f + e.cost_ns_per_vertex * q.vertices * 1e-6f;
}

bool SelectionPlan::cheaper(const Entry& a, const Entry& b, const SelectionQuery& q) {
  if (a.cost_known != b.cost_known) return a.cost_known;
  if (!a.cost_known) return false;
  const float ca = cost_ms(a, q), cb = cost_ms(b, q);
  if (ca != cb) return ca < cb;
  if (a.cost_ns_per_pixel != b.cost_ns_per_pixel) return a.cost_ns_per_pixel < b.cost_ns_per_pixel;
  return a.cost_ns_per_vertex < b.cost_ns_per_vertex;
}

bool SelectionPlan::has_error_limit(const SelectionQuery& q) { return q.max_error < kInf; }

uint32_t SelectionPlan::first_survivor(const SelectionQuery& q, uint32_t last) const {
  // Without an error budget the best-ranked survivor wins; with one, "good enough" is
  // decided, so the cheapest survivor wins (ties, and unmeasured costs, keep rank order).
  const bool cheapest = has_error_limit(q);
  uint32_t best = kNoIndex;
  for (uint32_t i : order_) {
    if (failures(entries_[i], q, i == last) != 0) continue;
    if (!cheapest) return i;
    if (best == kNoIndex || cheaper(entries_[i], entries_[best], q)) best = i;
  }
  return best;
}

uint32_t SelectionPlan::choose(const SelectionQuery& q, uint32_t last, SelectionRoute* route,
                               uint32_t* chain_start) const {
  if (uint32_t i = first_survivor(q, last); i != kNoIndex) {
    *route = SelectionRoute::direct;
    return i;
  }
  // Nothing survived: follow the explicit chain of the best technique the application
  // asked for (right scheme and band) that the device or a budget ruled out.
  constexpr uint8_t kIntent = fail_scheme | fail_distance | fail_screen;
  for (uint32_t i : order_) {
    if (failures(entries_[i], q, i == last) & kIntent) continue;
    uint32_t t = entries_[i].fallback;
    for (size_t steps = 0; t != kNoIndex && steps < entries_.size(); ++steps) {
      // Under an error limit the chain skips techniques beyond it or not measured: a limit
      // is a promise about the picture, which a fallback does not get to break.
      if (entries_[t].valid && !(failures(entries_[t], q, false) & fail_error)) {
        *route = SelectionRoute::fallback_chain;
        *chain_start = i;
        return t;
      }
      t = entries_[t].fallback;
    }
  }
  if (effect_fallback_ != kNoIndex && entries_[effect_fallback_].valid) {
    *route = SelectionRoute::effect_fallback;
    return effect_fallback_;
  }
  *route = SelectionRoute::none;
  return kNoIndex;
}

uint32_t SelectionPlan::select(const SelectionQuery& q, SelectionState& state) const {
  uint32_t last = state.plan_key == key_ ? state.last : kNoIndex;
  SelectionRoute route;
  uint32_t start = kNoIndex;
  uint32_t chosen = choose(q, last, &route, &start);
  state.last = chosen;
  state.plan_key = key_;
  return chosen;
}

uint32_t SelectionPlan::select(const SelectionQuery& q) const {
  SelectionRoute route;
  uint32_t start = kNoIndex;
  return choose(q, kNoIndex, &route, &start);
}

std::string_view SelectionPlan::name(uint32_t index) const {
  return index < names_.size() ? std::string_view(names_[index]) : std::string_view();
}

std::optional<uint32_t> SelectionPlan::index_of(std::string_view name) const {
  for (size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return uint32_t(i);
  return std::nullopt;
}

}  // namespace fx
