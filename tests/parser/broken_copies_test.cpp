// Broken copies of a DirectX-SDK-style effect: each single mistake must give exactly one
// error, on the line of the mistake, with the expected id (issue 2 acceptance).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "fx/diagnostic_render.h"
#include "fx/frontend.h"

namespace fx {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Mistake {
  const char* what;
  const char* find;     // text in the clean file (first occurrence)
  const char* replace;  // what the broken copy has instead
  uint32_t line;        // where the one error must be reported
  const char* id;
};

class BrokenCopy : public ::testing::TestWithParam<Mistake> {};

TEST(BrokenCopy, CleanFileChecksClean) {
  SourceManager sm;
  DiagnosticSink diags;
  std::string text = read_file(FXKIT_SOURCE_DIR "/tests/parser/data/sdk_sample.fx");
  ASSERT_FALSE(text.empty());
  ParsedEffect parsed = parse_effect_text("sdk_sample.fx", text, sm, diags);
  EXPECT_TRUE(parsed.ok) << render_text(diags.diagnostics(), sm);
  EXPECT_EQ(diags.diagnostics().size(), 0u) << render_text(diags.diagnostics(), sm);
}

TEST_P(BrokenCopy, GivesOnePreciseError) {
  const Mistake& m = GetParam();
  std::string text = read_file(FXKIT_SOURCE_DIR "/tests/parser/data/sdk_sample.fx");
  size_t at = text.find(m.find);
  ASSERT_NE(at, std::string::npos) << m.find;
  text.replace(at, std::string_view(m.find).size(), m.replace);

  SourceManager sm;
  DiagnosticSink diags;
  FrontEndOptions options;
  options.preprocessor.loader = [](const std::string&) { return std::optional<std::string>(); };
  ParsedEffect parsed = parse_effect_text("sdk_sample.fx", text, sm, diags, options);
  std::string rendered = render_text(diags.diagnostics(), sm);
  EXPECT_FALSE(parsed.ok) << m.what;
  ASSERT_EQ(diags.error_count(), 1u) << m.what << "\n" << rendered;
  const Diagnostic& d = *std::find_if(diags.diagnostics().begin(), diags.diagnostics().end(),
                                      [](const Diagnostic& x) { return x.severity >= Severity::error; });
  EXPECT_EQ(d.id, m.id) << rendered;
  EXPECT_EQ(sm.presumed(d.range.begin).line, m.line) << rendered;
  EXPECT_NE(rendered.find("sdk_sample.fx:" + std::to_string(m.line) + ":"), std::string::npos) << rendered;
}

INSTANTIATE_TEST_SUITE_P(
    SdkSample, BrokenCopy,
    ::testing::Values(
        Mistake{"misspelled state", "CullMode = CCW;", "CullMod = CCW;", 88, "unknown-state"},
        Mistake{"misspelled enum value", "AddressU = Wrap;", "AddressU = Wrp;", 40, "unknown-state-value"},
        Mistake{"undefined parameter reference", "<g_MeshTexture>", "<g_MeshTextur>", 36, "undefined-reference"},
        Mistake{"undefined shader function", "RenderScenePS(true)", "RenderScenPS(true)", 85, "undefined-reference"},
        Mistake{"unknown shader profile", "compile vs_2_0", "compile vs_9_0", 84, "unknown-shader-profile"},
        Mistake{"annotation of the wrong type", "string UIName = \"Gloss\";", "string UIName = 3;", 25,
                "annotation-type-mismatch"},
        Mistake{"duplicate technique", "technique RenderSceneNoTexture", "technique RenderSceneWithTexture1Light", 93,
                "duplicate-definition"},
        Mistake{"missing include", "shared float4x4 g_mWorld : WORLD;",
                "#include \"missing.fxh\"\nshared float4x4 g_mWorld : WORLD;", 13, "include-not-found"},
        Mistake{"missing semicolon after a state", "ZWriteEnable = true;", "ZWriteEnable = true", 87, "expected-token"},
        Mistake{"stray token in a pass", "AlphaBlendEnable = false;", "AlphaBlendEnable = false; )", 89,
                "expected-state"}),
    [](const ::testing::TestParamInfo<Mistake>& info) { return "case" + std::to_string(info.index); });

}  // namespace
}  // namespace fx
