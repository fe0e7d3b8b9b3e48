// Technique::run_script: a technique's DXSAS Script run through the public API into an image
// the application owns, on a validated device.
#include <gtest/gtest.h>

#include <array>

#include "../vulkan/effect_test_util.h"
#include "fxkit/fxkit.h"

namespace fx::vk::testing {
namespace {

// A post effect: the scene (the application's mesh, red above the middle of the frame and green
// below: clip-space y)
// into ScnMap on blue, then a pass that inverts ScnMap with Draw=Buffer into the frame.
constexpr const char* kInvertScene = R"(
float Script : STANDARDSGLOBAL < string ScriptClass = "scene"; string ScriptOrder = "postprocess";
                                 string ScriptOutput = "color"; > = 0.8;
float4 ClearColor = {0, 0, 1, 1};
texture ScnMap : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; string Format = "A8R8G8B8"; >;
sampler ScnSamp = sampler_state { Texture = <ScnMap>; MinFilter = POINT; MagFilter = POINT; AddressU = CLAMP; AddressV = CLAMP; };
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct S { float4 pos : POSITION; float height : TEXCOORD0; };
S SceneVS(float4 p : POSITION) { S o; o.pos = mul(p, WorldViewProjection); o.height = o.pos.y; return o; }
float4 ScenePS(S i) : COLOR0 { return i.height > 0 ? float4(1, 0, 0, 1) : float4(0, 1, 0, 1); }
struct Q { float4 pos : POSITION; float2 uv : TEXCOORD0; };
Q QuadVS(float4 p : POSITION, float2 uv : TEXCOORD0) { Q o; o.pos = p; o.uv = uv; return o; }
float4 InvertPS(float2 uv : TEXCOORD0) : COLOR0 { return float4(1 - tex2D(ScnSamp, uv).rgb, 1); }
technique Post < string Script = "RenderColorTarget0=ScnMap; ClearSetColor=ClearColor; Clear=Color; Clear=Depth;"
                                 "Pass=Scene; RenderColorTarget0=; Pass=Invert;"; > {
  pass Scene < string Script = "Draw=Geometry;"; > { CullMode = None; VertexShader = compile vs_3_0 SceneVS(); PixelShader = compile ps_3_0 ScenePS(); }
  pass Invert < string Script = "Draw=Buffer;"; > { CullMode = None; ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 InvertPS(); }
}
technique Plain { pass P { VertexShader = compile vs_3_0 SceneVS(); PixelShader = compile ps_3_0 ScenePS(); } }
)";

std::string text(const std::vector<fxkit::Message>& messages) {
  std::string s;
  for (const auto& m : messages) s += m.rendered;
  return s;
}

class ScriptApiTest : public VulkanTest {};

TEST_F(ScriptApiTest, RunScriptDrawsThePostEffectIntoTheApplicationsImage) {
  fxkit::DeviceOptions o;
  o.target = {.formats = {.color = {VK_FORMAT_R8G8B8A8_UNORM}, .depth = VK_FORMAT_D32_SFLOAT},
              .vertex_layout = fxkit::Mesh::vertex_layout(),
              .front_faces = fxkit::Winding::counter_clockwise,
              .y_flip = fxkit::YFlip::negative_viewport};
  std::vector<fxkit::Message> errors;
  auto device = fxkit::Device::create(
      {ctx().instance(), ctx().physical_device(), ctx().device(), ctx().queue(), ctx().queue_family()}, o, errors);
  ASSERT_TRUE(device) << text(errors);
  auto mesh = fxkit::Mesh::create(*device, "sphere", errors);
  ASSERT_TRUE(mesh) << text(errors);
  // The application's own image and depth, as a swapchain's would be.
  DiagnosticSink sink;
  constexpr uint32_t kSize = 32;
  auto frame = RenderTarget::create(ctx(), {kSize, kSize, VK_FORMAT_R8G8B8A8_UNORM, DepthAttachment::d32}, sink);
  ASSERT_TRUE(frame) << describe(sink);

  fxkit::Effect effect = device->load(write_effect("api_script.fx", kInvertScene));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  effect.set_scene(fxkit::Scene::framing(mesh->radius(), 1.0f));
  fxkit::Technique post = effect.technique("Post");
  EXPECT_TRUE(post.has_script());
  EXPECT_FALSE(effect.technique("Plain").has_script());

  device->begin_frame();
  bool ran = false;
  ASSERT_TRUE(device->submit([&](VkCommandBuffer cmd) {
    frame->begin(cmd);  // the application's frame, in attachment layouts, outside rendering
    frame->end(cmd);
    fxkit::ScriptFrame script;
    script.color = frame->color().view();
    script.depth = frame->depth()->view();
    script.area = frame->scissor();
    script.draw_geometry = [&](VkCommandBuffer c) { mesh->draw(c); };
    ran = post.run_script(cmd, script);
    frame->record_readback(cmd);
  }));
  ASSERT_TRUE(ran) << text(effect.messages());
  auto image = frame->readback_pixels(sink);
  ASSERT_TRUE(image) << describe(sink);
  auto rgb = [&](uint32_t x, uint32_t y) {
    const uint8_t* p = &image->pixels[(size_t(y) * image->width + x) * 4];
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  // Blue around the sphere inverted to yellow; its upper half red, inverted to cyan, on top.
  EXPECT_EQ(rgb(0, 0), (std::array<int, 3>{255, 255, 0}));
  EXPECT_EQ(rgb(kSize / 2, kSize / 2 - kSize / 8), (std::array<int, 3>{0, 255, 255}));
  EXPECT_EQ(rgb(kSize / 2, kSize / 2 + kSize / 8), (std::array<int, 3>{255, 0, 255}));

  const std::vector<fxkit::ScriptTarget> targets = post.script_targets();
  ASSERT_EQ(targets.size(), 1u);
  EXPECT_EQ(targets[0].name, "ScnMap");
  EXPECT_EQ(targets[0].extent.width, kSize);
  EXPECT_NE(targets[0].view, VK_NULL_HANDLE);

  // A technique without a script says so in messages().
  fxkit::Technique plain = effect.technique("Plain");
  EXPECT_TRUE(device->submit([&](VkCommandBuffer cmd) { EXPECT_FALSE(plain.run_script(cmd, {})); }));
  EXPECT_NE(text(effect.messages()).find("vk-script-none"), std::string::npos) << text(effect.messages());
}

}  // namespace
}  // namespace fx::vk::testing
