// tools/viewer's widget_for on the parameters of a real effect (fxkit::Effect::params()):
// what the viewer's panel lists, and as what. Statics are the shader's constants, not
// parameters, and are not listed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "fxkit/fxkit.h"
#include "param_widgets.h"

namespace {

TEST(ViewerParamWidgets, StaticsAreNotListedAndSettableValuesGetControls) {
  fxkit::DeviceOptions o;
  o.target.formats.color = {VK_FORMAT_R8G8B8A8_UNORM};
  o.target.formats.depth = VK_FORMAT_D32_SFLOAT;
  o.target.vertex_layout = fxkit::Mesh::vertex_layout();
  o.target.front_faces = fxkit::Winding::counter_clockwise;
  o.target.y_flip = fxkit::YFlip::negative_viewport;
  std::vector<fxkit::Message> errors;
  auto device = fxkit::Device::headless(o, {}, errors);
  ASSERT_TRUE(device);
  const auto path =
      std::filesystem::temp_directory_path() / ("fxkit_viewer_widgets_" + std::to_string(::getpid()) + ".fx");
  std::ofstream(path) << R"fx(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
static const float3 kAxis = {0.0, 1.0, 0.0};
static float Scale = 2.0;
float4 Tint < string UIName = "Tint of the whole object, multiplied in"; string UIWidget = "Color"; > = {1, 1, 1, 1};
bool Flip < string UIName = "Flip the axis (runtime switch, key F)"; > = false;
float Gain < float UIMin = 0.0; float UIMax = 4.0; > = 1.0;
float4 VS(float4 p : POSITION) : POSITION { return mul(p * Scale, WorldViewProjection); }
float4 PS() : COLOR0 { return Tint * Gain * float4(Flip ? -kAxis : kAxis, 1.0); }
technique T { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)fx";
  fxkit::Effect effect = device->load(path.string());
  ASSERT_TRUE(effect.ok());
  std::map<std::string, ParamWidget> shown;
  for (const fxkit::ParamInfo& p : effect.params()) shown[p.name] = widget_for(p);
  std::filesystem::remove(path);
  ASSERT_EQ(shown.count("kAxis") + shown.count("Scale"), 2u) << "params() lists statics; the viewer hides them";
  EXPECT_EQ(shown["kAxis"].kind, ParamWidget::Kind::hidden);
  EXPECT_EQ(shown["Scale"].kind, ParamWidget::Kind::hidden);
  EXPECT_EQ(shown["WorldViewProjection"].kind, ParamWidget::Kind::readonly);
  EXPECT_EQ(shown["Tint"].kind, ParamWidget::Kind::color);
  EXPECT_EQ(shown["Tint"].label, "Tint of the whole object, multiplied in");
  EXPECT_EQ(shown["Flip"].kind, ParamWidget::Kind::checkbox);
  EXPECT_EQ(shown["Gain"].kind, ParamWidget::Kind::slider);
}

}  // namespace
