// DXSAS scripts run by ScriptRunner on the validated device: a post effect draws its scene
// into a render target, blurs it into a second with Draw=Buffer and composites the blur into
// the frame; the frame differs from the unprocessed scene the way a blur does.
#include <gtest/gtest.h>

#include "effect_folder.h"
#include "effect_test_util.h"
#include "fx/binding/script_runner.h"

namespace fx::vk::testing {
namespace {

constexpr const char* kPostEffect = R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 ClearColor = {0, 0, 0, 1};
float ClearDepth = 1.0;
float Script : STANDARDSGLOBAL < string ScriptClass = "scene"; string ScriptOrder = "postprocess"; string ScriptOutput = "color"; > = 0.8;
texture ScnMap : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; string Format = "A8R8G8B8"; >;
texture BlurMap : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; >;
texture DepthBuffer : RENDERDEPTHSTENCILTARGET < float2 ViewportRatio = {1, 1}; >;
sampler ScnSamp = sampler_state { Texture = <ScnMap>; MinFilter = POINT; MagFilter = POINT; AddressU = CLAMP; AddressV = CLAMP; };
sampler BlurSamp = sampler_state { Texture = <BlurMap>; MinFilter = POINT; MagFilter = POINT; AddressU = CLAMP; AddressV = CLAMP; };
struct QuadOut { float4 p : POSITION; float2 uv : TEXCOORD0; };
QuadOut QuadVS(float4 p : POSITION, float2 uv : TEXCOORD0) { QuadOut o; o.p = float4(p.xy, 0, 1); o.uv = uv; return o; }
float4 SceneVS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 ScenePS() : COLOR0 { return float4(1, 1, 1, 1); }
float4 BlurPS(float2 uv : TEXCOORD0) : COLOR0 {
  float4 sum = 0;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y) sum += tex2D(ScnSamp, uv + float2(x, y) / 64.0);
  return sum / 49.0;
}
float4 CompositePS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(BlurSamp, uv); }
technique Plain { pass Scene { VertexShader = compile vs_3_0 SceneVS(); PixelShader = compile ps_3_0 ScenePS(); } }
technique Post < string Script = "RenderColorTarget0=ScnMap; RenderDepthStencilTarget=DepthBuffer; ClearSetColor=ClearColor; ClearSetDepth=ClearDepth; Clear=Color; Clear=Depth; Pass=Scene; RenderColorTarget0=BlurMap; Pass=Blur; RenderColorTarget0=; RenderDepthStencilTarget=; Pass=Composite;"; > {
  pass Scene < string Script = "Draw=Geometry;"; > { VertexShader = compile vs_3_0 SceneVS(); PixelShader = compile ps_3_0 ScenePS(); }
  pass Blur < string Script = "Draw=Buffer;"; > { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 BlurPS(); }
  pass Composite < string Script = "Draw=Buffer;"; > { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 CompositePS(); }
}
)";

class ScriptRenderTest : public VulkanTest {};

TEST_F(ScriptRenderTest, PostEffectBlursTheSceneItDrewIntoATarget) {
  fx::testing::EffectFolder folder("script_post");
  folder.write("post.fx", kPostEffect);
  constexpr uint32_t kSize = 64;
  auto plain = bind_effect(ctx(), folder.path("post.fx"), "Plain", "sphere", kSize);
  ASSERT_TRUE(plain);
  auto scene = plain->render();
  ASSERT_TRUE(scene);

  auto post = bind_effect(ctx(), folder.path("post.fx"), "Post", "sphere", kSize);
  ASSERT_TRUE(post);
  DiagnosticSink sink;
  auto runner = ScriptRunner::create(ctx(), *post->effect->model, *post->binding, *post->effect->params,
                                     post->technique, kSize, kSize, sink);
  ASSERT_TRUE(runner) << describe(sink);
  ASSERT_TRUE(runner->target("ScnMap"));
  EXPECT_EQ(runner->target("BlurMap")->width(), kSize);
  set_standard_semantics(*post->effect->params, *post->effect->model, post->preview->scene());
  auto image = post->preview->render_script(*runner, post->layout, sink);
  ASSERT_TRUE(image) << describe(sink);
  EXPECT_FALSE(sink.has_errors()) << describe(sink);

  // The unprocessed scene: a white sphere on the preview's dark clear colour.
  const uint32_t y = kSize / 2;
  EXPECT_EQ(scene->at(kSize / 2, y)[0], 255);
  EXPECT_EQ(image->at(kSize / 2, y)[0], 255) << "the blur of white is white";
  uint32_t edge = 0;  // the first white pixel of the middle row
  while (edge < kSize && scene->at(edge, y)[0] < 250) ++edge;
  ASSERT_GT(edge, 3u);
  ASSERT_LT(edge, kSize / 2);
  // Outside the silhouette the blur spreads light: brighter than the unprocessed background.
  EXPECT_GT(image->at(edge - 1, y)[0], scene->at(edge - 1, y)[0] + 40);
  // Inside, next to the edge, it spreads the black: darker than the unprocessed white.
  EXPECT_LT(image->at(edge + 1, y)[0], 235);
  // Every value of the blurred frame lies between black and white, smoothly: no pixel jumps by
  // more than a 7-texel box filter allows across the edge.
  for (uint32_t x = 1; x < kSize; ++x)
    EXPECT_LE(std::abs(int(image->at(x, y)[0]) - int(image->at(x - 1, y)[0])), 255 / 7 + 8) << x;
}

