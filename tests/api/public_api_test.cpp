// The public API (fxkit/fxkit.h) end to end on a validated device: a Device wrapped around
// the application's handles or made headless, effects loaded from files on disk, techniques
// by name and by selection, parameters, recording into the application's command buffer,
// the winding convention, reloads through begin_frame().
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <fstream>

#include "../vulkan/effect_test_util.h"
#include "fxkit/fxkit.h"
#include "patience.h"

namespace fx::vk::testing {
namespace {

// A lit sphere; `cull` is the D3D CullMode (CCW culls the back faces of D3D's clockwise meshes).
std::string lit_effect(const std::string& tint = "0.9, 0.6, 0.3", const std::string& cull = "CCW") {
  return R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4x4 World : WORLD;
float3 LightDirection : DIRECTION = {0.3, -0.8, -0.5};
float4 Tint = {)" +
         tint + R"(, 1.0};
struct V { float4 pos : POSITION; float3 n : TEXCOORD0; };
V VS(float4 p : POSITION, float3 n : NORMAL) { V o; o.pos = mul(p, WorldViewProjection); o.n = mul(n, (float3x3)World); return o; }
float4 PS(V i) : COLOR0 { return float4(Tint.rgb * (0.2 + 0.8 * saturate(dot(normalize(i.n), -LightDirection))), 1.0); }
technique lit < float MaxError = 1.5; string Scheme = "preview"; > { pass p0 { CullMode = )" +
         cull + R"(; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
technique assembly < string Requires = "render_targets>=64"; > { pass p0 { VertexShader = asm { vs.1.1 dcl_position v0 m4x4 oPos, v0, c0 }; } }
)";
}

std::string text(const std::vector<fxkit::Message>& messages) {
  std::string s;
  for (const auto& m : messages) s += m.rendered;
  return s;
}

fxkit::DeviceOptions options(fxkit::Winding winding = fxkit::Winding::counter_clockwise) {
  fxkit::DeviceOptions o;
  o.target = {.formats = {.color = {VK_FORMAT_R8G8B8A8_UNORM}, .depth = VK_FORMAT_D32_SFLOAT},
              .vertex_layout = fxkit::Mesh::vertex_layout(),
              .front_faces = winding,
              .y_flip = fxkit::YFlip::negative_viewport};
  return o;
}

// What each drawing test makes first: a device on the fixture's context, a sphere, an image.
struct Rig {
  std::unique_ptr<fxkit::Device> device;
  std::unique_ptr<fxkit::Mesh> mesh;
  std::unique_ptr<fxkit::Offscreen> image;
  std::vector<fxkit::Message> errors;
  explicit operator bool() const { return device && mesh && image; }
  // The red, green and blue of the image's centre pixel.
  std::array<uint8_t, 3> centre() const {
    const auto rgba = image->read_rgba8();
    const size_t c = (size_t(image->height() / 2) * image->width() + image->width() / 2) * 4;
    return {rgba.at(c), rgba.at(c + 1), rgba.at(c + 2)};
  }
};

class PublicApiTest : public VulkanTest {
 protected:
  Rig rig(const fxkit::DeviceOptions& o = options(), uint32_t size = 32) {
    Rig r;
    r.device = fxkit::Device::create(handles(), o, r.errors);
    if (r.device) r.mesh = fxkit::Mesh::create(*r.device, "sphere", r.errors);
    if (r.device) r.image = fxkit::Offscreen::create(*r.device, size, size, r.errors);
    return r;
  }
  fxkit::VulkanHandles handles() {
    return {ctx().instance(), ctx().physical_device(), ctx().device(), ctx().queue(), ctx().queue_family()};
  }
  // Writes `text` over the effect file at `path` and runs frames until the device reports
  // the reload (giving up after fx::testing::patience()); what begin_frame() reported.
  static std::vector<fxkit::Reload> rewrite_and_reload(fxkit::Device& device, const std::string& path,
                                                       const std::string& text) {
    std::ofstream(path, std::ios::trunc) << text;
    std::vector<fxkit::Reload> reloads;
    const auto give_up = std::chrono::steady_clock::now() + fx::testing::patience();
    while (reloads.empty() && std::chrono::steady_clock::now() < give_up) {
      device.wait_for_reload(std::chrono::milliseconds(20));
      reloads = device.begin_frame();
    }
    return reloads;
  }
  // One frame of `technique` on `mesh` into `image`; the centre pixel's RGB.
  static std::array<uint8_t, 3> draw(fxkit::Device& device, fxkit::Technique& technique, fxkit::Mesh& mesh,
                                     fxkit::Offscreen& image) {
    device.begin_frame();
    bool drawn = false;
    EXPECT_TRUE(device.submit([&](VkCommandBuffer cmd) {
      image.begin(cmd);
      if (technique.begin(cmd, image.viewport(), image.scissor()))
        for (uint32_t p = 0; p < technique.pass_count(); ++p)
          if (technique.apply(p)) mesh.draw(cmd), drawn = true;
      technique.end();
      image.end(cmd);
    }));
    EXPECT_TRUE(drawn);
    const auto rgba = image.read_rgba8();
    const size_t c = (size_t(image.height() / 2) * image.width() + image.width() / 2) * 4;
    return {rgba.at(c), rgba.at(c + 1), rgba.at(c + 2)};
  }
};

TEST_F(PublicApiTest, WrappedDeviceLoadsSelectsSetsDrawsAndReadsBack) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_lit.fx", lit_effect()));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  EXPECT_GT(effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f)), 0u);

  fxkit::Technique technique = effect.select();
  EXPECT_EQ(technique.name(), "lit");
  const auto orange = draw(*r.device, technique, *r.mesh, *r.image);
  EXPECT_GT(orange[0], orange[2] + 40) << "the default tint is orange";

  ASSERT_TRUE(effect.set(effect.param("Tint"), {0.1f, 0.2f, 0.9f, 1.0f}));
  const auto blue = draw(*r.device, technique, *r.mesh, *r.image);
  EXPECT_GT(blue[2], blue[0] + 40) << "the tint set through the handle is drawn";
  EXPECT_FALSE(effect.set(effect.param("Tint"), 1.0f)) << "a float for a float4 is refused";
  EXPECT_FALSE(effect.messages().empty());
}

// Technique::apply (inline, one call into the library) binds only between begin() and
// end(): a default technique, one not begun, one ended, or one whose begin() failed apply
// nothing; a pass past the last is refused with a message kept for messages().
TEST_F(PublicApiTest, ApplyBindsOnlyBetweenBeginAndEnd) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_apply.fx", lit_effect()));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  fxkit::Technique none, lit = effect.technique("lit"), broken = effect.technique("nope");
  EXPECT_FALSE(none.apply(0));
  EXPECT_FALSE(lit.apply(0)) << "not begun";
  r.device->begin_frame();
  EXPECT_TRUE(r.device->submit([&](VkCommandBuffer cmd) {
    r.image->begin(cmd);
    EXPECT_FALSE(none.begin(cmd, r.image->viewport(), r.image->scissor()));
    EXPECT_FALSE(broken.begin(cmd, r.image->viewport(), r.image->scissor()));
    EXPECT_FALSE(broken.apply(0)) << "its begin() failed";
    ASSERT_TRUE(lit.begin(cmd, r.image->viewport(), r.image->scissor()));
    EXPECT_TRUE(lit.apply(0));
    r.mesh->draw(cmd);
    EXPECT_FALSE(lit.apply(1)) << "past the last pass";
    lit.end();
    EXPECT_FALSE(lit.apply(0)) << "ended";
    r.image->end(cmd);
  }));
  bool told = false;
  for (const fxkit::Message& m : effect.messages()) told = told || m.code == "vk-pass-unknown";
  EXPECT_TRUE(told) << text(effect.messages());
}

