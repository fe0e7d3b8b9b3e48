// Edited defaults on a real file while an EffectLibrary runs: a parameter the application
// never set (or reset) takes the edited default and the event names it; a value the
// application set survives the edit.
#include "fx/diagnostic_render.h"
#include "fx/model/parameter_store.h"
#include "library_test_support.h"

namespace fx::testing {
namespace {

// A diffuse-and-specular effect whose two parameters' defaults the tests edit.
std::string lit_text(const std::string& kd, const std::string& ks = "0.2") {
  return "float Kd = " + kd +
         ";\n"
         "float Ks = " +
         ks +
         ";\n"
         "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
         "float4 PS() : COLOR0 { return Kd + Ks; }\n"
         "technique Lit { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
}

using Names = std::vector<std::string>;

class ReloadDefaultsTest : public ::testing::Test {
 protected:
  void SetUp() override { save_truncate_write(file(), lit_text("0.6")); }
  fs::path file() const { return dir / "lit.fx"; }
  // Saves `text` and returns the reload event it causes.
  ReloadEvent edit(const std::string& text) {
    save_truncate_write(file(), text);
    std::vector<ReloadEvent> events = next_events(lib);
    if (events.size() != 1) ADD_FAILURE() << events.size() << " events";
    if (events.empty()) return {};
    EXPECT_EQ(events[0].kind, ReloadEventKind::reloaded)
        << (events[0].sources ? render_text(events[0].diagnostics, *events[0].sources) : "");
    return events[0];
  }
  float value(const EffectHandle& e, Param p) {
    float v = -1;
    EXPECT_TRUE(e.params()->get(p, v));
    return v;
  }
  ScratchDir dir;
  EffectLibrary lib{test_options()};
};

TEST_F(ReloadDefaultsTest, ParameterNeverSetTakesTheEditedDefaultAndTheEventNamesIt) {
  EffectHandle e = lib.load(file().string());
  ASSERT_TRUE(e.ok());
  const Param kd = e.param("Kd");
  EXPECT_EQ(value(e, kd), 0.6f);
  ReloadEvent ev = edit(lit_text("0.05"));
  EXPECT_EQ(value(e, kd), 0.05f);
  EXPECT_EQ(ev.defaults_changed, Names{"Kd"});
  ev = edit(lit_text("0.05") + "// a comment\n");
  EXPECT_EQ(ev.defaults_changed, Names{}) << "no default changed";
}

TEST_F(ReloadDefaultsTest, ValueTheApplicationSetSurvivesAnEditedDefault) {
  EffectHandle e = lib.load(file().string());
  ASSERT_TRUE(e.ok());
  const Param kd = e.param("Kd"), ks = e.param("Ks");
  ASSERT_TRUE(e.params()->set(kd, 0.3f));
  ReloadEvent ev = edit(lit_text("0.05", "0.4"));
  EXPECT_EQ(value(e, kd), 0.3f) << "the application's value";
  EXPECT_EQ(value(e, ks), 0.4f) << "the edited default of a parameter never set";
  EXPECT_EQ(ev.defaults_changed, Names{"Ks"});
  ev = edit(lit_text("0.9", "0.4"));
  EXPECT_EQ(value(e, kd), 0.3f) << "still the application's after a second reload";
  EXPECT_EQ(ev.defaults_changed, Names{});
}

TEST_F(ReloadDefaultsTest, ResetParameterFollowsTheEditedDefault) {
  EffectHandle e = lib.load(file().string());
  ASSERT_TRUE(e.ok());
  const Param kd = e.param("Kd");
  ASSERT_TRUE(e.params()->set(kd, 0.3f));
  edit(lit_text("0.05"));
  ASSERT_EQ(value(e, kd), 0.3f);
  ASSERT_TRUE(e.params()->reset(kd));
  EXPECT_EQ(value(e, kd), 0.05f) << "reset() restores the live file's default";
  ReloadEvent ev = edit(lit_text("0.9"));
  EXPECT_EQ(value(e, kd), 0.9f);
  EXPECT_EQ(ev.defaults_changed, Names{"Kd"});
}

}  // namespace
}  // namespace fx::testing