// A post effect of the FX Composer kind: the host's scene (ScriptExternal) into a target, then
// a filter of it on a full-screen quad.
constexpr const char* kExternalEffect = R"(float4 ClearColor = {0, 0, 0, 1};
float Script : STANDARDSGLOBAL < string ScriptClass = "scene"; string ScriptOrder = "postprocess"; string ScriptOutput = "color"; > = 0.8;
texture ScnMap : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; >;
sampler ScnSamp = sampler_state { Texture = <ScnMap>; MinFilter = POINT; MagFilter = POINT; AddressU = CLAMP; AddressV = CLAMP; };
struct QuadOut { float4 p : POSITION; float2 uv : TEXCOORD0; };
QuadOut QuadVS(float4 p : POSITION, float2 uv : TEXCOORD0) { QuadOut o; o.p = float4(p.xy, 0, 1); o.uv = uv; return o; }
float4 ShowPS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(ScnSamp, uv); }
float4 InvertPS(float2 uv : TEXCOORD0) : COLOR0 { return float4(1 - tex2D(ScnSamp, uv).rgb, 1); }
technique Show < string Script = "RenderColorTarget0=ScnMap; ClearSetColor=ClearColor; Clear=Color; Clear=Depth; ScriptExternal=color; RenderColorTarget0=; Pass=P;"; > {
  pass P < string Script = "Draw=Buffer;"; > { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 ShowPS(); }
}
technique Invert < string Script = "RenderColorTarget0=ScnMap; ClearSetColor=ClearColor; Clear=Color; Clear=Depth; ScriptExternal=color; RenderColorTarget0=; Pass=P;"; > {
  pass P < string Script = "Draw=Buffer;"; > { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 InvertPS(); }
}
)";

// The frame `technique` of kExternalEffect draws, with the preview's stand-ins.
std::optional<fx::Image> render_external(Context& ctx, const std::string& path, const std::string& technique,
                                         uint32_t size) {
  auto e = bind_effect(ctx, path, technique, "sphere", size, std::nullopt, VK_FORMAT_R8G8B8A8_UNORM, true);
  if (!e) return std::nullopt;
  DiagnosticSink sink;
  auto runner =
      ScriptRunner::create(ctx, *e->effect->model, *e->binding, *e->effect->params, e->technique, size, size, sink);
  EXPECT_TRUE(runner) << describe(sink);
  if (!runner) return std::nullopt;
  EXPECT_TRUE(runner->draws_scene());
  set_standard_semantics(*e->effect->params, *e->effect->model, e->preview->scene());
  auto image = e->preview->render_script(*runner, e->layout, sink);
  EXPECT_TRUE(image) << describe(sink);
  EXPECT_FALSE(sink.has_errors()) << describe(sink);
  return image;
}

// ScriptExternal in a preview draws its test scene: a lit, patterned sphere on the clear
// colour, which the post effect then processes.
TEST_F(ScriptRenderTest, ScriptExternalDrawsTheTestSceneThePostEffectProcesses) {
  fx::testing::EffectFolder folder("script_external");
  folder.write("external.fx", kExternalEffect);
  constexpr uint32_t kSize = 48;
  auto shown = render_external(ctx(), folder.path("external.fx"), "Show", kSize);
  auto inverted = render_external(ctx(), folder.path("external.fx"), "Invert", kSize);
  ASSERT_TRUE(shown && inverted);
  // The scene: the clear colour in the corner, an object in many colours in the middle.
  EXPECT_EQ(shown->at(0, 0)[0], 0);
  const uint8_t background[4] = {0, 0, 0, 255};
  EXPECT_FALSE(shown->flat_over(background, 2)) << "the scene's object is not one flat colour";
  uint32_t drawn = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) drawn += shown->at(x, y)[0] + shown->at(x, y)[1] + shown->at(x, y)[2] > 0;
  EXPECT_GT(drawn, kSize * kSize / 4) << "the sphere fills the middle";
  // The post effect inverts every pixel of it.
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(int(inverted->at(x, y)[c]), 255 - int(shown->at(x, y)[c]), 1) << x << "," << y << " channel " << c;
}