TEST_F(PublicApiTest, TechniquesByNameSayWhyTheyCannotDraw) {
  std::vector<fxkit::Message> errors;
  auto device = fxkit::Device::create(handles(), options(), errors);
  ASSERT_TRUE(device) << text(errors);
  fxkit::Effect effect = device->load(write_effect("api_names.fx", lit_effect()));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  EXPECT_TRUE(effect.technique("lit").valid());
  EXPECT_EQ(effect.technique("lit").pass_count(), 1u);
  fxkit::Technique missing = effect.technique("nope");
  EXPECT_FALSE(missing.valid());
  EXPECT_EQ(missing.reason(), "the effect has no technique 'nope'");
  fxkit::Technique broken = effect.technique("assembly");
  EXPECT_FALSE(broken.valid());
  EXPECT_FALSE(broken.reason().empty());
  const auto infos = effect.techniques();
  ASSERT_EQ(infos.size(), 2u);
  ASSERT_NE(infos[0].annotation("MaxError"), nullptr) << "technique annotations, as written";
  EXPECT_FLOAT_EQ(infos[0].annotation("MaxError")->number(), 1.5f);
  EXPECT_EQ(infos[0].annotation("Scheme")->text, "preview");
  EXPECT_EQ(infos[1].annotation("MaxError"), nullptr);
  EXPECT_TRUE(infos[0].drawable);
  EXPECT_FALSE(infos[1].drawable);
  EXPECT_EQ(infos[1].reason, broken.reason());
}

TEST_F(PublicApiTest, TheTargetMustStateItsConventions) {
  std::vector<fxkit::Message> errors;
  auto o = options();
  o.target.front_faces = fxkit::Winding::unset;
  o.target.y_flip = fxkit::YFlip::unset;
  EXPECT_FALSE(fxkit::Device::create(handles(), o, errors));
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].code, "target-incomplete");
  EXPECT_NE(errors[0].text.find("front_faces"), std::string::npos);
  EXPECT_NE(errors[1].text.find("y_flip"), std::string::npos);
}

TEST_F(PublicApiTest, ADeviceCreatedWithoutDynamicRenderingIsRefused) {
  // What the application enabled decides, not what the physical device supports.
  VkDeviceCreateInfo created{};
  created.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  fxkit::VulkanHandles h = handles();
  h.created_with = &created;
  std::vector<fxkit::Message> errors;
  EXPECT_FALSE(fxkit::Device::create(h, options(), errors));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].code, "vk-feature-missing");

  VkPhysicalDeviceVulkan13Features v13{};
  v13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  v13.dynamicRendering = VK_TRUE;
  created.pNext = &v13;
  errors.clear();
  EXPECT_TRUE(fxkit::Device::create(h, options(), errors)) << text(errors);
}

TEST_F(PublicApiTest, TheStatedWindingDecidesWhichFacesTheEffectCulls) {
  // CullMode = CCW culls Direct3D's back faces. Stating the meshes' real winding
  // (counter-clockwise) draws the lit front of the sphere; claiming clockwise culls the
  // front and shows the dark inside of the back.
  std::array<uint8_t, 3> centre[2];
  const fxkit::Winding windings[2] = {fxkit::Winding::counter_clockwise, fxkit::Winding::clockwise};
  for (int i = 0; i < 2; ++i) {
    Rig r = rig(options(windings[i]));
    ASSERT_TRUE(r) << text(r.errors);
    fxkit::Effect effect = r.device->load(write_effect("api_cull.fx", lit_effect("1, 1, 1")));
    ASSERT_TRUE(effect.ok()) << text(effect.messages());
    effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
    fxkit::Technique t = effect.technique("lit");
    centre[i] = draw(*r.device, t, *r.mesh, *r.image);
  }
  EXPECT_GT(int(centre[0][0]), int(centre[1][0]) + 60) << int(centre[0][0]) << " vs " << int(centre[1][0]);
}

TEST_F(PublicApiTest, BeginFrameSwapsInAnEditAndKeepsTheLastGoodEffectAfterABrokenOne) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  const std::string path = write_effect("api_reload.fx", lit_effect());
  fxkit::Effect effect = r.device->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  const fxkit::Scene scene = fxkit::Scene::framing(r.mesh->radius(), 1.0f);
  effect.set_scene(scene);
  fxkit::Technique technique = effect.select();
  const auto before = draw(*r.device, technique, *r.mesh, *r.image);

  auto reload_after = [&](const std::string& text) { return rewrite_and_reload(*r.device, path, text); };
  auto failed = reload_after(lit_effect() + "technique broken { pass { VertexShader = compile vs_2_0 Nope(); } }");
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_EQ(failed[0].kind, fxkit::Reload::Kind::failed);
  ASSERT_FALSE(failed[0].messages.empty());
  EXPECT_EQ(failed[0].messages[0].file, path);
  EXPECT_GT(failed[0].messages[0].line, 0u);
  EXPECT_EQ(draw(*r.device, technique, *r.mesh, *r.image), before) << "the last good version draws";

  auto reloaded = reload_after(lit_effect("0.1, 0.9, 0.1"));
  ASSERT_EQ(reloaded.size(), 1u);
  EXPECT_EQ(reloaded[0].kind, fxkit::Reload::Kind::reloaded) << reloaded[0].str();
  effect.set_scene(scene);
  const auto green = draw(*r.device, technique, *r.mesh, *r.image);
  EXPECT_GT(green[1], green[0] + 40) << "the edited default tint is drawn";
}

// A Technique held by name draws that technique after a reload moves it to another index
// and counts its new passes (begin() and pass_count() resolve the name once per version).
TEST_F(PublicApiTest, ATechniqueHeldByNameFollowsItsNameAcrossAReloadThatReordersThem) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  auto colour = [](const char* name, const char* rgb, int passes = 1) {
    std::string t = std::string("technique ") + name + " {";
    for (int p = 0; p < passes; ++p)
      t += " pass { CullMode = None; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(float3(" +
           std::string(rgb) + ")); }";
    return t + " }\n";
  };
  const std::string common = R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS(uniform float3 c) : COLOR0 { return float4(c, 1.0); }
)";
  const std::string path =
      write_effect("api_reorder.fx", common + colour("red", "1, 0, 0") + colour("green", "0, 1, 0"));
  fxkit::Effect effect = r.device->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fxkit::Technique green = effect.technique("green");
  const auto before = draw(*r.device, green, *r.mesh, *r.image);
  EXPECT_GT(before[1], 200);
  EXPECT_LT(before[0], 50);
  EXPECT_EQ(green.pass_count(), 1u);
  auto reloaded =
      rewrite_and_reload(*r.device, path, common + colour("green", "0, 1, 0", 2) + colour("red", "1, 0, 0"));
  ASSERT_EQ(reloaded.size(), 1u);
  ASSERT_EQ(reloaded[0].kind, fxkit::Reload::Kind::reloaded) << reloaded[0].str();
  EXPECT_EQ(green.pass_count(), 2u) << "the reloaded technique's passes";
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  const auto after = draw(*r.device, green, *r.mesh, *r.image);
  EXPECT_GT(after[1], 200) << "still the technique called green";
  EXPECT_LT(after[0], 50);
}

