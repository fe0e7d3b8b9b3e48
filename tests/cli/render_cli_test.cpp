// `fxkit render` of effects written for an engine, with nothing set up: the stand-ins
// (bone palettes, colours, light direction and count), SV_Position as a vertex input, and
// the warnings for an image or an object of one flat colour, texture stand-ins that show a
// filter, a post effect run on the preview's test scene, and what a technique that only
// computes wrote.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>

#include "fx/image.h"
#include "fxkit_cli.h"

namespace {

// `fxkit render` of `source` (written as NAME.fx) with `options`, into NAME.png, and the PNG
// it wrote (empty when it wrote none).
struct Rendered {
  fx::testing::CliRun run;
  std::optional<fx::Image> image;
};
Rendered render(const std::string& name, const std::string& source, const std::string& options) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / ("fxkit_render_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / (name + ".fx"), png = dir / (name + ".png");
  std::ofstream(file) << source;
  Rendered r;
  r.run = fx::testing::run_fxkit("render " + file.string() + " " + options + " --out " + png.string(), true);
  fx::DiagnosticSink sink;
  if (r.run.status == 0) r.image = fx::read_png(png, sink, 4);
  return r;
}

// An XNA-style skinned, lit effect: nothing but WorldViewProj has a value a preview knows.
constexpr const char* kSkinned = R"(
float4x4 WorldViewProj;
float4x3 Bones[8];
float4 DiffuseColor;
float3 LightDirection;
int LightCount;
struct VSIn { float4 Position : SV_Position; float3 Normal : NORMAL;
              int4 Indices : BLENDINDICES0; float4 Weights : BLENDWEIGHT0; };
struct VSOut { float4 Position : SV_Position; float4 Color : COLOR0; };
VSOut VS(VSIn vin) {
  float4x3 skin = Bones[vin.Indices.x] * vin.Weights.x + Bones[vin.Indices.y] * vin.Weights.y;
  VSOut o;
  o.Position = mul(float4(mul(vin.Position, skin), 1), WorldViewProj);
  float3 n = normalize(mul(vin.Normal, (float3x3)skin));
  float lit = 0;
  for (int i = 0; i < LightCount; ++i) lit += saturate(dot(n, -LightDirection));
  o.Color = float4(DiffuseColor.rgb * (0.2 + lit), DiffuseColor.a);
  return o;
}
float4 PS(float4 c : COLOR0) : COLOR0 { return c; }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

TEST(FxkitRender, AnEngineEffectDrawsWithStandInsAndSaysWhichItGave) {
  const auto [r, image] = render("skinned", kSkinned, "--verbose --validation");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line : {"Bones <- identity bone palette (stand-in)", "DiffuseColor <- visible colour (stand-in)",
                           "LightDirection <- light direction (stand-in)", "LightCount <- light count (stand-in)"})
    EXPECT_NE(r.err.find(line), std::string::npos) << line << "\n" << r.err;
  EXPECT_EQ(r.err.find("image is constant"), std::string::npos) << r.err;
  ASSERT_TRUE(image);
  EXPECT_FALSE(image->constant());
  // The lit sphere: its centre is the stand-in grey times (0.2 + a light), not black.
  const uint8_t* centre = image->at(image->width / 2, image->height / 2);
  EXPECT_GT(centre[0], 60);
}

// An XNA-style vertex-colour variant (BasicEffect_VertexLighting_VertexColor): the lit colour
// times the vertex COLOR. The preview's mesh has no vertex colours; COLOR reads white, so the
// variant shows the lit material as its variant without vertex colours does, not black.
TEST(FxkitRender, VertexColourReadsWhiteOnThePreviewMesh) {
  const auto [r, image] = render("vertex_colour", R"(
float4x4 WorldViewProj;
float4 DiffuseColor;
float3 LightDirection;
struct VSOut { float4 Position : POSITION; float4 Color : COLOR0; };
VSOut VS(float4 p : POSITION, float3 n : NORMAL, float4 c : COLOR) {
  VSOut o;
  o.Position = mul(p, WorldViewProj);
  o.Color = DiffuseColor * (0.2 + saturate(dot(n, -LightDirection))) * c;
  return o;
}
float4 PS(float4 c : COLOR0) : COLOR0 { return c; }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)",
                                 "--validation");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("one flat colour"), std::string::npos) << r.err;
  ASSERT_TRUE(image);
  const uint8_t* centre = image->at(image->width / 2, image->height / 2);
  EXPECT_GT(centre[0], 60);
  EXPECT_EQ(centre[0], centre[2]);  // the stand-in grey, untinted: white vertex colours
}

