// docs/hot-reload.md and runtime/reload/include/fx/reload/vulkan_reload_backend.h: a
// FileWatcher loop, and an EffectLibrary drawing through a ReloadBackend (here into an
// EffectPreview's target).
// The examples are the docs' text, verbatim (examples_compiled_test.cpp): not reformatted.
// clang-format off
#include <array>
#include <chrono>

#include "example_fixture.h"
#include "fx/model/parameter_store.h"
#include "fx/reload/effect_library.h"
#include "fx/reload/file_watcher.h"
#include "fx/select/caps_sources.h"
#include "fx/select/selection.h"
#include "fx/binding/effect_preview.h"
#include "fx/reload/vulkan_reload_backend.h"

namespace fx::docs {
namespace {

using namespace std::chrono_literals;

// True `times` times, then false: the examples' frame loops.
auto running_for(int times) {
  return [times]() mutable { return times-- > 0; };
}

TEST_F(ExampleTest, WatchingFiles) {
  auto running = running_for(1);
  int reloads = 0;
  auto reload_everything_that_uses = [&](const std::filesystem::path&, fx::FileEventKind) { ++reloads; };

  fx::FileWatcher watcher({.coalesce_window = std::chrono::milliseconds(50)});
  watcher.watch("effects/strand_aniso.fx");     // and every file it #includes
  watcher.watch("effects/common.fxh");
  while (running()) {                            // a reload worker thread
    for (const fx::FileEvent& e : watcher.poll(std::chrono::milliseconds(50)))
      reload_everything_that_uses(e.path, e.kind);  // kind: changed | deleted
  }
  EXPECT_EQ(reloads, 0);  // nothing was edited
}

// The render-thread side: what an engine writes, drawing with an EffectPreview.
class ReloadExample : public ExampleTest {
 protected:
  void SetUp() override {
    ExampleTest::SetUp();
    fx::DiagnosticSink sink;
    preview = fx::vk::EffectPreview::create(ctx(), fx::sphere(8, 16), {.width = 32, .height = 32}, sink);
    ASSERT_TRUE(preview) << fx::vk::testing::describe(sink);
  }
  std::unique_ptr<fx::vk::EffectPreview> preview;
};

TEST_F(ReloadExample, LoadSetSelectDrawPoll) {
  const fx::vk::Context& ctx = this->ctx();
  fx::vk::EffectTextureCache& textures = preview->textures();
  fx::vk::FrameResources& frames = preview->frames();
  const fx::vk::RenderingFormats formats = preview->formats();
  const fx::vk::EffectBindingDesc desc = preview->binding_desc();
  auto layout_for = [&](std::span<const fx::InterfaceVariable> inputs) { return preview->vertex_layout(inputs); };
  const fx::DeviceCaps caps = fx::caps_from_physical_device(ctx.physical_device());
  std::vector<fx::ReloadEvent> events;
  auto log_event = [&](const fx::ReloadEvent& ev) { events.push_back(ev); };
  auto report = [](const fx::ReloadEvent&) {};
  const std::array<float, 3> dir{0.f, -1.f, 0.f};
  int frames_drawn = 0;
  auto draw = [&](fx::vk::EffectBinding& binding, uint32_t technique) {
    fx::DiagnosticSink sink;
    frames_drawn += preview->render(binding, technique, 0, sink).has_value();
  };
  auto running = running_for(2);

  fx::vk::ReloadBackend backend(ctx, textures, frames, {.formats = formats, .binding = desc, .vertex_layout = layout_for});
  fx::EffectLibrary lib({.include_dirs = {"effects"}, .coalesce = 50ms, .backend = &backend,
                         .caps = caps, .frames_in_flight = 2, .on_event = log_event});
  fx::EffectHandle e = lib.load("effects/strand_aniso.fx");   // ok(), diagnostics()
  fxkit::Param light = e.param("Light0Direction");               // by name, else semantic
  e.params()->set(light, std::span<const float>(dir));
  e.select({.distance = 12.f, .scheme = "quality"});          // remembered for reloads
  for (uint64_t frame = 0; running(); ++frame) {
    fx::vk::EffectBinding* binding = fx::vk::ReloadBackend::binding(*e.version());
    draw(*binding, e.technique());                            // begin, apply each pass, end
    for (const fx::ReloadEvent& ev : lib.poll(frame)) report(ev);  // at the frame boundary
  }

  EXPECT_TRUE(e.ok());
  EXPECT_TRUE(light.valid());
  EXPECT_EQ(e.technique_name(), "strand_bump_renormalized");
  EXPECT_EQ(frames_drawn, 2);

  {  // runtime/reload/include/fx/reload/vulkan_reload_backend.h
    fx::vk::ReloadBackend backend(ctx, textures, frames,
                                  {.formats = formats, .binding = desc, .vertex_layout = layout_for});
    fx::EffectLibrary lib({.backend = &backend});
    fx::EffectHandle handle = lib.load("effects/wood.fx");
    fx::vk::EffectBinding* b = fx::vk::ReloadBackend::binding(*handle.version());

    ASSERT_NE(b, nullptr);
    EXPECT_NE(b->first_ok_technique(), fx::kNoIndex);
  }
}

}  // namespace
}  // namespace fx::docs
