// The model over every seed effect and fuzz corpus file: no crash, sensible counts.
#include <gtest/gtest.h>

#include <filesystem>

#include "model_test_util.h"

namespace fx {
namespace {

std::vector<std::string> effect_files(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".fx") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

struct Counts {
  size_t parameters = 0, techniques = 0, passes = 0, shaders = 0, functions = 0;
  size_t front_end_errors = 0, model_errors = 0;
};

Counts run(const std::string& path, std::string& report) {
  SourceManager sm;
  DiagnosticSink diags;
  ParsedEffect parsed = parse_effect_file(path, sm, diags);
  Counts c;
  c.front_end_errors = diags.error_count();
  const size_t first_model_diagnostic = diags.diagnostics().size();
  EffectModel model = build_effect_model(parsed, sm, diags);
  c.model_errors = diags.error_count() - c.front_end_errors;
  c.functions = model.functions.size();
  c.parameters = model.parameters.size();
  c.techniques = model.techniques.size();
  for (const TechniqueInfo& t : model.techniques) {
    c.passes += t.passes.size();
    for (const PassInfo& p : t.passes) c.shaders += p.shaders.size();
  }
  for (size_t i = first_model_diagnostic; i < diags.diagnostics().size(); ++i)
    if (diags.diagnostics()[i].severity >= Severity::error) report += render_text({diags.diagnostics()[i]}, sm);
  return c;
}

TEST(SeedModel, ParserSeedEffects) {
  size_t files = 0;
  for (const std::string& path : effect_files(FXKIT_SOURCE_DIR "/tests/parser/data")) {
    std::string errors;
    Counts c = run(path, errors);
    ++files;
    EXPECT_GT(c.parameters, 0u) << path;
    EXPECT_GE(c.passes, c.techniques) << path;
    if (c.techniques) {
      EXPECT_GT(c.shaders + c.passes, 0u) << path;
    }
    // The seeds are valid effects: the model adds no errors beyond the front end's.
    EXPECT_EQ(c.model_errors, 0u) << path << "\n" << errors;
  }
  EXPECT_GE(files, 4u);
}

TEST(SeedModel, WoodShaderCounts) {
  std::string errors;
  Counts c = run(FXKIT_SOURCE_DIR "/tests/parser/data/wood.fx", errors);
  // A shader library without techniques: ringscale ... I, the noise volume, and four
  // functions (smoothstep, diffuse, specular, the wood shader).
  EXPECT_GE(c.parameters, 15u);
  EXPECT_EQ(c.techniques, 0u);
  EXPECT_EQ(c.functions, 4u);
}

TEST(SeedModel, FuzzCorpusDoesNotCrash) {
  for (const std::string& path : effect_files(FXKIT_SOURCE_DIR "/tests/fuzz/corpus")) {
    std::string errors;
    Counts c = run(path, errors);
    EXPECT_LE(c.passes, 64u) << path;
  }
}

}  // namespace
}  // namespace fx