// Rule files whose techniques only a draw shows wrong (Vulkan's validation layers name them):
// an array varying whose elements the vertex stage writes one by one (TEXCOORD1..3), also
// the fixed-function one of a pass that sets only a pixel shader, and a Buffer<float3> whose
// stand-in a texel buffer of three 32-bit components cannot be.
TEST(FxkitRender, ArrayVaryingsAndThreeComponentBuffersDrawCleanly) {
  const std::string rules = std::string(FXKIT_SOURCE_DIR) + "/tests/compile/data/fxc_accepts/";
  const auto dir = std::filesystem::path(::testing::TempDir());
  for (const auto& [file, technique] : {std::pair{"texcoord_array_varyings.fx", "WithVertexShader"},
                                        std::pair{"texcoord_array_varyings.fx", "PixelShaderOnly"},
                                        std::pair{"read_only_buffer_of_three_components.fx", "Render"}}) {
    const fx::testing::CliRun run =
        fx::testing::run_fxkit(std::string("render ") + rules + file + " --technique " + technique +
                                   " --validation --size 32x32 --out " + (dir / "array_varyings.png").string(),
                               true);
    EXPECT_EQ(run.status, 0) << file << " " << technique << "\n" << run.err;
  }
}

// A DirectX SDK-style lit effect (BasicHLSL's names): g_LightDir is the direction towards the
// light, an array of them one per light, and no value has a default. The stand-ins follow
// that convention, so the side of the sphere facing the camera is lit, not black.
TEST(FxkitRender, SdkLightDirectionPointsTowardsTheLight) {
  const auto [r, image] = render("sdk_lit", R"(
float4x4 g_mWorldViewProjection;
float4x4 g_mWorld;
float3 g_LightDir[2];
float4 g_LightDiffuse[2];
int g_nNumLights;
texture g_MeshTexture;
sampler MeshTextureSampler = sampler_state { Texture = <g_MeshTexture>; };
struct VSOut { float4 Position : POSITION; float4 Diffuse : COLOR0; };
VSOut VS(float4 p : POSITION, float3 n : NORMAL) {
  VSOut o;
  o.Position = mul(p, g_mWorldViewProjection);
  float3 normal = normalize(mul(n, (float3x3)g_mWorld));
  float3 lit = 0;
  for (int i = 0; i < g_nNumLights; ++i) lit += g_LightDiffuse[i].rgb * max(0, dot(normal, g_LightDir[i]));
  o.Diffuse = float4(lit, 1);
  return o;
}
float4 PS(float4 c : COLOR0) : COLOR0 { return c * tex2D(MeshTextureSampler, float2(0.5, 0.5)); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                                 "--verbose --validation");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line : {"g_LightDir <- direction to the light (stand-in)",
                           "g_MeshTexture <- colour test pattern (stand-in: no ResourceName)",
                           "g_LightDiffuse <- visible colour (stand-in)", "g_nNumLights <- light count (stand-in)"})
    EXPECT_NE(r.err.find(line), std::string::npos) << line << "\n" << r.err;
  ASSERT_TRUE(image);
  const uint8_t* centre = image->at(image->width / 2, image->height / 2);
  EXPECT_GT(std::max({centre[0], centre[1], centre[2]}), 100) << "the side facing the camera is lit";
}

