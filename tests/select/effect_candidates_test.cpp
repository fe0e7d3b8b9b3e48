// Selection for the shipped effects with validation from their real passes (compiled):
// every shipped profile picks what the seeds describe (docs/effects.md), and rejected
// techniques carry reasons with file:line.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "fx/compile/effect_file.h"
#include "fx/compile/shader_compiler.h"
#include "fx/compile/spirv_cache.h"
#include "fx/diagnostic_render.h"
#include "fx/frontend.h"
#include "fx/select/caps_sources.h"
#include "fx/select/effect_candidates.h"
#include "seed_picks.h"

namespace {

const std::string kEffects = std::string(FXKIT_SOURCE_DIR) + "/effects/";

struct Loaded {
  fx::DiagnosticSink diags;
  std::unique_ptr<fx::EffectFile> file;
};

// One compiler and memory cache for the whole suite: each profile revalidates the same shaders.
const fx::ShaderCompiler& compiler() {
  static fx::SpirvCache cache;
  static fx::ShaderCompiler c({}, &cache);
  return c;
}

std::unique_ptr<Loaded> load(const std::string& name) {
  auto l = std::make_unique<Loaded>();
  fx::FrontEndOptions options;
  options.preprocessor.include_dirs = {kEffects};
  l->file = fx::EffectFile::parse(kEffects + name, options, l->diags);
  EXPECT_FALSE(l->diags.has_errors()) << fx::render_text(l->diags.diagnostics(), l->file->sources);
  return l;
}

fx::DeviceCaps caps(const std::string& name) {
  fx::DiagnosticSink sink;
  auto c = fx::load_caps_profile(name, sink);
  EXPECT_TRUE(c.has_value()) << name;
  return c.value_or(fx::DeviceCaps{});
}

fx::EffectSelection selection(Loaded& l, const std::string& profile) {
  fx::DiagnosticSink sink;
  fx::EffectSelection s =
      fx::build_effect_selection(*l.file, caps(profile), sink, {.compile = true, .compiler = &compiler(), .plan = {}});
  EXPECT_FALSE(sink.has_errors()) << fx::render_text(sink.diagnostics(), l.file->sources);
  return s;
}

std::string pick(const std::string& effect, const std::string& profile, fx::SelectionCriteria criteria = {}) {
  auto l = load(effect);
  fx::EffectSelection s = selection(*l, profile);
  uint32_t chosen = s.plan.select(s.plan.query(criteria));
  return chosen == fx::kNoIndex ? std::string() : std::string(s.plan.name(chosen));
}

// 1-based line of the first line of `file` containing `needle`.
uint32_t line_containing(const std::string& file, const std::string& needle) {
  std::ifstream in(kEffects + file);
  std::string line;
  for (uint32_t n = 1; std::getline(in, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  ADD_FAILURE() << needle << " not in " << file;
  return 0;
}

const fx::TechniqueValidation& technique(const fx::EffectSelection& s, const std::string& name) {
  for (const auto& t : s.techniques)
    if (t.name == name) return t;
  static fx::TechniqueValidation none;
  ADD_FAILURE() << "no technique " << name;
  return none;
}

// The picks of docs/effects.md (also tests/effects, which reads annotations alone); here
// the validity comes from the passes, compiled.
TEST(EffectCandidates, EachGenerationPicksWhatTheSeedDescribesWithRealValidation) {
  for (const auto& row : fx::testing::seed_picks())
    for (const auto& [profile, want] : row.picks)
      EXPECT_EQ(pick(row.effect, profile), want) << row.effect << " on " << profile;
  fx::SelectionCriteria specular{.scheme = "specular"};
  EXPECT_EQ(pick("per_pixel_lighting.fx", "dx6", specular), "specular_emboss");
  EXPECT_EQ(pick("per_pixel_lighting.fx", "dx8", specular), "specular_emboss");  // the lowest measured error
  EXPECT_EQ(pick("per_pixel_lighting.fx", "modern", specular), "specular_pow_ps20");
  EXPECT_EQ(pick("strand_aniso.fx", "dx8", {.distance = 100.f}), "strand_lut_ps11");
}

TEST(EffectCandidates, EveryShippedTechniqueCompilesOnModern) {
  // On modern every HLSL/GLSL technique is valid; only assembly and fixed-function ones
  // are rejected, and never for a compile error.
  for (const char* effect : {"per_pixel_lighting.fx", "strand_aniso.fx", "hemisphere.fx", "brdf.fx", "wood.fx",
                             "seeds/wood_seed.fx", "aniso_lut_ward.fx", "aniso_highlights_glsl.fx"}) {
    auto l = load(effect);
    fx::EffectSelection s = selection(*l, "modern");
    for (const auto& t : s.techniques)
      for (const auto& r : t.reasons) {
        EXPECT_NE(r.id, "shader-compile-failed")
            << effect << " " << t.name << ": " << fx::render_text(r, l->file->sources);
        EXPECT_NE(r.id, "shader-exceeds-limit")
            << effect << " " << t.name << ": " << fx::render_text(r, l->file->sources);
      }
  }
}

TEST(EffectCandidates, RejectionsNameTheirFileAndLine) {
  auto l = load("per_pixel_lighting.fx");
  fx::EffectSelection modern = selection(*l, "modern");
  const auto& emboss = technique(modern, "emboss");
  ASSERT_FALSE(emboss.valid);
  // The vertex shader is vs.1.1 assembly (first), then the texture-stage states.
  auto located = [&](const fx::Diagnostic& d) { return fx::located_reason(d, l->file->sources); };
  bool found = false;
  uint32_t color_op_line = 0;
  {
    // emboss's first ColorOp[0] after its declaration.
    std::ifstream in(kEffects + "per_pixel_lighting.fx");
    std::string line;
    bool in_emboss = false;
    for (uint32_t n = 1; std::getline(in, line); ++n) {
      if (line.rfind("technique emboss", 0) == 0) in_emboss = true;
      if (in_emboss && line.find("ColorOp[0]") != std::string::npos) {
        color_op_line = n;
        break;
      }
    }
  }
  for (const auto& r : emboss.reasons) {
    if (r.id != "fixed-function-state") continue;
    EXPECT_EQ(located(r).find("per_pixel_lighting.fx:"), 0u) << located(r);
    EXPECT_NE(r.message.find("has no Vulkan equivalent (modern has no fixed-function texture stages)"),
              std::string::npos)
        << r.message;
    // ColorOp[0] is the reason or one of its located notes.
    if (r.message.find("'ColorOp[0]'") != std::string::npos)
      found = l->file->sources.presumed(r.range.begin).line == color_op_line;
    for (const auto& n : r.notes)
      if (n.message == "fixed-function state 'ColorOp[0]' here too")
        found = l->file->sources.presumed(n.location).line == color_op_line;
  }
  EXPECT_TRUE(found) << fx::render_text(emboss.reasons, l->file->sources);

  fx::EffectSelection dx7 = selection(*l, "dx7");
  const auto& ps20 = technique(dx7, "diffuse_ps20");
  ASSERT_EQ(ps20.reasons.size(), 2u) << fx::render_text(ps20.reasons, l->file->sources);
  uint32_t ps_line =
      line_containing("per_pixel_lighting.fx", "PixelShader = compile ps_2_0 TangentSpacePS(SPECULAR_NONE)");
  EXPECT_EQ(located(ps20.reasons[1]),
            "per_pixel_lighting.fx:" + std::to_string(ps_line) + ": ps_2_0 not supported on dx7");

  // The plan's explanation carries the same located sentences.
  fx::SelectionResult r = dx7.plan.explain(dx7.plan.query({}));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(dx7.plan.name(r.chosen), "dot3_multitexture");
  uint32_t i = *dx7.plan.index_of("diffuse_ps20");
  EXPECT_NE(r.reasons[i].find("invalid: per_pixel_lighting.fx:"), std::string::npos) << r.reasons[i];
  EXPECT_NE(r.reasons[i].find(": ps_2_0 not supported on dx7"), std::string::npos) << r.reasons[i];
}

TEST(EffectCandidates, CandidatesCopyAnnotationsAndCapTheirReasons) {
  auto l = load("per_pixel_lighting.fx");
  fx::EffectSelection modern = selection(*l, "modern");
  ASSERT_EQ(modern.candidates.size(), modern.techniques.size());
  for (size_t i = 0; i < modern.candidates.size(); ++i) {
    const auto& c = modern.candidates[i];
    const auto& t = modern.techniques[i];
    EXPECT_EQ(c.name, t.name);
    EXPECT_EQ(c.valid, t.valid);
    EXPECT_TRUE(c.annotations.string("UIName").has_value()) << c.name;
    EXPECT_EQ(c.reasons.size(), std::min<size_t>(t.reasons.size(), 5)) << c.name;
    if (t.reasons.size() > 4) {
      EXPECT_EQ(c.reasons[4], "and " + std::to_string(t.reasons.size() - 4) + " more");
    }
  }
  auto small = fx::effect_candidates(modern.techniques, l->file->sources, 1);
  for (size_t i = 0; i < small.size(); ++i)
    EXPECT_LE(small[i].reasons.size(), modern.techniques[i].reasons.empty() ? 0u : 2u);
  EXPECT_EQ(modern.first_valid(), fx::find_next_valid(modern.techniques));
  ASSERT_TRUE(modern.first_valid().has_value());
  EXPECT_EQ(modern.techniques[*modern.first_valid()].name, "diffuse_ps20");
}

}  // namespace
