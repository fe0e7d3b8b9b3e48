// Technique selection through the library: criteria are remembered and re-applied after a
// reload.
#include "fx/select/selection.h"
#include "library_test_support.h"

namespace fx::testing {
namespace {

std::string two_techniques(const std::string& best_scheme) {
  return "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
         "float4 PS() : COLOR0 { return 1; }\n"
         "technique Fancy <string Scheme = \"" +
         best_scheme +
         "\";> { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"
         "technique Plain <string Scheme = \"fast\";> { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = "
         "compile ps_2_0 PS(); } }\n";
}

TEST(TechniqueReselect, ReloadReselectsWithTheSameCriteria) {
  ScratchDir dir;
  save_truncate_write(dir / "t.fx", two_techniques("quality"));
  EffectLibrary lib(test_options());
  EffectHandle e = lib.load((dir / "t.fx").string());
  ASSERT_TRUE(e.ok());
  e.select({.scheme = "quality"});
  EXPECT_EQ(e.technique_name(), "Fancy");
  // The edit moves Fancy to another scheme: the same criteria now pick what is left.
  save_truncate_write(dir / "t.fx", two_techniques("cinematic"));
  std::vector<ReloadEvent> events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  ASSERT_EQ(events[0].kind, ReloadEventKind::reloaded);
  EXPECT_EQ(e.technique_name(), events[0].technique);
  EXPECT_NE(e.technique_name(), "Fancy");
}

}  // namespace
}  // namespace fx::testing