// An engine's space-to-space names (Kodu's LocalToModel, WorldToCamera): the transforms
// between scene spaces are bound by their names, one within object space is the identity.
TEST(FxkitRender, SpaceToSpaceTransformsAreBoundByTheirNames) {
  const auto [r, image] = render("spaces", R"(
float4x4 LocalToModel;
float4x4 ModelToWorld;
float4x4 WorldToCamera;
float4x4 CameraToClip;
float4 VS(float4 p : POSITION) : POSITION {
  return mul(mul(mul(mul(p, LocalToModel), ModelToWorld), WorldToCamera), CameraToClip);
}
float4 PS() : COLOR0 { return float4(1, 0.5, 0, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                                 "--verbose --validation");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line :
       {"LocalToModel <- identity object-space transform (stand-in)", "ModelToWorld <- WORLD (by its name)",
        "WorldToCamera <- VIEW (by its name)", "CameraToClip <- PROJECTION (by its name)"})
    EXPECT_NE(r.err.find(line), std::string::npos) << line << "\n" << r.err;
  ASSERT_TRUE(image);
  EXPECT_FALSE(image->constant());
}

TEST(FxkitRender, ParamOverridesAStandIn) {
  const auto [r, image] = render("skinned_param", kSkinned, "--param DiffuseColor=0,0,0,1");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(image);
  const uint8_t* centre = image->at(image->width / 2, image->height / 2);
  EXPECT_EQ(centre[0], 0);
}

// SAS semantics beyond the transforms: the viewport size is bound, a light's DIRECTION and
// POSITION (with its Object annotation) get stand-ins, and the light reaches the image.
TEST(FxkitRender, SasViewportAndLightSemanticsAreBound) {
  const auto [r, image] = render("sas", R"(
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
float2 Viewport : VIEWPORTPIXELSIZE;
float Elapsed : ELAPSEDTIME;
float3 SunDirection : DIRECTION < string Object = "DirectionalLight0"; >;
float3 Lamp : POSITION < string Object = "PointLight0"; >;
struct V { float4 position : POSITION; float3 normal : TEXCOORD0; float3 world : TEXCOORD1; };
V VS(float4 p : POSITION, float3 n : NORMAL) { V o; o.position = mul(p, WorldViewProj); o.normal = n; o.world = p.xyz; return o; }
float4 PS(V i, float2 pixel : VPOS) : COLOR0 {
  float sun = saturate(dot(normalize(i.normal), -SunDirection));
  float lamp = saturate(dot(normalize(i.normal), normalize(Lamp - i.world)));
  float edge = pixel.x < Viewport.x * 0.5 ? 1 : 0.5;
  return float4(sun * edge, lamp, Elapsed > 0 ? 1 : 0, 1);
}
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                                 "--verbose --validation --size 64x64");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line :
       {"Viewport <- VIEWPORTPIXELSIZE (by its semantic)", "Elapsed <- ELAPSEDTIME (by its semantic)",
        "SunDirection <- light direction (stand-in)", "Lamp <- light position (stand-in)"})
    EXPECT_NE(r.err.find(line), std::string::npos) << line << "\n" << r.err;
  ASSERT_TRUE(image);
  uint8_t most_green = 0, most_blue = 0;
  for (uint32_t y = 0; y < image->height; ++y)
    for (uint32_t x = 0; x < image->width; ++x)
      most_green = std::max(most_green, image->at(x, y)[1]), most_blue = std::max(most_blue, image->at(x, y)[2]);
  EXPECT_GT(most_green, 128) << "the stand-in lamp lights the side facing it";
  EXPECT_EQ(most_blue, 255) << "ELAPSEDTIME is positive";
}

// A D3D9 post-process pass sets only a pixel shader: fixed-function vertex processing is
// generated to write exactly what it reads (a struct of TEXCOORD0 and COLOR0 here).
TEST(FxkitRender, AnHlslPixelShaderWithoutAVertexShaderDraws) {
  const auto [r, image] = render("post", R"(
struct In { float2 uv : TEXCOORD0; float4 colour : COLOR0; };
float4 PS(In i, uniform float gain) : COLOR0 { return float4(i.uv * gain, i.colour.a, 1); }
technique T { pass P { PixelShader = compile ps_2_0 PS(1.0); } }
)",
                                 "--validation --size 64x64");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("image is constant"), std::string::npos) << r.err;
  ASSERT_TRUE(image);
  EXPECT_FALSE(image->constant());
}