// Effect::set_texture on the application's views: each frame in flight writes its kept
// descriptor set once, later frames write none, and setting a view again writes them again
// even when the handle is the same (a view made anew may reuse the old one's handle).
TEST_F(PublicApiTest, SetTextureWritesEachKeptDescriptorSetOnceAndAgainWhenSetAgain) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  const std::string path = write_effect("api_texture.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture Tex;
sampler2D S = sampler_state { Texture = <Tex>; };
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return tex2D(S, float2(0.5, 0.5)); }
technique t { pass { CullMode = None; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  fxkit::Effect effect = r.device->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  DiagnosticSink sink;
  auto red = solid_texture(ctx(), 255, 0, sink), green = solid_texture(ctx(), 0, 255, sink);
  ASSERT_TRUE(red && green) << describe(sink);
  fxkit::Technique technique = effect.technique("t");
  auto frame = [&](std::array<uint8_t, 3>& rgb) {
    effect.reset_stats();
    rgb = draw(*r.device, technique, *r.mesh, *r.image);
    return effect.stats().descriptor_writes;
  };
  std::array<uint8_t, 3> rgb{};
  ASSERT_TRUE(effect.set_texture("Tex", red->view(), red->layout()));
  for (uint64_t want : {1u, 1u, 0u, 0u}) {  // two frames in flight (DeviceOptions' default)
    EXPECT_EQ(frame(rgb), want);
    EXPECT_GT(rgb[0], 200);
  }
  ASSERT_TRUE(effect.set_texture("Tex", red->view(), red->layout())) << "the same handle again";
  for (uint64_t want : {1u, 1u, 0u}) EXPECT_EQ(frame(rgb), want);
  ASSERT_TRUE(effect.set_texture("Tex", green->view(), green->layout()));
  EXPECT_EQ(frame(rgb), 1u);
  EXPECT_GT(rgb[1], 200);
  EXPECT_LT(rgb[0], 50);
}

// A framed scene's WorldViewProjection for per-object draws: `on` draws the mesh in view,
// `off` moves clip x far off screen (row 3, D3D order).
struct PerObjectMatrix {
  fxkit::Param wvp;
  float on[16] = {}, off[16] = {};
  bool ok = false;
};
PerObjectMatrix per_object_matrix(fxkit::Effect& effect, float radius) {
  PerObjectMatrix m;
  effect.set_scene(fxkit::Scene::framing(radius, 1.0f));
  m.wvp = effect.param("WorldViewProjection");
  m.ok = effect.get(m.wvp, std::span<float>(m.on));
  std::copy_n(m.on, 16, m.off);
  m.off[12] += 1000.f;
  return m;
}

// Effect::set_matrix per object (inline once the matrix is the application's and its block
// is hot): each object of a frame draws with its own value, a getter reads the last one back,
// and a handle from before a reload sets the new version's matrix.
TEST_F(PublicApiTest, SetMatrixPerObjectDrawsEachValueAndFollowsReloads) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  const std::string path = write_effect("api_per_object.fx", lit_effect());
  fxkit::Effect effect = r.device->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  const PerObjectMatrix m = per_object_matrix(effect, r.mesh->radius());
  ASSERT_TRUE(m.ok);
  const fxkit::Param wvp = m.wvp;
  const float* on = m.on;
  const float* off = m.off;
  fxkit::Technique technique = effect.select();
  ASSERT_TRUE(effect.set_matrix(wvp, on));
  const auto sphere = draw(*r.device, technique, *r.mesh, *r.image);
  // Two objects in one frame, the matrix set before each; the centre pixel.
  auto two_objects = [&](const float* first, const float* second) {
    r.device->begin_frame();
    EXPECT_TRUE(r.device->submit([&](VkCommandBuffer cmd) {
      r.image->begin(cmd);
      if (technique.begin(cmd, r.image->viewport(), r.image->scissor()))
        for (const float* m : {first, second}) {
          EXPECT_TRUE(effect.set_matrix(wvp, m));
          for (uint32_t p = 0; p < technique.pass_count(); ++p)
            if (technique.apply(p)) r.mesh->draw(cmd);
        }
      technique.end();
      r.image->end(cmd);
    }));
    return r.centre();
  };
  EXPECT_NE(two_objects(off, off), sphere) << "both off screen";
  EXPECT_EQ(two_objects(off, on), sphere) << "the second object draws with its own matrix";
  EXPECT_EQ(two_objects(on, off), sphere) << "the first object draws with its own matrix";
  float back[16];
  ASSERT_TRUE(effect.get(wvp, std::span<float>(back)));
  EXPECT_TRUE(std::equal(back, back + 16, off)) << "the getter reads the last value set";

  auto reloaded = rewrite_and_reload(*r.device, path, lit_effect("0.1, 0.9, 0.1"));
  ASSERT_EQ(reloaded.size(), 1u);
  EXPECT_EQ(reloaded[0].kind, fxkit::Reload::Kind::reloaded) << reloaded[0].str();
  EXPECT_NE(two_objects(off, off), sphere) << "after the reload, both off screen";
  const auto green = two_objects(on, off);
  EXPECT_GT(green[1], green[0] + 40) << "the new version draws the object set on screen";
  EXPECT_EQ(two_objects(off, on), green);
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
}

