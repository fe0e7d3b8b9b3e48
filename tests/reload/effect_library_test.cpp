// EffectLibrary against real files and the real kernel: save patterns, include graph,
// broken edits, parameter survival, deletion, retirement and a leak soak.
#include <cstdlib>

#include "fx/diagnostic_render.h"
#include "fx/model/parameter_store.h"
#include "fx/reload/reload_transaction.h"
#include "library_test_support.h"

namespace fx::testing {
namespace {

class EffectLibraryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    save_truncate_write(dir / "common.fxh", common_text());
    save_truncate_write(dir / "a.fx", effect_text());
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  ScratchDir dir;
};

bool has_id(const std::vector<Diagnostic>& ds, const std::string& id) {
  for (const Diagnostic& d : ds)
    if (d.id == id) return true;
  return false;
}

TEST_F(EffectLibraryTest, LoadsAndWatchesTheIncludeGraph) {
  EffectLibrary lib(test_options());
  EffectHandle e = lib.load(path("a.fx"));
  ASSERT_TRUE(e.ok()) << render_text(e.diagnostics(), *e.diagnostic_sources());
  EXPECT_EQ(e.serial(), 1u);
  EXPECT_EQ(lib.stats().watched_files, 2u);  // a.fx and common.fxh
  EXPECT_EQ(lib.load(path("a.fx")).version(), e.version()) << "same path, same effect";
}

TEST_F(EffectLibraryTest, EachEditorSavePatternReloadsExactlyOnce) {
  EffectLibrary lib(test_options());
  EffectHandle e = lib.load(path("a.fx"));
  ASSERT_TRUE(e.ok());
  using Save = void (*)(const fs::path&, const std::string&);
  const Save patterns[] = {save_truncate_write, save_rename_over, save_backup_rename, save_truncate_write};
  uint64_t expected = 1;
  for (Save save : patterns) {
    save(dir / "a.fx", effect_text(std::to_string(expected) + ", 0, 0, 1"));
    std::vector<ReloadEvent> events = next_events(lib);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, ReloadEventKind::reloaded) << render_text(events[0].diagnostics, *events[0].sources);
    ASSERT_EQ(events[0].changed.size(), 1u);
    EXPECT_EQ(fs::path(events[0].changed[0]).filename(), "a.fx");
    // A duplicate reload of the previous save would have bumped the serial twice.
    EXPECT_EQ(e.serial(), ++expected);
  }
  EXPECT_EQ(lib.stats().transactions, 4u);
}

TEST_F(EffectLibraryTest, IncludeChangeReloadsExactlyTheEffectsThatIncludeIt) {
  save_truncate_write(dir / "b.fx", effect_text("0, 1, 0, 1"));
  save_truncate_write(dir / "c.fx", standalone_text());
  EffectLibrary lib(test_options());
  EffectHandle a = lib.load(path("a.fx")), b = lib.load(path("b.fx")), c = lib.load(path("c.fx"));
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  save_rename_over(dir / "common.fxh", common_text("2.0"));
  std::vector<ReloadEvent> events = next_events(lib, 2);
  ASSERT_EQ(events.size(), 2u);
  for (const ReloadEvent& ev : events) {
    EXPECT_EQ(ev.kind, ReloadEventKind::reloaded);
    EXPECT_EQ(fs::path(ev.changed.at(0)).filename(), "common.fxh");
    EXPECT_FALSE(ev.recompiled.empty()) << "the pixel shader changed";
  }
  EXPECT_EQ(a.serial(), 2u);
  EXPECT_EQ(b.serial(), 2u);
  // c does not include common.fxh: its next event is its own edit, and it is its first.
  save_truncate_write(dir / "c.fx", standalone_text("0.25"));
  events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(fs::path(events[0].file).filename(), "c.fx");
  EXPECT_EQ(c.serial(), 2u);
  EXPECT_EQ(a.serial(), 2u);
}