TEST(FxkitRender, AnHlslVertexShaderWithoutAPixelShaderDraws) {
  // D3D9 texture stages beside an HLSL vertex shader: the generated pixel stage reads the
  // three-component colour and the coordinates it writes, and nothing it does not.
  const auto [r, image] = render("texture_stages", R"(
float4x4 WorldViewProj;
struct Out { float4 p : SV_Position; float3 c : COLOR0; float2 uv : TEXCOORD0; };
Out VS(float4 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0) {
  Out o; o.p = mul(p, WorldViewProj); o.c = n * 0.5 + 0.5; o.uv = uv; return o;
}
technique T { pass P {
  VertexShader = compile vs_2_0 VS();
  PixelShader = NULL;
  TextureFactor = 0xff80c0ff;
  ColorOp[0] = Modulate; ColorArg1[0] = Diffuse; ColorArg2[0] = TFactor;
} }
)",
                                 "--validation --size 64x64");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("image is constant"), std::string::npos) << r.err;
  ASSERT_TRUE(image);
  EXPECT_FALSE(image->constant());
}

TEST(FxkitRender, ASamplerArrayDrawsWithEveryElementBound) {
  // Every element of a sampler array gets a descriptor (the first element's texture): the
  // second element, read by the shader, used to be left unwritten and crashed the driver.
  const auto [r, image] = render("sampler_array", R"(
texture A; texture B;
sampler Samplers[2] = { sampler_state { Texture = <A>; }, sampler_state { Texture = <B>; } };
float4x4 WorldViewProj;
float4 VS(float4 p : POSITION, inout float2 uv : TEXCOORD0) : POSITION { return mul(p, WorldViewProj); }
float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(Samplers[0], uv) * 0.5 + tex2D(Samplers[1], uv) * float4(uv, 0, 0.5); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)",
                                 "--validation --size 64x64");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(image);
  EXPECT_FALSE(image->constant());
  // What the user is told: the second element draws with the first element's texture.
  EXPECT_NE(r.err.find("'Samplers' is an array of 2; every element samples its first element's texture"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("[vk-image-array-first]"), std::string::npos) << r.err;
}

TEST(FxkitRender, AnUnnamedTechniqueIsNamedByItsIndexAsInfoAndCompileName) {
  // `technique { ... }` is valid D3D; fxkit info and compile call it technique<index>.
  const auto [r, image] = render("unnamed", R"(
float4x4 WorldViewProj;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProj); }
float4 Red() : COLOR0 { return float4(1, 0, 0, 1); }
float4 Green() : COLOR0 { return float4(0, 1, 0, 1); }
technique { pass { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Red(); } }
technique { pass { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Green(); } }
)",
                                 "--technique technique1 --validation --size 16x16");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(image);
  const uint8_t* centre = &image->pixels[(8 * image->width + 8) * 4];
  EXPECT_EQ(centre[1], 255);  // the second technique's green
  EXPECT_EQ(centre[0], 0);
}

TEST(FxkitRender, ASpriteShaderTransformingItsPositionInPlaceDraws) {
  // The stock sprite effects of XNA, FNA and MonoGame: `inout float4 position : SV_Position`.
  const auto [r, image] = render("sprite", R"(
float4x4 MatrixTransform;
sampler TextureSampler : register(s0);
void SpriteVertexShader(inout float4 color : COLOR0, inout float2 texCoord : TEXCOORD0, inout float4 position : SV_Position) {
  position = mul(position, MatrixTransform);
}
float4 SpritePixelShader(float4 color : COLOR0, float2 texCoord : TEXCOORD0) : SV_Target0 {
  return tex2D(TextureSampler, texCoord) * color;
}
technique SpriteBatch { pass { VertexShader = compile vs_2_0 SpriteVertexShader(); PixelShader = compile ps_2_0 SpritePixelShader(); } }
)",
                                 "--validation --size 32x32");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(image);
  EXPECT_FALSE(image->constant()) << r.err;
}

