// Hot reload with rendering: EffectLibrary + ReloadBackend + EffectPreview on the validated
// device. A broken edit leaves the picture bit-identical, a fix applies, and reloads during
// rendered frames never drop a frame, trip validation or leak Vulkan objects
// (FXKIT_SOAK=1: 1,000 frames; default 100).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>

#include "effect_test_util.h"
#include "fx/reload/effect_library.h"
#include "fx/reload/reload_transaction.h"
#include "fx/reload/vulkan_reload_backend.h"
#include "patience.h"

namespace fx::vk::testing {
namespace {

class EffectReloadTest : public VulkanTest {};

// A lit sphere whose brightness is `scale` (edits change it); `broken` adds a syntax error.
std::string effect_text(float scale, bool broken = false) {
  return std::string(R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4x4 World : WORLD;
float3 LightDirection : DIRECTION = {0.3, -0.8, -0.5};
float4 Tint = {0.9, 0.6, 0.3, 1.0};
texture Lut < string Generator = "pow"; int Width = 64; int Height = 2; float Exponent = 8; string Format = "unorm8"; >;
sampler2D LutSampler = sampler_state { Texture = <Lut>; MinFilter = Linear; MagFilter = Linear; AddressU = Clamp; AddressV = Clamp; };
struct V { float4 pos : POSITION; float3 n : TEXCOORD0; };
V VS(float4 p : POSITION, float3 n : NORMAL) { V o; o.pos = mul(p, WorldViewProjection); o.n = mul(n, (float3x3)World); return o; }
float4 PS(V i) : COLOR0 {
  float d = saturate(dot(normalize(i.n), -LightDirection));
  return float4(Tint.rgb * (0.15 + d * )") +
         std::to_string(scale) + R"() + tex2D(LutSampler, float2(d, 0.5)).r * 0.3, 1.0);
}
technique lit { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)" + (broken ? "technique broken { pass p0 { VertexShader = compile vs_2_0 Missing( } }\n" : "");
}

// A library rendering one effect file through the preview, as `fxkit watch` does.
struct ReloadHarness {
  std::string path;
  std::unique_ptr<EffectPreview> preview;
  std::unique_ptr<ReloadBackend> backend;
  std::unique_ptr<EffectLibrary> lib;
  EffectHandle effect;
  uint64_t frame = 0;

  ReloadHarness(Context& ctx, const std::string& name, const std::string& text = effect_text(0.85f)) {
    path = write_effect(name, text);
    DiagnosticSink sink;
    auto mesh = make_mesh("sphere", sink);
    EffectPreviewDesc desc;
    desc.width = desc.height = 48;
    preview = EffectPreview::create(ctx, *mesh, desc, sink);
    EXPECT_TRUE(preview) << describe(sink);
    EffectPreview* p = preview.get();
    backend = std::make_unique<ReloadBackend>(
        ctx, preview->textures(), preview->frames(),
        ReloadBackendDesc{preview->formats(), preview->binding_desc(),
                          [p](std::span<const InterfaceVariable> in) { return p->vertex_layout(in); }});
    EffectLibraryOptions options;
    options.backend = backend.get();
    options.coalesce = std::chrono::milliseconds(5);
    lib = std::make_unique<EffectLibrary>(std::move(options));
    effect = lib->load(path);
    EXPECT_TRUE(effect.ok()) << [&] {
      std::string s;
      for (auto& d : effect.diagnostics()) s += d.id + ": " + d.message + "\n";
      return s;
    }();
    effect.select();
  }
  ~ReloadHarness() {
    effect = {};
    lib.reset();  // versions (and their bindings) before the preview they draw into
  }

  // One frame: poll at the boundary, draw the live version. nullopt = a dropped frame.
  std::optional<fx::Image> frame_once(std::vector<ReloadEvent>* events = nullptr) {
    auto polled = lib->poll(frame++);
    if (events) events->insert(events->end(), polled.begin(), polled.end());
    auto version = effect.version();
    EffectBinding* binding = version ? ReloadBackend::binding(*version) : nullptr;
    if (!binding) return std::nullopt;
    set_standard_semantics(*effect.params(), *version->model, preview->scene());
    DiagnosticSink sink;
    auto image = preview->render(*binding, effect.technique(), 0, sink);
    EXPECT_TRUE(image) << describe(sink);
    return image;
  }

  // Renders frames until a reload event arrives (giving up after fx::testing::patience());
  // the frames are checked.
  ReloadEvent frames_until_event(std::vector<fx::Image>* images = nullptr) {
    const auto give_up = std::chrono::steady_clock::now() + fx::testing::patience();
    std::vector<ReloadEvent> events;
    while (events.empty() && std::chrono::steady_clock::now() < give_up) {
      lib->wait(std::chrono::milliseconds(2));
      auto image = frame_once(&events);
      EXPECT_TRUE(image) << "dropped frame " << frame;
      if (image && images) images->push_back(*image);
    }
    EXPECT_FALSE(events.empty()) << "no reload event within 10 s";
    return events.empty() ? ReloadEvent{} : events.front();
  }

  void edit(const std::string& text) { std::ofstream(path, std::ios::trunc) << text; }
};

TEST_F(EffectReloadTest, BrokenEditKeepsTheImageAndTheFixApplies) {
  ReloadHarness h(ctx(), "reload_broken.fx");
  auto before = h.frame_once();
  ASSERT_TRUE(before);
  h.edit(effect_text(0.85f, /*broken=*/true));
  ReloadEvent failed = h.frames_until_event();
  EXPECT_EQ(failed.kind, ReloadEventKind::failed);
  ASSERT_FALSE(failed.diagnostics.empty());
  auto after = h.frame_once();
  ASSERT_TRUE(after);
  EXPECT_EQ(before->pixels, after->pixels);  // bit-identical: the last good version draws
  h.edit(effect_text(0.3f));
  ReloadEvent fixed = h.frames_until_event();
  EXPECT_EQ(fixed.kind, ReloadEventKind::reloaded);
  auto darker = h.frame_once();
  ASSERT_TRUE(darker);
  EXPECT_NE(before->pixels, darker->pixels);
}

TEST_F(EffectReloadTest, ReloadsDuringRenderedFramesDropNothingAndLeakNothing) {
  // A number of edits, not of frames: how many frames a reload takes depends on the machine's
  // load, and the test waits for each reload's event.
  const char* soak = std::getenv("FXKIT_SOAK");
  const uint32_t edits = soak && std::string(soak) == "1" ? 300 : 30;
  ReloadHarness h(ctx(), "reload_soak.fx");
  ASSERT_TRUE(h.frame_once());
  const int64_t baseline_objects = EffectBinding::live_vulkan_objects();
  const size_t baseline_textures = h.preview->textures().gpu_count();
  const size_t baseline_versions = EffectVersion::live_count();
  uint64_t reloads = 0, failures = 0;
  for (uint32_t edit = 0; edit < edits; ++edit) {
    // Good and broken edits alternate with two brightness values; every third is broken.
    const bool broken = edit % 3 == 2;
    h.edit(effect_text(edit % 2 ? 0.5f : 0.7f, broken));
    ReloadEvent ev = h.frames_until_event();
    (ev.kind == ReloadEventKind::reloaded ? reloads : failures) += 1;
    EXPECT_EQ(ev.kind, broken ? ReloadEventKind::failed : ReloadEventKind::reloaded) << "edit " << edit;
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(h.frame_once());  // frames between edits
    if (HasFailure()) break;
  }
  // Back to the first text: the live version then holds what the baseline version held.
  h.edit(effect_text(0.85f));
  EXPECT_EQ(h.frames_until_event().kind, ReloadEventKind::reloaded);
  ASSERT_TRUE(h.frame_once());
  ctx().wait_idle();
  h.lib->release_all();
  EXPECT_EQ(reloads, edits - edits / 3);
  EXPECT_EQ(failures, edits / 3);
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
  EXPECT_EQ(EffectBinding::live_vulkan_objects(), baseline_objects);
  EXPECT_EQ(h.preview->textures().gpu_count(), baseline_textures);
  EXPECT_EQ(EffectVersion::live_count(), baseline_versions);
}

// A sphere in one colour: a texture shader's texel, which `colour` (HLSL) gives; `broken`
// leaves the function unfinished.
std::string texture_shader_text(const std::string& colour, bool broken = false) {
  return R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture Fill < string function = "Paint"; int width = 4; int height = 4; >;
sampler2D FillSampler = sampler_state { Texture = <Fill>; };
float4 Paint(float2 p : POSITION) : COLOR { return )" +
         colour + (broken ? "" : "; }") + R"(
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return tex2D(FillSampler, float2(0.5, 0.5)); }
technique painted { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";
}

// A reloaded version fills its texture anew: an edited texture shader changes the picture; a
// broken one keeps the last good picture.
TEST_F(EffectReloadTest, AnEditedTextureShaderRefillsItsTexture) {
  ReloadHarness h(ctx(), "reload_texture_shader.fx", texture_shader_text("float4(1, 0, 0, 1)"));
  auto centre = [](const fx::Image& image) {
    const uint8_t* p = image.at(image.width / 2, image.height / 2);
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  auto red = h.frame_once();
  ASSERT_TRUE(red);
  EXPECT_EQ(centre(*red), (std::array<int, 3>{255, 0, 0}));
  h.edit(texture_shader_text("float4(0, 0, 1, 1)"));
  EXPECT_EQ(h.frames_until_event().kind, ReloadEventKind::reloaded);
  auto blue = h.frame_once();
  ASSERT_TRUE(blue);
  EXPECT_EQ(centre(*blue), (std::array<int, 3>{0, 0, 255}));
  h.edit(texture_shader_text("float4(0, 1, 0, 1)", /*broken=*/true));
  EXPECT_EQ(h.frames_until_event().kind, ReloadEventKind::failed);
  auto kept = h.frame_once();
  ASSERT_TRUE(kept);
  EXPECT_EQ(centre(*kept), (std::array<int, 3>{0, 0, 255}));
}

}  // namespace
}  // namespace fx::vk::testing
