// SelectionPlan: bands with hysteresis, schemes, budgets, ranking, fallback chains, cycles,
// reason texts, and agreement between the fast path and explain().
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "fx/select/selection.h"

namespace {

using Ann = std::initializer_list<std::pair<std::string, fx::AnnotationValue>>;

fx::TechniqueCandidate tech(std::string name, Ann annotations, bool valid = true) {
  fx::TechniqueCandidate t;
  t.name = std::move(name);
  t.annotations = fx::AnnotationMap(annotations);
  t.valid = valid;
  if (!valid) t.reasons = {"ps_3_0 not supported on dx9"};
  return t;
}

fx::SelectionPlan build(const std::vector<fx::TechniqueCandidate>& list, fx::SelectionPlanOptions options = {}) {
  fx::DiagnosticSink sink;
  fx::SelectionPlan plan = fx::SelectionPlan::build(list, sink, options);
  EXPECT_EQ(sink.diagnostics().size(), 0u) << (sink.diagnostics().empty() ? "" : sink.diagnostics()[0].message);
  return plan;
}

// near [0, 20) exact, far [20, inf) 2 LSB off: the classic two-band LOD pair.
std::vector<fx::TechniqueCandidate> lod_pair() {
  return {tech("near", {{"MinDistance", 0.f}, {"MaxDistance", 20.f}, {"MaxError", 0.f}}),
          tech("far", {{"LodMin", 20.f}, {"MaxError", 2.f}})};
}

TEST(Selection, DistanceBandsPickByDistance) {
  fx::SelectionPlan plan = build(lod_pair());
  fx::SelectionQuery q = plan.query({});
  for (auto [d, want] : {std::pair{0.f, 0u}, {19.9f, 0u}, {20.f, 1u}, {1000.f, 1u}}) {
    q.distance = d;
    EXPECT_EQ(plan.select(q), want) << d;
  }
  q.distance = 35.f;
  EXPECT_EQ(plan.explain(q).reasons[0], "outside distance band [0, 20) at 35");
}

TEST(Selection, HysteresisHoldsABandUntilTheEdgeIsCrossedByTheMargin) {
  fx::SelectionPlan plan = build(lod_pair());
  fx::SelectionQuery q = plan.query({});
  fx::SelectionState state;
  // Approach from far away: "near" is taken as soon as its band is entered.
  std::vector<std::pair<float, uint32_t>> approach = {{30.f, 1}, {21.f, 1}, {20.01f, 1}, {19.99f, 0}};
  for (auto [d, want] : approach) {
    q.distance = d;
    EXPECT_EQ(plan.select(q, state), want) << "approach " << d;
  }
  // Retreat: "near" is kept up to 20 + 10% and left only beyond it.
  std::vector<std::pair<float, uint32_t>> retreat = {{20.5f, 0}, {21.9f, 0}, {22.1f, 1}, {21.f, 1}};
  for (auto [d, want] : retreat) {
    q.distance = d;
    fx::SelectionResult why = plan.explain(q, &state);
    EXPECT_EQ(plan.select(q, state), want) << "retreat " << d;
    EXPECT_EQ(why.chosen, want);
    if (d == 20.5f) {
      EXPECT_TRUE(why.kept_by_hysteresis);
    }
  }
  // Jitter across the edge: with state it switches once, without it every frame.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> jitter(19.5f, 20.5f);
  fx::SelectionState jitter_state;
  uint32_t prev_with = fx::kNoIndex, prev_without = fx::kNoIndex;
  int switches_with = -1, switches_without = -1;
  for (int frame = 0; frame < 200; ++frame) {
    q.distance = jitter(rng);
    uint32_t with = plan.select(q, jitter_state), without = plan.select(q);
    switches_with += with != prev_with;
    switches_without += without != prev_without;
    prev_with = with;
    prev_without = without;
  }
  EXPECT_LE(switches_with, 1);
  EXPECT_GT(switches_without, 50);
}

TEST(Selection, HysteresisAnnotationAndStaleStates) {
  auto list = lod_pair();
  list[0].annotations.set("Hysteresis", 0.5f);
  fx::SelectionPlan plan = build(list);
  fx::SelectionQuery q = plan.query({.distance = 5.f});
  fx::SelectionState state;
  EXPECT_EQ(plan.select(q, state), 0u);
  q.distance = 29.f;  // inside [0, 30)
  EXPECT_EQ(plan.select(q, state), 0u);
  // A plan with the same technique names (a reload) keeps the memory but its own margins.
  fx::SelectionPlan reloaded = build(lod_pair());
  EXPECT_EQ(reloaded.key(), plan.key());
  fx::SelectionState copy = state;
  EXPECT_EQ(reloaded.select(q, copy), 1u);
  q.distance = 21.f;
  copy = state;
  EXPECT_EQ(reloaded.select(q, copy), 0u);
  // A state from another effect's plan carries no memory.
  fx::SelectionPlan renamed = build({tech("a", {{"MaxDistance", 20.f}}), tech("b", {})});
  EXPECT_NE(renamed.key(), plan.key());
  copy = state;
  EXPECT_EQ(renamed.select(q, copy), 1u);
}

TEST(Selection, ScreenSizeBands) {
  fx::SelectionPlan plan = build({tech("detailed", {{"MinScreenSize", 64.f}}), tech("simple", {})});
  EXPECT_EQ(plan.select(plan.query({.screen_size = 100.f})), 0u);
  EXPECT_EQ(plan.select(plan.query({.screen_size = 20.f})), 1u);
  EXPECT_EQ(plan.select(plan.query({})), 0u);  // unknown size: bands do not filter
  EXPECT_EQ(plan.explain(plan.query({.screen_size = 20.f})).reasons[0], "outside screen-size band [64, inf) at 20");
}

TEST(Selection, SchemesFilterAndUnknownSchemesMatchOnlyUntagged) {
  fx::SelectionPlan plan = build({tech("fancy", {{"Scheme", std::string("quality")}, {"MaxError", 0.f}}),
                                  tech("fast", {{"Scheme", std::string("performance, low_power")}, {"MaxError", 0.f}}),
                                  tech("plain", {{"MaxError", 3.f}})});
  EXPECT_EQ(plan.select(plan.query({.scheme = "quality"})), 0u);
  EXPECT_EQ(plan.select(plan.query({.scheme = "low_power"})), 1u);
  EXPECT_EQ(plan.select(plan.query({.scheme = "cinematic"})), 2u);
  EXPECT_EQ(plan.select(plan.query({})), 0u);
  fx::SelectionResult r = plan.explain(plan.query({.scheme = "quality"}));
  EXPECT_EQ(r.reasons[1], "scheme 'performance, low_power' not in 'quality'");
  EXPECT_EQ(r.reasons[2], "ranks below 'fancy' (lower error: 'fancy' 0 LSB, this one 3 LSB)");
  fx::SelectionPlan perf = build({tech("perf", {{"Scheme", std::string("performance")}}), tech("q", {})});
  EXPECT_EQ(perf.explain(perf.query({.scheme = "quality"})).reasons[0], "scheme 'performance' not in 'quality'");
}

TEST(Selection, CostAndErrorBudgets) {
  fx::SelectionPlan plan = build({
      tech("reference", {{"CostMs", 1.8f}, {"MaxError", 0.f}}),
      tech("lut", {{"CostNsPerPixel", 2.f}, {"MaxError", 1.f}}),
      tech("approx", {{"CostMs", 0.1f}, {"MaxErrorAbs", 4.f / 255.f}}),
  });
  EXPECT_EQ(plan.select(plan.query({})), 0u);
  // 2 ns/pixel * 200k pixels = 0.4 ms: fits 1 ms.
  fx::SelectionQuery q = plan.query({.pixels = 200000.f, .cost_budget_ms = 1.f});
  EXPECT_EQ(plan.select(q), 1u);
  fx::SelectionResult r = plan.explain(q);
  EXPECT_EQ(r.reasons[0], "cost 1.8 ms over budget 1.0 ms");
  EXPECT_EQ(r.reasons[2], "ranks below 'lut' (lower error: 'lut' 1 LSB, this one 4 LSB)");
  q.pixels = 1e6f;  // 2 ms now
  EXPECT_EQ(plan.select(q), 2u);
  EXPECT_EQ(plan.explain(q).reasons[1], "cost 2.0 ms over budget 1.0 ms");
  q.max_error = 2.f;
  EXPECT_EQ(plan.select(q), fx::kNoIndex);
  EXPECT_EQ(plan.explain(q).reasons[2], "error 4 LSB over limit 2 LSB");
}

// An error limit means "good enough": the cheapest technique within it wins, and a technique
// with no measured error cannot promise to be within it.
TEST(Selection, ErrorLimitPicksTheCheapestMeasuredTechnique) {
  fx::SelectionPlan plan = build({
      tech("reference", {{"CostNsPerPixel", 9.f}}),
      tech("analytic", {{"CostNsPerPixel", 6.f}, {"MaxError", 0.f}}),
      tech("lut", {{"CostNsPerPixel", 4.f}, {"MaxError", 3.f}}),
      tech("coarse", {{"CostNsPerPixel", 2.f}, {"MaxError", 20.f}}),
  });
  const float inf = std::numeric_limits<float>::infinity();
  // No limit: rank order, where the unmeasured 'reference' ranks after every measured error.
  EXPECT_EQ(plan.select(plan.query({.pixels = 1e6f, .max_error = inf})), 1u);
  fx::SelectionQuery q = plan.query({.pixels = 1e6f, .max_error = 4.f});
  EXPECT_EQ(plan.select(q), 2u);
  fx::SelectionResult r = plan.explain(q);
  EXPECT_EQ(r.reasons[0], "error not measured (no MaxError annotation) under limit 4 LSB");
  EXPECT_EQ(r.reasons[1], "ranks below 'lut' (cheaper within the error limit: 'lut' 4.0 ms, this one 6.0 ms)");
  EXPECT_EQ(r.reasons[3], "error 20 LSB over limit 4 LSB");
  EXPECT_EQ(plan.select(plan.query({.pixels = 1e6f, .max_error = 0.5f})), 1u);
  EXPECT_EQ(plan.select(plan.query({.pixels = 1e6f, .max_error = 100.f})), 3u);
  // A measured error without a measured cost ranks after every measured cost.
  fx::SelectionPlan partial =
      build({tech("table", {{"MaxError", 3.f}}), tech("pow", {{"CostNsPerPixel", 5.f}, {"MaxError", 3.f}})});
  fx::SelectionQuery pq = partial.query({.pixels = 1e6f, .max_error = 4.f});
  EXPECT_EQ(partial.select(pq), 1u);
  EXPECT_EQ(partial.explain(pq).reasons[0],
            "ranks below 'pow' (cheaper within the error limit: 'pow' 5.0 ms, this one's cost not measured)");
  // Equal costs keep rank order (lower error first).
  fx::SelectionPlan tie =
      build({tech("a", {{"CostMs", 1.f}, {"MaxError", 2.f}}), tech("b", {{"CostMs", 1.f}, {"MaxError", 1.f}})});
  fx::SelectionQuery tq = tie.query({.max_error = 5.f});
  EXPECT_EQ(tie.select(tq), 1u);
  EXPECT_EQ(tie.explain(tq).reasons[0], "ranks below 'b' (lower error: 'b' 1 LSB, this one 2 LSB)");
}

// An unknown error is unknown, not zero: the technique ranks after the measured ones (so
// annotating one technique and not its sibling cannot make the sibling look exact), fails
// every error limit, and the reason names what costs.fxh says about it.
TEST(Selection, UnmeasuredErrorIsUnknownNotExact) {
  fx::SelectionPlan plan = build({
      tech("asm", {{"ErrorNotMeasured", std::string("not drawable on Vulkan: ps.1.1 assembly")}}),
      tech("seed", {{"CostNsPerPixel", 3.f}, {"MaxError", 28.f}}),
      tech("exact", {{"CostNsPerPixel", 5.f}, {"MaxError", 0.5f}}),
  });
  EXPECT_EQ(std::vector<uint32_t>(plan.rank_order().begin(), plan.rank_order().end()),
            (std::vector<uint32_t>{2, 1, 0}));
  EXPECT_EQ(plan.select(plan.query({})), 2u);
  fx::SelectionQuery q = plan.query({.max_error = 32.f});
  fx::SelectionResult r = plan.explain(q);
  EXPECT_EQ(r.chosen, 1u);  // no pixel count: the lower ns per pixel decides
  EXPECT_EQ(r.reasons[0], "error not measured (not drawable on Vulkan: ps.1.1 assembly) under limit 32 LSB");
  EXPECT_EQ(r.reasons[2],
            "ranks below 'seed' (cheaper within the error limit: 'seed' 3 ns per pixel, this one 5 ns per pixel)");
  EXPECT_EQ(plan.select(plan.query({.max_error = 2.f})), 2u);
  // Nothing within the limit and no fallback chain: no technique, not the unmeasured one.
  EXPECT_EQ(plan.select(plan.query({.max_error = 0.1f})), fx::kNoIndex);
}

// Errors measured against different models do not compare: a substitute group ranks as a
// whole where its first technique is declared, and by error only within itself.
TEST(Selection, ErrorsRankWithinTheirSubstituteGroup) {
  const std::string bump = "bump mapped";
  fx::SelectionPlan plan = build({
      tech("bump_renormalized", {{"MaxError", 21.f}, {"Substitutes", bump}, {"CostNsPerPixel", 7.f}}),
      tech("bump_unnormalized", {{"MaxError", 43.f}, {"Substitutes", bump}, {"CostNsPerPixel", 5.f}}),
      tech("analytic", {{"MaxError", 6.f}, {"CostNsPerPixel", 3.f}}),
      tech("lut", {{"MaxError", 16.f}, {"CostNsPerPixel", 2.f}}),
  });
  EXPECT_EQ(std::vector<uint32_t>(plan.rank_order().begin(), plan.rank_order().end()),
            (std::vector<uint32_t>{0, 1, 2, 3}));
  fx::SelectionResult r = plan.explain(plan.query({}));
  EXPECT_EQ(r.chosen, 0u);
  EXPECT_EQ(r.reasons[2], "ranks below 'bump_renormalized' (its substitute group is declared first)");
  EXPECT_EQ(r.reasons[1], "ranks below 'bump_renormalized' (lower error: 'bump_renormalized' 21 LSB, this one 43 LSB)");
  // Without the bump techniques (a variant without them), the analytic one leads.
  fx::SelectionPlan plain = build({tech("lut", {{"MaxError", 16.f}}), tech("analytic", {{"MaxError", 6.f}})});
  EXPECT_EQ(plain.select(plain.query({})), 1u);
  // An error limit still picks the cheapest technique within it, whatever its group.
  EXPECT_EQ(plan.select(plan.query({.max_error = 20.f})), 3u);
}

// Per-vertex work is priced per vertex: with a vertex count the per-vertex technique's cost
// grows with the mesh, without one it ties on ns per pixel and then compares ns per vertex.
TEST(Selection, CostNsPerVertexCountsWithTheVertices) {
  fx::SelectionPlan plan = build({
      tech("per_pixel", {{"CostNsPerPixel", 4.f}, {"CostNsPerVertex", 1.f}, {"MaxError", 1.f}}),
      tech("per_vertex", {{"CostNsPerPixel", 1.f}, {"CostNsPerVertex", 20.f}, {"MaxError", 1.f}}),
  });
  EXPECT_EQ(plan.select(plan.query({.pixels = 1e4f, .vertices = 100.f, .max_error = 2.f})), 1u);
  EXPECT_EQ(plan.select(plan.query({.pixels = 1e4f, .vertices = 1e4f, .max_error = 2.f})), 0u);
  fx::SelectionPlan tie = build({
      tech("a", {{"CostNsPerPixel", 2.f}, {"CostNsPerVertex", 9.f}, {"MaxError", 1.f}}),
      tech("b", {{"CostNsPerPixel", 2.f}, {"CostNsPerVertex", 3.f}, {"MaxError", 1.f}}),
  });
  fx::SelectionQuery q = tie.query({.max_error = 2.f});
  EXPECT_EQ(tie.select(q), 1u);
  EXPECT_EQ(tie.explain(q).reasons[0],
            "ranks below 'b' (cheaper within the error limit: 'b' 3 ns per vertex, this one 9 ns per vertex)");
}

TEST(Selection, TiesGoToPriorityThenDeclarationOrder) {
  fx::SelectionPlan plan = build({tech("a", {}), tech("b", {{"Priority", 2}}), tech("c", {{"Priority", 2}})});
  EXPECT_EQ(plan.select(plan.query({})), 1u);
  EXPECT_EQ(std::vector<uint32_t>(plan.rank_order().begin(), plan.rank_order().end()),
            (std::vector<uint32_t>{1, 2, 0}));
  fx::SelectionResult r = plan.explain(plan.query({}));
  EXPECT_EQ(r.reasons[0], "ranks below 'b' (priority: 'b' 2, this one 0)");
  EXPECT_EQ(r.reasons[2], "ranks below 'b' (declared earlier)");
}

TEST(Selection, ExplicitFallbackChainSkipsInvalidLinks) {
  // The app wants "quality"; both quality techniques are invalid here, so the chain of the
  // best one is followed into the performance scheme.
  std::vector<fx::TechniqueCandidate> list = {
      tech("sm3", {{"Scheme", std::string("quality")}, {"Fallback", std::string("sm3_lite")}}, false),
      tech("sm3_lite", {{"Scheme", std::string("quality")}, {"Fallback", std::string("sm2")}}, false),
      tech("sm2", {{"Scheme", std::string("performance")}}),
  };
  fx::SelectionPlan plan = build(list);
  fx::SelectionQuery q = plan.query({.scheme = "quality"});
  EXPECT_EQ(plan.select(q), 2u);
  fx::SelectionResult r = plan.explain(q);
  EXPECT_EQ(r.route, fx::SelectionRoute::fallback_chain);
  EXPECT_EQ(r.fallback_path, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(r.reasons[0], "invalid: ps_3_0 not supported on dx9; fell back to 'sm2'");
  EXPECT_EQ(r.reasons[1], "invalid: ps_3_0 not supported on dx9");
  // Out of the quality techniques' band, the chain is not the app's intent: nothing.
  list[0].annotations.set("MaxDistance", 10.f);
  list[1].annotations.set("MaxDistance", 10.f);
  fx::SelectionPlan banded = build(list);
  EXPECT_EQ(banded.select(banded.query({.distance = 50.f, .scheme = "quality"})), fx::kNoIndex);
}

TEST(Selection, EffectFallbackIsTheLastResort) {
  std::vector<fx::TechniqueCandidate> list = {tech("fancy", {{"MaxDistance", 10.f}}),
                                              tech("flat", {{"Scheme", std::string("debug")}})};
  fx::SelectionPlan plan = build(list, {.effect_fallback = "flat"});
  fx::SelectionResult r = plan.explain(plan.query({.distance = 50.f, .scheme = "quality"}));
  EXPECT_EQ(r.chosen, 1u);
  EXPECT_EQ(r.route, fx::SelectionRoute::effect_fallback);
  EXPECT_EQ(std::string(fx::to_string(r.route)), "effect fallback");
  fx::SelectionPlan none = build(list);
  EXPECT_EQ(none.explain(none.query({.distance = 50.f, .scheme = "quality"})).route, fx::SelectionRoute::none);
}

TEST(Selection, FallbackCyclesAreErrorsNotHangs) {
  std::vector<fx::TechniqueCandidate> list = {
      tech("a", {{"Fallback", std::string("b")}}, false),
      tech("b", {{"Fallback", std::string("c")}}, false),
      tech("c", {{"Fallback", std::string("a")}}, false),
      tech("self", {{"Fallback", std::string("self")}}, false),
  };
  fx::DiagnosticSink sink;
  fx::SelectionPlan plan = fx::SelectionPlan::build(list, sink);
  ASSERT_EQ(sink.error_count(), 2u);
  EXPECT_EQ(sink.diagnostics()[0].id, "fallback-cycle");
  EXPECT_EQ(sink.diagnostics()[0].message, "fallback cycle 'a' -> 'b' -> 'c' -> 'a'; the link from 'c' is ignored");
  EXPECT_EQ(sink.diagnostics()[1].message, "fallback cycle 'self' -> 'self'; the link from 'self' is ignored");
  EXPECT_EQ(plan.select(plan.query({})), fx::kNoIndex);
  EXPECT_EQ(plan.explain(plan.query({})).route, fx::SelectionRoute::none);
}

TEST(Selection, UnknownFallbacksAndBadAnnotationsAreDiagnosed) {
  std::vector<fx::TechniqueCandidate> list = {
      tech("ps20", {{"Fallback", std::string("ps11")}}),
      tech("ps_11", {{"MinDistance", std::string("far")}, {"Priority", 1.5f}}),
      tech("odd", {{"MinDistance", 30.f}, {"MaxDistance", 10.f}}),
  };
  fx::DiagnosticSink sink;
  fx::SelectionPlan plan = fx::SelectionPlan::build(list, sink, {.effect_fallback = "nope"});
  std::vector<std::string> ids, messages;
  for (const auto& d : sink.diagnostics()) {
    ids.push_back(d.id);
    messages.push_back(d.message);
  }
  EXPECT_EQ(ids, (std::vector<std::string>{"selection-annotation", "selection-annotation", "selection-annotation",
                                           "unknown-fallback", "unknown-fallback"}));
  EXPECT_EQ(messages[0], "annotation 'MinDistance' of technique 'ps_11' must be a number; ignored");
  EXPECT_EQ(messages[1], "annotation 'Priority' of technique 'ps_11' must be an int; ignored");
  EXPECT_EQ(messages[3], "technique 'ps20': fallback technique 'ps11' does not exist; did you mean 'ps_11'?");
  EXPECT_EQ(plan.size(), 3u);
  fx::SelectionQuery q = plan.query({.distance = 20.f});
  EXPECT_EQ(plan.select(q), 0u);
  EXPECT_EQ(plan.explain(q).reasons[2], "outside distance band [30, 10) at 20");
}

TEST(Selection, EmptyPlanChoosesNothing) {
  fx::SelectionPlan plan = build({});
  fx::SelectionState state;
  EXPECT_EQ(plan.select(plan.query({}), state), fx::kNoIndex);
  EXPECT_TRUE(plan.explain(plan.query({})).reasons.empty());
}

// explain() documents select(): they must agree on every query, with and without state.
TEST(Selection, ExplainAgreesWithSelectOnRandomQueries) {
  std::vector<fx::TechniqueCandidate> list = {
      tech("q_near", {{"Scheme", std::string("quality")},
                      {"MaxDistance", 15.f},
                      {"CostMs", 0.8f},
                      {"Fallback", std::string("q_mid")}}),
      tech("q_mid",
           {{"Scheme", std::string("quality")},
            {"MinDistance", 10.f},
            {"MaxDistance", 60.f},
            {"MaxError", 1.f},
            {"CostNsPerPixel", 3.f}},
           false),
      tech("perf", {{"Scheme", std::string("performance")},
                    {"MaxError", 4.f},
                    {"CostMs", 0.05f},
                    {"Fallback", std::string("any_far")}}),
      tech("any_far", {{"MinDistance", 40.f}, {"MaxError", 6.f}, {"MinScreenSize", 8.f}}),
      tech("billboard", {{"MaxError", 20.f}, {"MaxScreenSize", 16.f}, {"Priority", 1}}),
  };
  fx::SelectionPlan plan = build(list, {.effect_fallback = "billboard"});
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> dist(0.f, 100.f), size(-1.f, 64.f), pix(0.f, 5e5f), budget(0.f, 2.f),
      err(0.f, 8.f);
  const char* schemes[] = {"", "quality", "performance", "other"};
  std::vector<fx::SelectionState> states(16);
  int routes[4] = {};
  for (int i = 0; i < 20000; ++i) {
    fx::SelectionQuery q = plan.query({.distance = dist(rng),
                                       .screen_size = size(rng),
                                       .pixels = pix(rng),
                                       .scheme = schemes[rng() % 4],
                                       .cost_budget_ms = budget(rng),
                                       .max_error = err(rng)});
    fx::SelectionState& s = states[rng() % states.size()];
    fx::SelectionResult r = plan.explain(q, &s);
    ASSERT_EQ(plan.select(q, s), r.chosen) << i;
    ++routes[int(r.route)];
    for (uint32_t k = 0; k < plan.size(); ++k) ASSERT_EQ(r.reasons[k].empty(), k == r.chosen);
  }
  // The effect fallback is always valid here, so every query ends with a technique.
  for (int route = 0; route < 3; ++route) EXPECT_GT(routes[route], 0) << route;
  EXPECT_EQ(routes[3], 0);
}

}  // namespace