TEST_F(PublicApiTest, InputsTheLayoutLacksReadDefaultsOnlyWhenTheTargetSaysWhere) {
  // COLOR0 is not in the mesh layout: an error naming what is on offer, or (0, 0, 0, 1) from
  // fxkit's buffer at the stated binding, so the sphere draws black with alpha 1 plus 0.5 red.
  const std::string effect_text = R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct V { float4 pos : POSITION; float4 colour : COLOR0; };
V VS(float4 p : POSITION, float4 c : COLOR0) { V o; o.pos = mul(p, WorldViewProjection); o.colour = c; return o; }
float4 PS(V i) : COLOR0 { return i.colour + float4(0.5, 0, 0, 0); }
technique coloured { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";
  const std::string path = write_effect("api_defaults.fx", effect_text);
  {
    std::vector<fxkit::Message> errors;
    auto device = fxkit::Device::create(handles(), options(), errors);
    ASSERT_TRUE(device) << text(errors);
    fxkit::Effect effect = device->load(path);
    EXPECT_FALSE(effect.ok());
    const auto messages = effect.messages();
    auto missing = std::find_if(messages.begin(), messages.end(),
                                [](const fxkit::Message& m) { return m.code == "vk-vertex-attribute-missing"; });
    ASSERT_NE(missing, messages.end()) << text(messages);
    EXPECT_NE(missing->text.find("reads COLOR"), std::string::npos) << missing->rendered;
    EXPECT_EQ(missing->file, path) << "located at the VertexShader state";
    EXPECT_EQ(missing->line, 6u) << missing->rendered;
  }
  auto o = options();
  o.target.default_attribute_binding = 1;
  Rig r = rig(o);
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fxkit::Technique t = effect.technique("coloured");
  const auto centre = draw(*r.device, t, *r.mesh, *r.image);
  EXPECT_NEAR(int(centre[0]), 128, 2);
  EXPECT_EQ(int(centre[1]), 0);
  EXPECT_EQ(int(centre[2]), 0);
}

TEST_F(PublicApiTest, WithoutDynamicStateEveryStateIsInThePipeline) {
  // Two techniques with different cull and depth states, one frame each: with dynamic state
  // the states are set by vkCmdSet* where the device has extended dynamic state; without,
  // they are in the pipelines and only viewport and scissor are set.
  uint64_t calls[2] = {};
  for (int dynamic = 0; dynamic < 2; ++dynamic) {
    auto o = options();
    o.dynamic_state = dynamic == 1;
    Rig r = rig(o, 16);
    ASSERT_TRUE(r) << text(r.errors);
    fxkit::Effect effect = r.device->load(write_effect(
        "api_dynamic.fx", lit_effect("1, 1, 1", "None") +
                              "technique culled { pass p0 { CullMode = CW; ZEnable = false; VertexShader = "
                              "compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"));
    ASSERT_TRUE(effect.ok()) << text(effect.messages());
    fxkit::Technique lit = effect.technique("lit"), culled = effect.technique("culled");
    draw(*r.device, lit, *r.mesh, *r.image);
    draw(*r.device, culled, *r.mesh, *r.image);
    calls[dynamic] = effect.stats().dynamic_state_calls;
  }
  EXPECT_EQ(calls[0], 4u) << "static pipelines: only viewport and scissor, at each of the two begins";
  if (ctx().features().extended_dynamic_state) {
    EXPECT_GT(calls[1], calls[0]);
  }
}

TEST_F(PublicApiTest, FramesInFlightOverlapWithoutTouchingWhatTheGpuReads) {
  // An engine's loop: two frames in flight, each slot waited by its fence only before the
  // slot is recorded again; nothing changes between frames, so fxkit could be tempted to
  // reuse the previous frame's uniform data and descriptor sets, which the GPU may still be
  // reading when that slot's memory is recycled (VUID-vkResetDescriptorPool-descriptorPool-00313).
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_in_flight.fx", lit_effect()));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fxkit::Technique technique = effect.select();
  VkCommandPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = ctx().queue_family();
  VkCommandPool pool = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateCommandPool(ctx().device(), &pool_info, nullptr, &pool), VK_SUCCESS);
  VkCommandBuffer cmds[2];
  VkCommandBufferAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  alloc.commandPool = pool;
  alloc.commandBufferCount = 2;
  ASSERT_EQ(vkAllocateCommandBuffers(ctx().device(), &alloc, cmds), VK_SUCCESS);
  VkFence fences[2];
  VkFenceCreateInfo fence_info{};
  fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  for (VkFence& f : fences) ASSERT_EQ(vkCreateFence(ctx().device(), &fence_info, nullptr, &f), VK_SUCCESS);
  for (int frame = 0; frame < 8; ++frame) {
    const int slot = frame % 2;
    vkWaitForFences(ctx().device(), 1, &fences[slot], VK_TRUE, UINT64_MAX);  // frame - 2 is done
    vkResetFences(ctx().device(), 1, &fences[slot]);
    r.device->begin_frame();
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    vkBeginCommandBuffer(cmds[slot], &begin);
    r.image->begin(cmds[slot]);
    ASSERT_TRUE(technique.begin(cmds[slot], r.image->viewport(), r.image->scissor()));
    for (uint32_t p = 0; p < technique.pass_count(); ++p)
      if (technique.apply(p)) r.mesh->draw(cmds[slot]);
    technique.end();
    r.image->end(cmds[slot]);
    vkEndCommandBuffer(cmds[slot]);
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmds[slot];
    ASSERT_EQ(vkQueueSubmit(ctx().queue(), 1, &submit, fences[slot]), VK_SUCCESS);
  }
  vkWaitForFences(ctx().device(), 2, fences, VK_TRUE, UINT64_MAX);
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
  for (VkFence f : fences) vkDestroyFence(ctx().device(), f, nullptr);
  vkDestroyCommandPool(ctx().device(), pool, nullptr);
}

TEST(PublicApiHeadless, HeadlessDeviceReportsValidationThroughMessages) {
  std::vector<fxkit::Message> errors;
  fxkit::HeadlessOptions headless;
  headless.validation = true;
  auto device = fxkit::Device::headless(options(), headless, errors);
  ASSERT_TRUE(device) << text(errors);
  EXPECT_FALSE(device->device_name().empty());
  auto mesh = fxkit::Mesh::create(*device, "no_such_shape", errors);
  EXPECT_FALSE(mesh);
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors.back().rendered.find("no_such_shape"), std::string::npos);
  EXPECT_TRUE(device->take_validation_messages().empty());
}

}  // namespace
}  // namespace fx::vk::testing

namespace fx::vk::testing {
namespace {

TEST_F(PublicApiTest, ParamsReflectTypesDefaultsAndAnnotations) {
  std::vector<fxkit::Message> errors;
  auto device = fxkit::Device::create(handles(), options(), errors);
  ASSERT_TRUE(device) << text(errors);
  fxkit::Effect effect = device->load(write_effect("api_params.fx", lit_effect() + R"(
float Gloss <string UIName = "Glossiness"; string UIWidget = "Slider"; float UIMin = 1; float UIMax = 128;
             int UISteps = 10; bool UIVisible = true;> = 32;
int Count : LIGHTCOUNT = 3;
float3 Lights[2] = {1, 2, 3, 4, 5, 6};
texture DiffuseMap <string ResourceName = "brick.png";>;
texture3D Noise;
sampler2D DiffuseSampler = sampler_state { Texture = <DiffuseMap>; };
string Help = "one line of help";
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  const std::vector<fxkit::ParamInfo> params = effect.params();
  auto find = [&](const char* name) -> const fxkit::ParamInfo& {
    auto it = std::find_if(params.begin(), params.end(), [&](const auto& p) { return p.name == name; });
    EXPECT_NE(it, params.end()) << name;
    return *it;
  };
  const fxkit::ParamInfo& wvp = find("WorldViewProjection");
  EXPECT_EQ(wvp.semantic, "WORLDVIEWPROJECTION");
  EXPECT_EQ(wvp.kind, fxkit::ParamKind::numeric);
  EXPECT_EQ(wvp.rows, 4u);
  EXPECT_EQ(wvp.columns, 4u);
  EXPECT_EQ(wvp.components, 16u);
  EXPECT_FALSE(wvp.has_default);

  const fxkit::ParamInfo& tint = find("Tint");
  EXPECT_EQ(tint.type, "float4");
  EXPECT_EQ(tint.default_value, (std::vector<float>{0.9f, 0.6f, 0.3f, 1.0f}));
  EXPECT_TRUE(tint.settable);
  std::vector<float> now(tint.components);
  ASSERT_TRUE(effect.set(tint.handle, {0.5f, 0.5f, 0.5f, 1.0f}));
  ASSERT_TRUE(effect.get(tint.handle, now));
  EXPECT_EQ(now[0], 0.5f) << "the current value is read through the handle";

  const fxkit::ParamInfo& gloss = find("Gloss");
  ASSERT_NE(gloss.annotation("UIName"), nullptr);
  EXPECT_EQ(gloss.annotation("UIName")->kind, fxkit::Annotation::Kind::string);
  EXPECT_EQ(gloss.annotation("UIName")->text, "Glossiness");
  EXPECT_EQ(gloss.annotation("UIMax")->kind, fxkit::Annotation::Kind::floats);
  EXPECT_EQ(gloss.annotation("UIMax")->number(), 128.f);
  EXPECT_EQ(gloss.annotation("UISteps")->kind, fxkit::Annotation::Kind::ints);
  EXPECT_EQ(gloss.annotation("UIVisible")->kind, fxkit::Annotation::Kind::boolean);
  EXPECT_EQ(gloss.annotation("uiname"), nullptr) << "annotation names are case-sensitive";

  const fxkit::ParamInfo& count = find("Count");
  EXPECT_EQ(count.scalar, fxkit::ScalarKind::int32);
  std::vector<int32_t> n(1);
  ASSERT_TRUE(effect.get(count.handle, n));
  EXPECT_EQ(n[0], 3);
  const fxkit::ParamInfo& lights = find("Lights");
  EXPECT_EQ(lights.elements, 2u);
  EXPECT_EQ(lights.components, 6u);
  const fxkit::ParamInfo& map = find("DiffuseMap");
  EXPECT_EQ(map.kind, fxkit::ParamKind::texture);
  EXPECT_EQ(map.resource_name, "brick.png");
  EXPECT_EQ(find("Noise").texture_shape, "3D");
  EXPECT_EQ(find("DiffuseSampler").kind, fxkit::ParamKind::sampler);
  EXPECT_EQ(find("Help").kind, fxkit::ParamKind::string);
  EXPECT_EQ(find("Help").default_text, "one line of help");
}

// DirectX SDK samples declare their transforms without semantics (BasicHLSL's
// g_mWorldViewProjection): set_scene binds them by name, and warns about a transform it
// cannot place.
TEST_F(PublicApiTest, SetSceneBindsTransformsByTheirNamesAndWarnsAboutOnesLeftZero) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  auto renamed = [](std::string s, const std::string& from, const std::string& to) {
    for (size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
    return s;
  };
  std::string sdk = renamed(lit_effect(), "WorldViewProjection : WORLDVIEWPROJECTION", "WorldViewProjection");
  sdk = renamed(renamed(sdk, "World : WORLD", "World"), "World", "g_mWorld");  // g_mWorldViewProjection too
  fxkit::Effect effect = r.device->load(write_effect("api_sdk_names.fx", sdk));
  ASSERT_TRUE(effect.ok()) << text(effect.messages()) << sdk;
  EXPECT_EQ(effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f)), 2u);
  fxkit::Technique technique = effect.select();
  const auto lit = draw(*r.device, technique, *r.mesh, *r.image);
  EXPECT_GT(lit[0], 40) << "the sphere is drawn with the transforms bound by name";
  EXPECT_EQ(text(effect.messages()).find("scene-transform-unbound"), std::string::npos) << text(effect.messages());

  const std::string unknown = renamed(sdk, "g_mWorldViewProjection", "g_mMyTransform");
  fxkit::Effect unbound = r.device->load(write_effect("api_unknown_names.fx", unknown));
  ASSERT_TRUE(unbound.ok()) << text(unbound.messages());
  EXPECT_EQ(unbound.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f)), 1u);
  const std::string warned = text(unbound.messages());
  EXPECT_NE(warned.find("'g_mMyTransform' is read by the shaders but set_scene() left it zero"), std::string::npos)
      << warned;
  EXPECT_EQ(warned.find("'g_mWorld'"), std::string::npos) << warned;
}