// Multiple render targets (RenderColorTarget1): a geometry pass writes COLOR0 into one target
// and COLOR1 into another, after a Clear that clears both, as Direct3D 9 clears every bound
// target; a composite reads both into the frame.
constexpr const char* kMrtEffect = R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 ClearColor = {0, 0, 1, 1};
texture Albedo : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; >;
texture Normals : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; >;
sampler AlbedoSamp = sampler_state { Texture = <Albedo>; MinFilter = POINT; MagFilter = POINT; };
sampler NormalSamp = sampler_state { Texture = <Normals>; MinFilter = POINT; MagFilter = POINT; };
struct Targets { float4 albedo : COLOR0; float4 normal : COLOR1; };
float4 SceneVS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
Targets GBufferPS() { Targets t; t.albedo = float4(1, 0, 0, 1); t.normal = float4(0, 1, 0, 1); return t; }
struct QuadOut { float4 p : POSITION; float2 uv : TEXCOORD0; };
QuadOut QuadVS(float4 p : POSITION, float2 uv : TEXCOORD0) { QuadOut o; o.p = float4(p.xy, 0, 1); o.uv = uv; return o; }
float4 CompositePS(float2 uv : TEXCOORD0) : COLOR0 {
  float4 a = tex2D(AlbedoSamp, uv), n = tex2D(NormalSamp, uv);
  return float4(a.r, n.g, a.b * n.b, 1);
}
technique Deferred < string Script = "RenderColorTarget0=Albedo; RenderColorTarget1=Normals; ClearSetColor=ClearColor; Clear=Color; Clear=Depth; Pass=GBuffer; RenderColorTarget1=; RenderColorTarget0=; Pass=Composite;"; > {
  pass GBuffer < string Script = "Draw=Geometry;"; > { VertexShader = compile vs_3_0 SceneVS(); PixelShader = compile ps_3_0 GBufferPS(); }
  pass Composite < string Script = "Draw=Buffer;"; > { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 CompositePS(); }
}
)";

TEST_F(ScriptRenderTest, RenderColorTarget1TakesTheSecondOutputAndIsCleared) {
  fx::testing::EffectFolder folder("script_mrt");
  folder.write("mrt.fx", kMrtEffect);
  constexpr uint32_t kSize = 32;
  auto e = bind_effect(ctx(), folder.path("mrt.fx"), "Deferred", "sphere", kSize);
  ASSERT_TRUE(e);
  DiagnosticSink sink;
  auto runner =
      ScriptRunner::create(ctx(), *e->effect->model, *e->binding, *e->effect->params, e->technique, kSize, kSize, sink);
  ASSERT_TRUE(runner) << describe(sink);
  ASSERT_TRUE(runner->target("Normals"));
  set_standard_semantics(*e->effect->params, *e->effect->model, e->preview->scene());
  const size_t errors = ctx().validation_error_count();
  auto image = e->preview->render_script(*runner, e->layout, sink);
  ASSERT_TRUE(image) << describe(sink);
  EXPECT_FALSE(sink.has_errors()) << describe(sink);
  EXPECT_EQ(ctx().validation_error_count(), errors) << describe_messages(ctx());
  const uint8_t* centre = image->at(kSize / 2, kSize / 2);
  EXPECT_EQ(centre[0], 255);  // COLOR0 went into Albedo
  EXPECT_EQ(centre[1], 255);  // COLOR1 into Normals
  EXPECT_EQ(centre[2], 0);
  const uint8_t* corner = image->at(0, 0);
  EXPECT_EQ(corner[0], 0);
  EXPECT_EQ(corner[1], 0);
  EXPECT_EQ(corner[2], 255);  // both targets cleared blue
}

// A technique without a Script gets no runner, and says so.
TEST_F(ScriptRenderTest, TechniqueWithoutScriptHasNoRunner) {
  fx::testing::EffectFolder folder("script_none");
  folder.write("post.fx", kPostEffect);
  auto plain = bind_effect(ctx(), folder.path("post.fx"), "Plain", "sphere", 16);
  ASSERT_TRUE(plain);
  DiagnosticSink sink;
  EXPECT_FALSE(ScriptRunner::create(ctx(), *plain->effect->model, *plain->binding, *plain->effect->params,
                                    plain->technique, 16, 16, sink));
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-script-none");
}

}  // namespace
}  // namespace fx::vk::testing
