// Generational scenarios: hand-written candidate lists mirroring the seeds' techniques,
// validated against each shipped profile; each generation picks what the seed says.
#include <gtest/gtest.h>

#include "fx/select/caps_sources.h"
#include "fx/select/selection.h"
#include "fx/select/technique_candidate.h"

namespace {

fx::DeviceCaps profile(const char* name) {
  fx::DiagnosticSink sink;
  return fx::load_caps_profile(name, sink).value_or(fx::DeviceCaps{});
}

fx::TechniqueCandidate technique(std::string name, std::string requires_list) {
  fx::TechniqueCandidate t;
  t.name = std::move(name);
  t.annotations.set("Requires", std::move(requires_list));
  return t;
}

// The per-pixel diffuse bump map of the lighting seed, best first as a D3DX effect lists
// them: HLSL ps_2_0, ps_1_1 assembly, the DOTPRODUCT3 fallback, the emboss fallback
// ("dual texture unit with a subtract operation"), and plain multitexture.
std::vector<fx::TechniqueCandidate> diffuse_bump() {
  return {
      technique("hlsl_ps_2_0", "vs_2_0 ps_2_0"),
      technique("asm_ps_1_1", "vs_1_1 ps_1_1"),
      technique("dot3_multitexture", "fixed_function_stages dot3 textures>=2"),
      technique("emboss", "vs_1_1 fixed_function_stages subtract textures>=2"),
      technique("base_multitexture", "fixed_function_stages textures>=2"),
  };
}

// The strand seed: four lights per pass need ps_1_4 (DirectX 8.1); ps_1_1 needs two passes.
std::vector<fx::TechniqueCandidate> strands() {
  return {
      technique("strand_ps_2_0", "vs_2_0 ps_2_0"),
      technique("strand_ps_1_4_four_lights", "vs_1_1 ps_1_4 textures>=4"),
      technique("strand_ps_1_1_two_pass", "vs_1_1 ps_1_1"),
  };
}

std::string pick(std::vector<fx::TechniqueCandidate> list, const char* caps_name) {
  fx::validate(list, profile(caps_name));
  fx::DiagnosticSink sink;
  fx::SelectionPlan plan = fx::SelectionPlan::build(list, sink);
  EXPECT_FALSE(sink.has_errors());
  uint32_t chosen = plan.select(plan.query({}));
  // With no annotations, selection is D3DX's "first valid technique".
  auto first_valid = fx::find_next_valid(list);
  EXPECT_EQ(first_valid.has_value(), chosen != fx::kNoIndex);
  if (first_valid) {
    EXPECT_EQ(*first_valid, chosen);
  }
  return std::string(plan.name(chosen));
}

TEST(Generations, DiffuseBumpPicksPerSeed) {
  EXPECT_EQ(pick(diffuse_bump(), "dx6"), "emboss");  // most DX6 cards lack DOTPRODUCT3
  EXPECT_EQ(pick(diffuse_bump(), "dx7"), "dot3_multitexture");
  EXPECT_EQ(pick(diffuse_bump(), "dx8"), "asm_ps_1_1");
  EXPECT_EQ(pick(diffuse_bump(), "dx8_1"), "asm_ps_1_1");
  EXPECT_EQ(pick(diffuse_bump(), "dx9"), "hlsl_ps_2_0");
  EXPECT_EQ(pick(diffuse_bump(), "modern"), "hlsl_ps_2_0");
}

TEST(Generations, StrandsPickPerSeed) {
  EXPECT_EQ(pick(strands(), "dx7"), "");
  EXPECT_EQ(pick(strands(), "dx8"), "strand_ps_1_1_two_pass");
  EXPECT_EQ(pick(strands(), "dx8_1"), "strand_ps_1_4_four_lights");
  EXPECT_EQ(pick(strands(), "dx9"), "strand_ps_2_0");
  EXPECT_EQ(pick(strands(), "modern"), "strand_ps_2_0");
}

TEST(Generations, ModernDeviceRejectsEverySm1AndFixedFunctionTechnique) {
  auto list = diffuse_bump();
  EXPECT_EQ(fx::validate(list, profile("modern")), 1u);
  EXPECT_EQ(list[1].reasons,
            (std::vector<std::string>{"vs_1_1 not supported on modern", "ps_1_1 not supported on modern"}));
  EXPECT_EQ(list[2].reasons, (std::vector<std::string>{"fixed_function_stages not supported on modern",
                                                       "dot3 not supported on modern"}));
}

TEST(Generations, ReasonsExplainTheDx7Choice) {
  auto list = diffuse_bump();
  fx::validate(list, profile("dx7"));
  fx::DiagnosticSink sink;
  fx::SelectionPlan plan = fx::SelectionPlan::build(list, sink);
  fx::SelectionResult r = plan.explain(plan.query({}));
  ASSERT_EQ(r.chosen, 2u);
  EXPECT_EQ(r.route, fx::SelectionRoute::direct);
  EXPECT_EQ(r.reasons[0], "invalid: vs_2_0 not supported on dx7; ps_2_0 not supported on dx7");
  EXPECT_EQ(r.reasons[1], "invalid: ps_1_1 not supported on dx7");
  EXPECT_EQ(r.reasons[2], "");
  EXPECT_EQ(r.reasons[3], "ranks below 'dot3_multitexture' (declared earlier)");
}

TEST(Generations, FindNextValidWalksLikeD3dx) {
  auto list = diffuse_bump();
  fx::validate(list, profile("dx7"));
  std::vector<size_t> walk;
  for (auto i = fx::find_next_valid(list); i; i = fx::find_next_valid(list, *i)) walk.push_back(*i);
  EXPECT_EQ(walk, (std::vector<size_t>{2, 3, 4}));
  EXPECT_EQ(fx::find_next_valid(list, 99), std::nullopt);
  EXPECT_EQ(fx::find_next_valid(std::span<const fx::TechniqueCandidate>{}), std::nullopt);
}

TEST(Generations, ValidateKeepsUpstreamRejectionsAndFlagsBadRequires) {
  fx::TechniqueCandidate t = technique("broken", "ps_2_0 dott3");
  t.valid = false;
  t.reasons = {"compile error in PS()"};
  t.requirements.push_back(fx::CapsRequirement::limit("render_targets", 2));
  EXPECT_FALSE(fx::validate(t, profile("dx9")));
  EXPECT_EQ(t.reasons, (std::vector<std::string>{"compile error in PS()", "unknown requirement 'dott3'"}));
  fx::TechniqueCandidate u = technique("typed", "");
  u.annotations = {{"Requires", 3}};
  EXPECT_FALSE(fx::validate(u, profile("dx9")));
  EXPECT_EQ(u.reasons, std::vector<std::string>{"annotation Requires must be a string"});
}

}  // namespace