// Criteria::caps selects as an older generation would, among what this device draws: a DX8
// card cannot run ps_2_0, so the ps_1_1 technique is chosen and techniques() says why.
TEST_F(PublicApiTest, SelectionEmulatesACapsProfile) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  const std::string common = R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 Bright() : COLOR0 { return float4(1, 1, 1, 1); }
float4 Dim() : COLOR0 { return float4(0.5, 0.5, 0.5, 1); }
technique sm2 { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Bright(); } }
)";
  const std::string sm1 =
      "technique sm1 { pass p0 { VertexShader = compile vs_1_1 VS(); PixelShader = compile ps_1_1 Dim(); } }\n";
  const std::string path = write_effect("api_emulated_caps.fx", common + sm1);
  fxkit::Effect effect = r.device->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  EXPECT_EQ(effect.select().name(), "sm2");
  fxkit::Criteria dx8;
  dx8.caps = "dx8";
  EXPECT_EQ(effect.select(dx8).name(), "sm1");
  const auto listed = effect.techniques();
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_TRUE(listed[0].drawable) << "this device still draws it";
  EXPECT_NE(listed[0].caps_reason.find("dx8: "), std::string::npos) << listed[0].caps_reason;
  EXPECT_NE(listed[0].caps_reason.find("ps_2_0"), std::string::npos) << listed[0].caps_reason;
  EXPECT_EQ(listed[1].caps_reason, "");

  // A reload selects again under the same emulated profile: the new ps_1_1 technique,
  // declared first, is what a DX8 card would now draw.
  fxkit::Technique chosen = effect.select(dx8);
  std::ofstream(path, std::ios::trunc) << common +
                                              "technique sm1_first { pass p0 { VertexShader = compile vs_1_1 VS(); "
                                              "PixelShader = compile ps_1_1 Bright(); } }\n" +
                                              sm1;
  std::vector<fxkit::Reload> reloads;
  for (auto give_up = std::chrono::steady_clock::now() + fx::testing::patience();
       reloads.empty() && std::chrono::steady_clock::now() < give_up;) {
    r.device->wait_for_reload(std::chrono::milliseconds(20));
    reloads = r.device->begin_frame();
  }
  ASSERT_EQ(reloads.size(), 1u);
  ASSERT_EQ(reloads[0].kind, fxkit::Reload::Kind::reloaded) << reloads[0].str();
  EXPECT_EQ(chosen.name(), "sm1_first");

  EXPECT_EQ(effect.select().name(), "sm2") << "a select() without caps is for this device again";
  EXPECT_TRUE(effect.techniques()[0].caps_reason.empty());
  fxkit::Criteria unknown;
  unknown.caps = "dx5";
  EXPECT_EQ(effect.select(unknown).name(), "sm2");
  EXPECT_NE(text(effect.messages()).find("selecting for this device"), std::string::npos) << text(effect.messages());
  EXPECT_EQ(fxkit::caps_profiles().front(), "dx6");
}

// A colour with no default draws black until set_preview_defaults gives it a stand-in;
// parameters with defaults keep them.
// A GLSL effect draws through a device whose vertex layout names mesh semantics (POSITION,
// NORMAL, ...): its inputs (inPosition, inTexCoord, ...) have no semantics and read the
// attribute their names suggest, as fxkit render reads them. (It drew nothing in fxkit-view:
// vk-vertex-attribute-missing for every input.)
TEST_F(PublicApiTest, AGlslEffectsInputsReadTheMeshAttributesTheirNamesSuggest) {
  Rig r = rig(options(), 64);
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(std::string(FXKIT_SOURCE_DIR) + "/effects/aniso_highlights_glsl.fx");
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fxkit::Technique technique = effect.technique("aniso_blinn_phong");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  const auto centre = draw(*r.device, technique, *r.mesh, *r.image);
  EXPECT_GT(int(centre[0]) + centre[1] + centre[2], 0) << "nothing drawn at the centre";
  EXPECT_EQ(text(effect.messages()), "");
}

