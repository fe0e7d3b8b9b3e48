// `fxkit watch --out` renders as `fxkit render` does: a technique's DXSAS Script runs (its
// full-screen pass covers the frame), not its first pass on the mesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fx/image.h"
#include "fxkit_cli.h"

namespace {

TEST(FxkitWatch, RendersATechniquesScript) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / ("fxkit_watch_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "scripted.fx", png = dir / "scripted.png";
  // Drawn on the mesh, the pass leaves the corners the clear colour; run as the script says
  // (Draw=Buffer), it covers the whole frame in green.
  std::ofstream(file) << R"(
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
float Script : STANDARDSGLOBAL < string ScriptClass = "scene"; string ScriptOrder = "postprocess"; > = 0.8;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProj); }
float4 QuadVS(float4 p : POSITION) : POSITION { return float4(p.xy, 0, 1); }
float4 PS() : COLOR0 { return float4(0, 1, 0, 1); }
technique Fill < string Script = "RenderColorTarget0=; Pass=P;"; > {
  pass P < string Script = "Draw=Buffer;"; > { ZEnable = false; VertexShader = compile vs_2_0 QuadVS(); PixelShader = compile ps_2_0 PS(); }
}
)";
  const fx::testing::CliRun r =
      fx::testing::run_fxkit("watch " + file.string() + " --frames 2 --out " + png.string(), true);
  ASSERT_EQ(r.status, 0) << r.err;
  fx::DiagnosticSink sink;
  auto image = fx::read_png(png, sink, 4);
  ASSERT_TRUE(image);
  const uint8_t* corner = image->at(0, 0);
  EXPECT_EQ(corner[0], 0);
  EXPECT_EQ(corner[1], 255);
  EXPECT_EQ(corner[2], 0);
  std::filesystem::remove_all(dir);
}

}  // namespace