TEST(FxkitRender, AFlatImageIsAWarningNamingTheUnboundTransform) {
  const fx::testing::CliRun r = render("unbound", R"(
float4x4 ClipFromObjectXf;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, ClipFromObjectXf); }
float4 PS() : COLOR0 { return float4(1, 0, 0, 1); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)",
                                       "")
                                    .run;
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("'ClipFromObjectXf' is read by the shaders but left zero"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("warning: the image is constant"), std::string::npos) << r.err;
}

// A sphere drawn in one colour on the background is no preview either: the frame varies,
// the object does not.
TEST(FxkitRender, AnObjectInOneFlatColourIsAWarning) {
  const std::string source = R"(
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProj); }
float4 PS() : COLOR0 { return float4(1, 0, 0, 1); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";
  const fx::testing::CliRun flat = render("flat_object", source, "").run;
  ASSERT_EQ(flat.status, 0) << flat.err;
  EXPECT_NE(flat.err.find("warning: the image is one flat colour over the drawn object (255,0,0,255)"),
            std::string::npos)
      << flat.err;
  EXPECT_EQ(flat.err.find("image is constant"), std::string::npos) << flat.err;
  const std::string shaded = R"(
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
struct V { float4 p : POSITION; float3 n : TEXCOORD0; };
V VS(float4 p : POSITION, float3 n : NORMAL) { V o; o.p = mul(p, WorldViewProj); o.n = n; return o; }
float4 PS(float3 n : TEXCOORD0) : COLOR0 { return float4(n * 0.5 + 0.5, 1); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";
  const fx::testing::CliRun varied = render("varied_object", shaded, "").run;
  ASSERT_EQ(varied.status, 0) << varied.err;
  EXPECT_EQ(varied.err.find("one flat colour"), std::string::npos) << varied.err;
}

// A filter of a texture no file fills (the SDK's colour inverse) shows: the stand-in is a
// test pattern, not white, and --verbose names it.
TEST(FxkitRender, AFilterOfATextureStandInShowsTheFilter) {
  const auto [r, image] = render("inverse", R"(
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
texture SceneTexture;
sampler SceneSampler = sampler_state { Texture = <SceneTexture>; };
struct V { float4 p : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V o; o.p = mul(p, WorldViewProj); o.uv = uv; return o; }
float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return float4(1 - tex2D(SceneSampler, uv).rgb, 1); }
technique ColorInverse { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)",
                                 "--verbose --validation");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("SceneTexture <- colour test pattern (stand-in: no ResourceName)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("one flat colour"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("image is constant"), std::string::npos) << r.err;
  ASSERT_TRUE(image);
}

// A post effect that processes the host's scene shows it processed: the preview draws its test
// scene for ScriptExternal, and --verbose says so.
TEST(FxkitRender, APostEffectProcessesThePreviewsTestScene) {
  const auto [r, image] = render("external", R"(
float Script : STANDARDSGLOBAL < string ScriptClass = "scene"; string ScriptOrder = "postprocess"; > = 0.8;
float4 ClearColor = {0, 0, 0, 1};
texture ScnMap : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; >;
sampler ScnSamp = sampler_state { Texture = <ScnMap>; AddressU = CLAMP; AddressV = CLAMP; };
struct Q { float4 p : POSITION; float2 uv : TEXCOORD0; };
Q VS(float4 p : POSITION, float2 uv : TEXCOORD0) { Q o; o.p = float4(p.xy, 0, 1); o.uv = uv; return o; }
float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return float4(dot(tex2D(ScnSamp, uv).rgb, float3(0.3, 0.59, 0.11)).xxx, 1); }
technique Grey < string Script = "RenderColorTarget0=ScnMap; ClearSetColor=ClearColor; Clear=Color; Clear=Depth; ScriptExternal=color; RenderColorTarget0=; Pass=P;"; > {
  pass P < string Script = "Draw=Buffer;"; > { ZEnable = false; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); }
}
)",
                                 "--verbose --validation");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("ScriptExternal <- the preview's test scene (stand-in)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("one flat colour"), std::string::npos) << r.err;
  ASSERT_TRUE(image);
  // Grey: the test scene's colours, each with equal channels.
  const uint8_t* centre = image->at(image->width / 2, image->height / 2);
  EXPECT_GT(centre[0], 20);
  EXPECT_NEAR(centre[0], centre[1], 1);
  EXPECT_NEAR(centre[1], centre[2], 1);
}