// techniques() gives each distance band as `fxkit select` prints it (one formatting function,
// fx::band_text): an open end is -inf or inf, and a technique without a band has none.
TEST_F(PublicApiTest, TechniquesGiveTheirDistanceBandAsSelectPrintsIt) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  const std::string path = write_effect("api_distance_bands.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return float4(1, 1, 1, 1); }
technique near < float MaxDistance = 50.0; > { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
technique far < float MinDistance = 50.0; > { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
technique middle < float LodMin = 2.5; float LodMax = 50.0; > { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
technique any { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  fxkit::Effect effect = r.device->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  const auto listed = effect.techniques();
  ASSERT_EQ(listed.size(), 4u);
  EXPECT_EQ(listed[0].distance_band, "[-inf, 50)");
  EXPECT_EQ(listed[1].distance_band, "[50, inf)");
  EXPECT_EQ(listed[2].distance_band, "[2.5, 50)");
  EXPECT_EQ(listed[3].distance_band, "");
}

TEST_F(PublicApiTest, PreviewDefaultsGiveAColourWithoutADefaultAVisibleValue) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  std::string source = lit_effect();
  const std::string tint = "float4 Tint = {0.9, 0.6, 0.3, 1.0};";
  ASSERT_NE(source.find(tint), std::string::npos);
  source.replace(source.find(tint), tint.size(), "float4 Tint;");
  fxkit::Effect effect = r.device->load(write_effect("api_preview_defaults.fx", source));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fxkit::Technique technique = effect.technique("lit");
  EXPECT_EQ(draw(*r.device, technique, *r.mesh, *r.image)[0], 0) << "no default: black";
  EXPECT_EQ(effect.set_preview_defaults(), std::vector<std::string>{"Tint"});
  EXPECT_GT(draw(*r.device, technique, *r.mesh, *r.image)[0], 40) << "the stand-in grey, lit";
  EXPECT_TRUE(effect.set_preview_defaults().empty()) << "a second call finds nothing left zero";
}

// A per-object matrix held by both passes of one technique and by another
// technique's pass (shared: store_hot logs a change for the other holders), drawn object after
// object with the matrix set before each, techniques mixed within a frame.
TEST_F(PublicApiTest, APerObjectMatrixEveryPassAndTechniqueHoldsDrawsItsObjects) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  const std::string path = write_effect("api_shared_world.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 Tint = {0.9, 0.6, 0.3, 1};
float4 Tint2 = {0.1, 0.2, 0.9, 1};
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return Tint; }
float4 PS2() : COLOR0 { return Tint2; }
technique two { pass p0 { CullMode = None; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); }
                pass p1 { CullMode = None; ZFunc = LessEqual; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS2(); } }
technique one { pass p0 { CullMode = None; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  fxkit::Effect effect = r.device->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  const PerObjectMatrix m = per_object_matrix(effect, r.mesh->radius());
  ASSERT_TRUE(m.ok);
  const fxkit::Param wvp = m.wvp;
  const float* on = m.on;
  const float* off = m.off;
  fxkit::Technique two = effect.technique("two"), one = effect.technique("one");
  ASSERT_TRUE(effect.set_matrix(wvp, on));
  struct Obj {
    fxkit::Technique* t;
    const float* m;
  };
  auto frame = [&](std::vector<Obj> objs) {
    r.device->begin_frame();
    EXPECT_TRUE(r.device->submit([&](VkCommandBuffer cmd) {
      r.image->begin(cmd);
      fxkit::Technique* begun = nullptr;
      for (const Obj& o : objs) {
        if (o.t != begun) {
          if (begun) begun->end();
          begun = o.t;
          EXPECT_TRUE(begun->begin(cmd, r.image->viewport(), r.image->scissor()));
        }
        EXPECT_TRUE(effect.set_matrix(wvp, o.m));
        for (uint32_t p = 0; p < o.t->pass_count(); ++p)
          if (o.t->apply(p)) r.mesh->draw(cmd);
      }
      if (begun) begun->end();
      r.image->end(cmd);
    }));
    return r.centre();
  };
  const auto blue = frame({{&two, on}});
  const auto orange = frame({{&one, on}});
  const auto none = frame({{&two, off}});
  ASSERT_NE(blue, orange);
  ASSERT_NE(blue, none);
  for (int rep = 0; rep < 3; ++rep) {
    EXPECT_EQ(frame({{&two, off}, {&two, on}}), blue) << rep;
    EXPECT_EQ(frame({{&two, on}, {&two, off}}), blue) << rep;
    EXPECT_EQ(frame({{&two, off}, {&two, on}, {&two, off}}), blue) << rep;
    EXPECT_EQ(frame({{&two, off}, {&two, off}, {&two, off}}), none) << rep;
    EXPECT_EQ(frame({{&one, off}, {&two, off}, {&one, on}, {&two, off}}), orange) << rep;
    EXPECT_EQ(frame({{&one, on}, {&two, off}, {&one, off}, {&two, on}}), blue) << rep;
    EXPECT_EQ(frame({{&two, on}, {&one, off}, {&two, off}, {&one, off}}), blue) << rep;
    EXPECT_EQ(frame({{&one, off}, {&one, off}, {&two, off}, {&one, off}}), none) << rep;
  }
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
}

// FX11's Apply binds every shader a pass sets: a pass with a compute shader beside its vertex
// and pixel shaders is dispatched (its compute shader) and applied (its graphics stages). The
// draw reads the buffer the same pass's dispatch wrote; each half has only its own resources.
TEST_F(PublicApiTest, APassWithComputeAndGraphicsShadersIsDispatchedAndApplied) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_compute_beside_graphics.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float Green = 0.5;
RWStructuredBuffer<float4> Colors;
StructuredBuffer<float4> Read;
[numthreads(2, 1, 1)] void Simulate(uint3 id : SV_DispatchThreadID) { Colors[id.x] = float4(0.5 * id.x, 0.25, 1, 1); }
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return float4(Read[1].x, Green, Read[1].z, 1); }
technique11 T { pass P {
  SetVertexShader(CompileShader(vs_5_0, VS()));
  SetPixelShader(CompileShader(ps_5_0, PS()));
  SetComputeShader(CompileShader(cs_5_0, Simulate()));
} }
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fx::DiagnosticSink sink;
  auto buffer = fx::vk::Buffer::create(
      ctx(), {32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, fx::vk::MemoryUsage::readback, "test colours"}, sink);
  ASSERT_TRUE(buffer);
  EXPECT_TRUE(effect.set_buffer("Colors", buffer->handle()));
  EXPECT_TRUE(effect.set_buffer("Read", buffer->handle()));
  fxkit::Technique technique = effect.technique("T");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  EXPECT_TRUE(technique.compute_pass(0));
  EXPECT_TRUE(technique.draw_pass(0));

  r.device->begin_frame();
  bool dispatched = false, drawn = false;
  ASSERT_TRUE(r.device->submit([&](VkCommandBuffer cmd) {
    dispatched = technique.dispatch(cmd, 0, 1);
    r.image->begin(cmd);
    if (technique.begin(cmd, r.image->viewport(), r.image->scissor()) && technique.apply(0))
      r.mesh->draw(cmd), drawn = true;
    technique.end();
    r.image->end(cmd);
  }));
  EXPECT_TRUE(dispatched) << text(effect.messages());
  EXPECT_TRUE(drawn) << text(effect.messages());
  const std::array<uint8_t, 3> centre = r.centre();
  EXPECT_NEAR(centre[0], 128, 1);  // Read[1] = (0.5, 0.25, 1), written by the dispatch
  EXPECT_NEAR(centre[1], 128, 1);  // Green, the pixel shader's uniform
  EXPECT_EQ(centre[2], 255);
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
}

// FX11's "simulate, then draw" through the public API: the application's buffer is bound to
// the compute pass's RWStructuredBuffer and to the draw's StructuredBuffer (one buffer, two
// views, as an engine binds a UAV and an SRV of it); the compute pass is dispatched before
// the rendering and the draw reads what it wrote (the barrier is dispatch()'s).
TEST_F(PublicApiTest, DispatchWritesTheApplicationsBufferThatALaterDrawReads) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_compute.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
RWStructuredBuffer<float4> Written;
StructuredBuffer<float4> Read;
[numthreads(4, 1, 1)] void Simulate(uint3 id : SV_DispatchThreadID) { Written[id.x] = float4(0.25 * id.x, 0.5, 1, 1); }
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return Read[3]; }
technique11 T {
  pass Simulate { SetComputeShader(CompileShader(cs_5_0, Simulate())); }
  pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
}
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fx::DiagnosticSink sink;
  auto buffer = fx::vk::Buffer::create(
      ctx(), {64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, fx::vk::MemoryUsage::readback, "test particles"}, sink);
  ASSERT_TRUE(buffer);
  EXPECT_TRUE(effect.set_buffer("Written", buffer->handle(), 0, 64));
  EXPECT_TRUE(effect.set_buffer("Read", buffer->handle()));
  EXPECT_FALSE(effect.set_buffer("Missing", buffer->handle())) << "no pass uses it";
  fxkit::Technique technique = effect.technique("T");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  EXPECT_TRUE(technique.compute_pass(0));
  EXPECT_FALSE(technique.compute_pass(1));
  EXPECT_FALSE(technique.draw_pass(0));
  EXPECT_TRUE(technique.draw_pass(1));

  r.device->begin_frame();
  bool dispatched = false, refused = false, drawn = false;
  ASSERT_TRUE(r.device->submit([&](VkCommandBuffer cmd) {
    dispatched = technique.dispatch(cmd, 0, 1);
    r.image->begin(cmd);
    if (technique.begin(cmd, r.image->viewport(), r.image->scissor())) {
      refused = !technique.apply(0);
      if (technique.apply(1)) r.mesh->draw(cmd), drawn = true;
    }
    technique.end();
    r.image->end(cmd);
  }));
  EXPECT_TRUE(dispatched) << text(effect.messages());
  EXPECT_TRUE(refused) << "a compute pass is dispatched, not applied";
  EXPECT_TRUE(drawn) << text(effect.messages());
  float written[16] = {};
  ASSERT_TRUE(buffer->read(written, sizeof written));
  EXPECT_FLOAT_EQ(written[4 * 2], 0.5f);
  EXPECT_FLOAT_EQ(written[4 * 3 + 1], 0.5f);
  const std::array<uint8_t, 3> centre = r.centre();
  EXPECT_NEAR(centre[0], 191, 1);  // Read[3] = (0.75, 0.5, 1)
  EXPECT_NEAR(centre[1], 128, 1);
  EXPECT_EQ(centre[2], 255);
}