TEST_F(EffectLibraryTest, BrokenEditKeepsTheLastGoodEffectThenTheFixApplies) {
  EffectLibrary lib(test_options());
  EffectHandle e = lib.load(path("a.fx"));
  ASSERT_TRUE(e.ok());
  Param gloss = e.param("Gloss");
  ASSERT_TRUE(gloss.valid());
  ASSERT_TRUE(e.params()->set(gloss, 0.75f));
  auto good = e.version();

  // Line 4 (after the include and two parameters) is not effect syntax.
  save_truncate_write(dir / "a.fx", effect_text("1, 0.5, 0.25, 1", "float4 Broken = ;\n"));
  std::vector<ReloadEvent> events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ReloadEventKind::failed);
  ASSERT_FALSE(events[0].diagnostics.empty());
  std::string text = render_text(events[0].diagnostics, *events[0].sources);
  EXPECT_NE(text.find("a.fx:4:"), std::string::npos) << text;
  EXPECT_EQ(e.version(), good) << "the last good version stays live";
  float value = 0;
  ASSERT_TRUE(e.params()->get(gloss, value));
  EXPECT_EQ(value, 0.75f);

  // An unknown name in shader code is the semantic model's finding, as `fxkit check` and
  // the editor report it (with its did-you-mean), before glslang runs.
  save_truncate_write(dir / "a.fx", effect_text("1, 0.5, 0.25, 1", "float Bad() { return Glos; }\n"));
  events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ReloadEventKind::failed);
  text = render_text(events[0].diagnostics, *events[0].sources);
  EXPECT_NE(text.find("a.fx:4:22: error: use of undeclared identifier 'Glos'; did you mean 'Gloss'? "
                      "[unknown-identifier]"),
            std::string::npos)
      << text;
  EXPECT_EQ(e.version(), good);

  // A glslang error inside a shader function points into the .fx file the same way.
  save_truncate_write(dir / "a.fx", effect_text("1, 0.5, 0.25, 1", "float Bad() { return float3(1, 2).x; }\n"));
  events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ReloadEventKind::failed);
  text = render_text(events[0].diagnostics, *events[0].sources);
  EXPECT_NE(text.find("a.fx:4:"), std::string::npos) << text;
  EXPECT_EQ(e.version(), good);

  save_truncate_write(dir / "a.fx", effect_text("0, 0, 1, 1"));
  events = next_events(lib);
  ASSERT_GE(events.size(), 1u);
  EXPECT_EQ(events.back().kind, ReloadEventKind::reloaded)
      << render_text(events.back().diagnostics, *events.back().sources);
  EXPECT_NE(e.version(), good);
  ASSERT_TRUE(e.params()->get(gloss, value)) << "the old handle still works";
  EXPECT_EQ(value, 0.75f) << "values survive a reload";
}

TEST_F(EffectLibraryTest, ACompilerCrashFailsTheReloadAndKeepsTheLastGoodEffect) {
  EffectLibraryOptions options = test_options();
  // The worker aborts on a unit whose text holds the marker, as glslang does on what it
  // cannot survive; the marker is a name the pixel shader reaches, so it is in the unit.
  options.compile_workers = CompileWorkerOptions{.workers = 1, .arguments = {"--abort-on", "FXKIT_TEST_CRASH"}};
  EffectLibrary lib(std::move(options));
  ASSERT_NE(lib.compile_workers(), nullptr) << lib.compile_workers_error();
  EffectHandle e = lib.load(path("a.fx"));
  ASSERT_TRUE(e.ok());
  auto good = e.version();

  save_truncate_write(dir / "common.fxh", "float FXKIT_TEST_CRASH = 1;\nfloat Scale() { return FXKIT_TEST_CRASH; }\n");
  std::vector<ReloadEvent> events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ReloadEventKind::failed);
  ASSERT_TRUE(has_id(events[0].diagnostics, "compiler-crashed"));
  std::string text = render_text(events[0].diagnostics, *events[0].sources);
  EXPECT_NE(text.find("a.fx:5:"), std::string::npos) << "at the pixel shader's definition: " << text;
  EXPECT_EQ(e.version(), good) << "the last good version stays live";
  EXPECT_EQ(lib.compile_workers()->stats().crashed, 1u);

  save_truncate_write(dir / "common.fxh", common_text("2.0"));
  events = next_events(lib);
  ASSERT_GE(events.size(), 1u);
  EXPECT_EQ(events.back().kind, ReloadEventKind::reloaded)
      << render_text(events.back().diagnostics, *events.back().sources);
  EXPECT_NE(e.version(), good) << "the replaced worker compiles the fix";
}

TEST_F(EffectLibraryTest, RemovedParameterHandleBecomesInertWithAWarning) {
  EffectLibrary lib(test_options());
  EffectHandle e = lib.load(path("a.fx"));
  Param gloss = e.param("Gloss");
  Param tint = e.param("Tint");
  const float red[4] = {1, 0, 0, 1};
  ASSERT_TRUE(e.params()->set(tint, std::span<const float>(red)));
  save_truncate_write(dir / "a.fx", effect_text("1, 0.5, 0.25, 1", "", /*with_gloss=*/false));
  std::vector<ReloadEvent> events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  ASSERT_EQ(events[0].kind, ReloadEventKind::reloaded);
  EXPECT_TRUE(has_id(events[0].diagnostics, "reload-parameter-removed"));
  ParamStatus status = e.params()->set(gloss, 1.0f);
  EXPECT_EQ(status.code, ParamStatus::removed) << status.message;
  float out[4] = {};
  ASSERT_TRUE(e.params()->get(tint, std::span<float>(out)));
  EXPECT_EQ(out[0], 1.f);
  EXPECT_EQ(out[1], 0.f);
}