// The summary line's error figure says whose error it is and in what unit.
TEST(FxkitRender, TheSummarySaysTheErrorIsTheTechniquesMeasuredOneIn8BitLevels) {
  const std::string source = R"(
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProj); }
float4 PS() : COLOR0 { return float4(0.5, 0.5, 0.5, 1); }
technique T < float MaxError = 180; > { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";
  const auto [r, image] = render("measured", source, "");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("technique's measured max error 180 (8-bit levels, its MaxError annotation)"), std::string::npos)
      << r.out;
}

}  // namespace

// The D3D10 particle pattern: a stream-output pass captures the mesh's triangles (here moved
// to clip space and coloured by the geometry shader), and the pass after it draws what was
// captured (DrawAuto) instead of the mesh.
TEST(FxkitRender, AStreamOutputPassCapturesWhatTheNextPassDraws) {
  const auto [r, image] = render("stream_output", R"(
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
struct V { float4 pos : POSITION; };
struct P { float4 pos : POSITION; float3 colour : COLOR0; };
V VS(float4 p : POSITION) { V o; o.pos = mul(p, WorldViewProj); return o; }
[maxvertexcount(3)] void GS(triangle V v[3], inout TriangleStream<P> stream) {
  for (int i = 0; i < 3; ++i) { P p; p.pos = v[i].pos; p.colour = float3(0.25, 0.75, 0.5); stream.Append(p); }
}
struct Pixel { float4 pos : SV_Position; float3 colour : COLOR0; };
Pixel Show(P p) { Pixel o; o.pos = p.pos; o.colour = p.colour; return o; }
float4 PS(Pixel p) : SV_Target { return float4(p.colour, 1); }
technique10 Particles {
  pass Capture < int StreamOutVertices = 65536; > {
    SetVertexShader(CompileShader(vs_4_0, VS()));
    SetGeometryShader(ConstructGSWithSO(CompileShader(gs_4_0, GS()), "POSITION.xyzw; COLOR0.xyz"));
    SetPixelShader(NULL);
  }
  pass Draw {
    SetVertexShader(CompileShader(vs_4_0, Show()));
    SetGeometryShader(NULL);
    SetPixelShader(CompileShader(ps_4_0, PS()));
  }
}
)",
                                 "--validation --size 64x64");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(image);
  EXPECT_FALSE(image->constant()) << "the captured sphere is drawn over the background";
  const size_t centre = (size_t(32) * 64 + 32) * 4;
  EXPECT_NEAR(image->pixels.at(centre), 64, 1);
  EXPECT_NEAR(image->pixels.at(centre + 1), 191, 1);
  EXPECT_NEAR(image->pixels.at(centre + 2), 128, 1);
}

// A technique that only computes draws nothing: the PNG is what it wrote, here the buffer it
// fills from one it only reads (a pattern stands in for that one), and it is no constant image.
TEST(FxkitRender, AComputeOnlyTechniqueShowsTheBufferItWrote) {
  const auto [r, image] = render("compute_only", R"(StructuredBuffer<float3> Positions;
RWStructuredBuffer<float> Distances;
[numthreads(64, 1, 1)] void Measure(uint3 id : SV_DispatchThreadID) { Distances[id.x] = length(Positions[id.x]); }
technique11 Falloff { pass P < int3 Dispatch = {4, 1, 1}; > { SetComputeShader(CompileShader(cs_5_0, Measure())); } }
)",
                                 "--verbose --validation");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("Positions <- a pattern (stand-in: a buffer no pass writes)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the image is the words its compute passes wrote to buffer 'Distances'"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("image is constant"), std::string::npos) << r.err;
  ASSERT_TRUE(image);
  EXPECT_EQ(image->width, 64u);
  EXPECT_FALSE(image->constant());
}