// A storage image nothing is bound to gets a stand-in the size of the Target's extent (so a
// compute pass with one thread per pixel covers the image), 256 x 256 when it gives none.
TEST_F(PublicApiTest, StorageImageStandInsTakeTheTargetsExtent) {
  for (const auto& [extent, expected] : {std::pair{VkExtent2D{32, 16}, std::array<int, 2>{128, 64}},
                                         std::pair{VkExtent2D{0, 0}, std::array<int, 2>{255, 255}}}) {
    fxkit::DeviceOptions o = options();
    o.target.extent = extent;
    Rig r = rig(o);
    ASSERT_TRUE(r) << text(r.errors);
    fxkit::Effect effect = r.device->load(write_effect("api_storage_extent.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
RWTexture2D<float4> Canvas;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { uint w, h; Canvas.GetDimensions(w, h); return float4(w / 64.0, h / 64.0, 0, 1); }
technique11 T { pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)"));
    ASSERT_TRUE(effect.ok()) << text(effect.messages());
    effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
    fxkit::Technique technique = effect.technique("T");
    const std::array<uint8_t, 3> centre = draw(*r.device, technique, *r.mesh, *r.image);
    EXPECT_NEAR(centre[0], expected[0], 1) << extent.width;
    EXPECT_NEAR(centre[1], expected[1], 1) << extent.height;
  }
}

// An AppendStructuredBuffer and a ConsumeStructuredBuffer on one application buffer and one
// counter (glslang's "name@count" buffer), as FX11 binds one UAV to both: a compute pass
// appends four items, the next consumes two into an RWStructuredBuffer, and the draw shows
// the last item consumed first.
TEST_F(PublicApiTest, AppendedItemsAreConsumedInTheNextPassAndDrawn) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_append_consume.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
AppendStructuredBuffer<float4> Emitted;
ConsumeStructuredBuffer<float4> Pending;
RWStructuredBuffer<float4> Taken;
[numthreads(1, 1, 1)] void Emit() {
  for (uint i = 0; i < 4; ++i) Emitted.Append(float4(0.25 * i, 0.5, 1, 1));
}
[numthreads(1, 1, 1)] void Take() {
  Taken[0] = Pending.Consume();
  Taken[1] = Pending.Consume();
}
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return Taken[0]; }
technique11 T {
  pass Emit { SetComputeShader(CompileShader(cs_5_0, Emit())); }
  pass Take { SetComputeShader(CompileShader(cs_5_0, Take())); }
  pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
}
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fx::DiagnosticSink sink;
  auto items = fx::vk::Buffer::create(
      ctx(), {64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, fx::vk::MemoryUsage::readback, "test items"}, sink);
  auto counter = fx::vk::Buffer::create(
      ctx(), {16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, fx::vk::MemoryUsage::readback, "test item count"}, sink);
  ASSERT_TRUE(items && counter);
  const uint32_t zeros[4] = {};
  ASSERT_TRUE(counter->write(zeros, sizeof zeros));
  EXPECT_TRUE(effect.set_buffer("Emitted", items->handle()));
  EXPECT_TRUE(effect.set_buffer("Emitted@count", counter->handle()));
  EXPECT_TRUE(effect.set_buffer("Pending", items->handle()));
  EXPECT_TRUE(effect.set_buffer("Pending@count", counter->handle()));
  fxkit::Technique technique = effect.technique("T");
  ASSERT_TRUE(technique.valid()) << technique.reason();

  r.device->begin_frame();
  bool dispatched = false, drawn = false;
  ASSERT_TRUE(r.device->submit([&](VkCommandBuffer cmd) {
    dispatched = technique.dispatch(cmd, 0, 1) && technique.dispatch(cmd, 1, 1);
    r.image->begin(cmd);
    if (technique.begin(cmd, r.image->viewport(), r.image->scissor()) && technique.apply(2))
      r.mesh->draw(cmd), drawn = true;
    technique.end();
    r.image->end(cmd);
  }));
  EXPECT_TRUE(dispatched) << text(effect.messages());
  EXPECT_TRUE(drawn) << text(effect.messages());
  uint32_t count = 99;
  ASSERT_TRUE(counter->read(&count, sizeof count));
  EXPECT_EQ(count, 2u) << "four appended, two consumed";
  float appended[16] = {};
  ASSERT_TRUE(items->read(appended, sizeof appended));
  for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(appended[4 * i], 0.25f * float(i));
  const std::array<uint8_t, 3> centre = r.centre();
  EXPECT_NEAR(centre[0], 191, 1);  // the last appended item, (0.75, 0.5, 1), consumed first
  EXPECT_NEAR(centre[1], 128, 1);
  EXPECT_EQ(centre[2], 255);
}

// A tbuffer is a storage buffer: the zeroed stand-in draws black, the application's buffer
// (set_buffer by the tbuffer's name) draws its member.
TEST_F(PublicApiTest, TbufferReadsTheApplicationsBuffer) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_tbuffer.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
tbuffer Lighting { float4 Ambient; float4 Tint; };
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return float4(Tint.rgb, 1); }
technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fxkit::Technique technique = effect.technique("T");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  const auto centre = [&] {
    r.device->begin_frame();
    EXPECT_TRUE(r.device->submit([&](VkCommandBuffer cmd) {
      r.image->begin(cmd);
      if (technique.begin(cmd, r.image->viewport(), r.image->scissor()) && technique.apply(0)) r.mesh->draw(cmd);
      technique.end();
      r.image->end(cmd);
    }));
    return r.centre();
  };
  EXPECT_EQ(centre(), (std::array<uint8_t, 3>{0, 0, 0})) << "the zeroed stand-in" << text(effect.messages());
  fx::DiagnosticSink sink;
  auto lighting = fx::vk::Buffer::create(
      ctx(), {32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, fx::vk::MemoryUsage::upload, "test tbuffer"}, sink);
  ASSERT_TRUE(lighting);
  const float values[8] = {1, 1, 1, 1, 0.25f, 0.5f, 1, 1};
  ASSERT_TRUE(lighting->write(values, sizeof values));
  EXPECT_TRUE(effect.set_buffer("Lighting", lighting->handle()));
  const auto tinted = centre();
  EXPECT_NEAR(tinted[0], 64, 1) << text(effect.messages());
  EXPECT_NEAR(tinted[1], 128, 1);
  EXPECT_EQ(tinted[2], 255);
}