TEST_F(EffectLibraryTest, DeletedFileKeepsTheEffectAndReCreationIsPickedUp) {
  EffectLibrary lib(test_options());
  EffectHandle e = lib.load(path("a.fx"));
  auto good = e.version();
  fs::remove(dir / "a.fx");
  std::vector<ReloadEvent> events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ReloadEventKind::deleted);
  EXPECT_TRUE(has_id(events[0].diagnostics, "reload-file-deleted"));
  EXPECT_EQ(e.version(), good);
  save_truncate_write(dir / "a.fx", effect_text("0, 1, 1, 1"));
  events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ReloadEventKind::reloaded);
  EXPECT_EQ(e.serial(), 2u);
}

TEST_F(EffectLibraryTest, AFailedFirstLoadBecomesOkOnceFixed) {
  save_truncate_write(dir / "a.fx", "technique {\n");
  EffectLibrary lib(test_options());
  EffectHandle e = lib.load(path("a.fx"));
  EXPECT_FALSE(e.ok());
  EXPECT_FALSE(e.diagnostics().empty());
  EXPECT_FALSE(e.param("Gloss").valid());
  save_rename_over(dir / "a.fx", effect_text());
  std::vector<ReloadEvent> events = next_events(lib);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ReloadEventKind::reloaded);
  EXPECT_TRUE(e.ok());
  EXPECT_TRUE(e.param("Gloss").valid());
}

TEST_F(EffectLibraryTest, ReplacedVersionsAreReleasedOnlyAfterTheirFramesRetire) {
  EffectLibraryOptions o = test_options();
  o.frames_in_flight = 2;
  EffectLibrary lib(o);
  EffectHandle e = lib.load(path("a.fx"));
  std::weak_ptr<const EffectVersion> old = e.version();
  save_truncate_write(dir / "a.fx", effect_text("0, 0, 0, 1"));
  ASSERT_TRUE(lib.wait(fx::testing::patience()));
  ASSERT_EQ(lib.poll(10).size(), 1u);  // swapped in while recording frame 10
  EXPECT_EQ(lib.stats().retiring, 1u);
  EXPECT_FALSE(old.expired()) << "frames 8 and 9 may still use it";
  lib.poll(11);
  EXPECT_FALSE(old.expired());
  lib.poll(12);
  EXPECT_TRUE(old.expired()) << "frames before 10 have retired by frame 12";
  EXPECT_EQ(lib.stats().retiring, 0u);
}

TEST_F(EffectLibraryTest, SoakOfMixedGoodAndBrokenEditsLeaksNothing) {
  const char* soak = std::getenv("FXKIT_SOAK");
  const int edits = soak && std::string(soak) == "1" ? 1000 : 50;
  size_t baseline = EffectVersion::live_count();
  {
    EffectLibrary lib(test_options());
    EffectHandle e = lib.load(path("a.fx"));
    Param gloss = e.param("Gloss");
    ASSERT_TRUE(e.params()->set(gloss, 0.125f));
    int reloaded = 0, failed = 0;
    for (int i = 0; i < edits; ++i) {
      bool broken = i % 3 == 1;
      std::string tint = std::to_string(i % 7) + ", " + std::to_string(i) + ", 0, 1";
      save_rename_over(dir / "a.fx", effect_text(tint, broken ? "float4 Broken = ;\n" : ""));
      std::vector<ReloadEvent> events = next_events(lib);
      ASSERT_EQ(events.size(), 1u) << "edit " << i;
      (events[0].kind == ReloadEventKind::reloaded ? reloaded : failed)++;
      ASSERT_EQ(events[0].kind, broken ? ReloadEventKind::failed : ReloadEventKind::reloaded) << "edit " << i;
    }
    float value = 0;
    ASSERT_TRUE(e.params()->get(gloss, value));
    EXPECT_EQ(value, 0.125f);
    EXPECT_EQ(lib.stats().reloads, static_cast<uint64_t>(reloaded));
    EXPECT_EQ(lib.stats().failures, static_cast<uint64_t>(failed));
    EXPECT_LE(lib.stats().retiring, 2u) << "old versions are released as frames pass";
  }
  EXPECT_EQ(EffectVersion::live_count(), baseline);
}

}  // namespace
}  // namespace fx::testing
