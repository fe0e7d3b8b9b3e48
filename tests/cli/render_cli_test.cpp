// `fxkit render` of effects written for an engine, with nothing set up: the stand-ins
// (bone palettes, colours, light direction and count), SV_Position as a vertex input, and
// the warning for an image that is one flat colour.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fx/image.h"
#include "fxkit_cli.h"

namespace {

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / ("fxkit_render_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
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
  const auto fx = write("skinned.fx", kSkinned);
  const auto png = fx.parent_path() / "skinned.png";
  const fxkit_test::CliRun r =
      fxkit_test::run_fxkit("render " + fx.string() + " --verbose --validation --out " + png.string(), true);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line : {"Bones <- identity bone palette (stand-in)", "DiffuseColor <- visible colour (stand-in)",
                           "LightDirection <- light direction (stand-in)", "LightCount <- light count (stand-in)"})
    EXPECT_NE(r.err.find(line), std::string::npos) << line << "\n" << r.err;
  EXPECT_EQ(r.err.find("image is constant"), std::string::npos) << r.err;
  fx::DiagnosticSink sink;
  const auto image = fx::read_png(png, sink, 4);
  ASSERT_TRUE(image);
  EXPECT_FALSE(image->constant());
  // The lit sphere: its centre is the stand-in grey times (0.2 + a light), not black.
  const uint8_t* centre = image->at(image->width / 2, image->height / 2);
  EXPECT_GT(centre[0], 60);
}

TEST(FxkitRender, ParamOverridesAStandIn) {
  const auto fx = write("skinned_param.fx", kSkinned);
  const auto png = fx.parent_path() / "skinned_param.png";
  const fxkit_test::CliRun r = fxkit_test::run_fxkit(
      "render " + fx.string() + " --param DiffuseColor=0,0,0,1 --out " + png.string(), true);
  ASSERT_EQ(r.status, 0) << r.err;
  fx::DiagnosticSink sink;
  const auto image = fx::read_png(png, sink, 4);
  ASSERT_TRUE(image);
  const uint8_t* centre = image->at(image->width / 2, image->height / 2);
  EXPECT_EQ(centre[0], 0);
}

TEST(FxkitRender, AFlatImageIsAWarningNamingTheUnboundTransform) {
  const auto fx = write("unbound.fx", R"(
float4x4 ClipFromObjectXf;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, ClipFromObjectXf); }
float4 PS() : COLOR0 { return float4(1, 0, 0, 1); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  const fxkit_test::CliRun r =
      fxkit_test::run_fxkit("render " + fx.string() + " --out " + (fx.parent_path() / "unbound.png").string(), true);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("'ClipFromObjectXf' is read by the shaders but left zero"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("warning: the image is constant"), std::string::npos) << r.err;
}

}  // namespace