// fx_5_0 class linkage: a pixel shader calls through an interface parameter bound in the pass
// to an interface variable; the application binds that variable to one class instance, then
// to another, and the draw runs each class (one with member data the application set, one
// without), with no recompile between them.
TEST_F(PublicApiTest, SetClassInstanceSwitchesTheClassAnInterfaceCallRuns) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_class_linkage.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
interface iColour { float3 Colour(); };
class cSolid : iColour { float3 colour; float3 Colour() { return colour; } };
class cGreen : iColour { float3 Colour() { return float3(0, 1, 0); } };
iColour g_colour;
cGreen g_green;
cSolid g_solid;
struct V { float4 pos : SV_Position; };
V VS(float4 p : POSITION) { V o; o.pos = mul(p, WorldViewProjection); return o; }
float4 PS(V i, iColour colour) : SV_Target { return float4(colour.Colour(), 1); }
technique11 T {
  pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), g_colour)); }
}
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  const std::vector<fxkit::ParamInfo> params = effect.params();
  auto colour = std::find_if(params.begin(), params.end(), [](const auto& p) { return p.name == "g_colour"; });
  ASSERT_NE(colour, params.end());
  EXPECT_EQ(colour->class_instances, (std::vector<std::string>{"g_green", "g_solid"}));
  EXPECT_EQ(colour->scalar, fxkit::ScalarKind::int32);

  fxkit::Technique technique = effect.technique("T");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  const fxkit::Param g_colour = effect.param("g_colour");
  ASSERT_TRUE(effect.set(effect.param("g_solid"), {0.0f, 0.0f, 1.0f}));
  ASSERT_TRUE(effect.set_class_instance(g_colour, "g_solid"));
  const auto blue = draw(*r.device, technique, *r.mesh, *r.image);
  EXPECT_EQ(blue, (std::array<uint8_t, 3>{0, 0, 255})) << "cSolid's colour member, set by the application";
  ASSERT_TRUE(effect.set_class_instance(g_colour, "g_green"));
  const auto green = draw(*r.device, technique, *r.mesh, *r.image);
  EXPECT_EQ(green, (std::array<uint8_t, 3>{0, 255, 0})) << "cGreen's method";
  EXPECT_FALSE(effect.set_class_instance(g_colour, "g_nothing"));
  EXPECT_NE(text(effect.messages()).find("'g_nothing' is not a class instance"), std::string::npos)
      << text(effect.messages());
}

// Classes derived from classes (the DirectX SDK's DynamicShaderLinkage sample: `class
// cHemiAmbientLight : cAmbientLight`), instances in a constant buffer: an instance holds its
// base's members first; a call reaches the class's override, else the method it inherits.
TEST_F(PublicApiTest, ADerivedClassInheritsMembersAndTheMethodsItDoesNotOverride) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_class_inheritance.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
interface iLight { float3 Ambient(); float3 Direct(); };
class cAmbient : iLight { float3 colour; float3 Ambient() { return colour; } float3 Direct() { return 0; } };
class cHemi : cAmbient { float3 ground; float3 Ambient(); };
class cSun : cAmbient { float3 Direct() { return colour * 0.5; } };
float3 cHemi::Ambient() { return colour + ground; }
cbuffer Lights { cAmbient g_ambient; cHemi g_hemi; cSun g_sun; };
iLight g_light;
struct V { float4 pos : SV_Position; };
V VS(float4 p : POSITION) { V o; o.pos = mul(p, WorldViewProjection); return o; }
float4 PS(V i, iLight light) : SV_Target { return float4(light.Ambient() + light.Direct(), 1); }
technique11 T {
  pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), g_light)); }
}
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fxkit::Technique technique = effect.technique("T");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  const fxkit::Param light = effect.param("g_light");
  ASSERT_TRUE(effect.set(effect.param("g_hemi"), {0.5f, 0.0f, 0.0f, 0.0f, 0.5f, 0.0f}));  // colour, then ground
  ASSERT_TRUE(effect.set(effect.param("g_sun"), {0.0f, 0.4f, 0.0f}));
  ASSERT_TRUE(effect.set_class_instance(light, "g_hemi"));
  EXPECT_EQ(draw(*r.device, technique, *r.mesh, *r.image), (std::array<uint8_t, 3>{128, 128, 0}))
      << "cHemi's Ambient (its base's colour and its ground), cAmbient's Direct (0)";
  ASSERT_TRUE(effect.set_class_instance(light, "g_sun"));
  EXPECT_EQ(draw(*r.device, technique, *r.mesh, *r.image), (std::array<uint8_t, 3>{0, 153, 0}))
      << "cAmbient's Ambient (0.4) and cSun's Direct (0.2)";
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
}

// A method defined outside its class, after the constant buffer that holds the instances and a
// global it reads (the DirectX SDK's DynamicShaderLinkage sample reads `g_vEyeDir` so): fxc
// reads it where it is defined, so it sees that global; it calls a method of its class, and a
// derived class inherits it with its own members.
TEST_F(PublicApiTest, AMethodDefinedAfterItsClassSeesTheGlobalsDeclaredBeforeIt) {
  Rig r = rig();
  ASSERT_TRUE(r) << text(r.errors);
  fxkit::Effect effect = r.device->load(write_effect("api_class_method_after.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
interface iLight { float3 Ambient(); };
class cAmbient : iLight { float3 colour; float3 Ambient(); float3 Scaled(float k) { return colour * k; } };
class cHemi : cAmbient { float3 ground; };
cbuffer Lights { cAmbient g_ambient; cHemi g_hemi; float3 g_boost; };
iLight g_light;
float3 cAmbient::Ambient() { float3 half = Scaled(0.5); return half + g_boost; }
struct V { float4 pos : SV_Position; };
V VS(float4 p : POSITION) { V o; o.pos = mul(p, WorldViewProjection); return o; }
float4 PS(V i, iLight light) : SV_Target { return float4(light.Ambient(), 1); }
technique11 T {
  pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), g_light)); }
}
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(r.mesh->radius(), 1.0f));
  fxkit::Technique technique = effect.technique("T");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  const fxkit::Param light = effect.param("g_light");
  ASSERT_TRUE(effect.set(effect.param("g_ambient"), {1.0f, 0.0f, 0.0f}));
  ASSERT_TRUE(effect.set(effect.param("g_hemi"), {0.0f, 1.0f, 0.0f, 1.0f, 1.0f, 1.0f}));  // colour, then ground
  ASSERT_TRUE(effect.set(effect.param("g_boost"), {0.0f, 0.0f, 0.25f}));
  ASSERT_TRUE(effect.set_class_instance(light, "g_ambient"));
  EXPECT_EQ(draw(*r.device, technique, *r.mesh, *r.image), (std::array<uint8_t, 3>{128, 0, 64}))
      << "half of cAmbient's colour, plus the global";
  ASSERT_TRUE(effect.set_class_instance(light, "g_hemi"));
  EXPECT_EQ(draw(*r.device, technique, *r.mesh, *r.image), (std::array<uint8_t, 3>{0, 128, 64}))
      << "the inherited method on cHemi's own colour";
  EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
}

}  // namespace
}  // namespace fx::vk::testing
