// DXSAS Script annotations: a post effect's technique and pass scripts planned step by step,
// and each kind of mistake warned about at its place inside the annotation's string.
#include <gtest/gtest.h>

#include "model_test_util.h"

namespace fx {
namespace {

constexpr const char* kPostEffect = R"(float Script : STANDARDSGLOBAL < string ScriptClass = "scene";
  string ScriptOrder = "postprocess"; string ScriptOutput = "color"; > = 0.8;
float4 ClearColor = {0, 0, 0, 1};
float ClearDepth = 1;
int Taps = 2;
texture Scene : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; string Format = "A8R8G8B8"; >;
texture Depth : RENDERDEPTHSTENCILTARGET < float2 ViewportRatio = {1, 1}; >;
float4 PS() : COLOR0 { return 1; }
technique Main < string Script = "RenderColorTarget0=Scene; RenderDepthStencilTarget=Depth; ClearSetColor=ClearColor; ClearSetDepth=ClearDepth; Clear=Color; Clear=Depth; ScriptExternal=color; RenderColorTarget0=; RenderDepthStencilTarget=; LoopByCount=Taps; Pass=Blur; LoopEnd=; Pass=Composite;"; > {
  pass Blur < string Script = "Draw=Buffer;"; > { PixelShader = compile ps_2_0 PS(); }
  pass Composite < string Script = "Draw=Buffer;"; > { PixelShader = compile ps_2_0 PS(); }
}
)";

TEST(DxsasScript, PostEffectScriptsArePlanned) {
  auto b = test::build(kPostEffect);
  ASSERT_TRUE(b->diags.diagnostics().empty()) << b->text();
  const TechniqueInfo& t = b->model.techniques[0];
  ASSERT_TRUE(t.script);
  const std::vector<ScriptStep>& steps = t.script->steps;
  ASSERT_EQ(steps.size(), 13u);
  EXPECT_EQ(steps[0].command, ScriptCommand::render_color_target);
  EXPECT_EQ(steps[0].parameter, b->model.find_parameter("Scene"));
  EXPECT_EQ(steps[1].parameter, b->model.find_parameter("Depth"));
  EXPECT_EQ(steps[5].clear, ScriptClear::depth);
  EXPECT_EQ(steps[6].command, ScriptCommand::script_external);
  EXPECT_EQ(steps[7].parameter, kNoIndex);  // back to the frame's own target
  EXPECT_EQ(steps[9].command, ScriptCommand::loop_by_count);
  EXPECT_EQ(steps[10].pass, 0u);
  EXPECT_EQ(steps[12].pass, 1u);
  ASSERT_TRUE(t.passes[0].script);
  ASSERT_EQ(t.passes[0].script->steps.size(), 1u);
  EXPECT_EQ(t.passes[0].script->steps[0].draw, ScriptDraw::buffer);
  EXPECT_EQ(b->model.script_global.script_order, "postprocess");
  // Each step is located inside the string: "Pass=Blur" on line 9.
  const PresumedLocation at = b->sm->presumed(steps[10].range.begin);
  EXPECT_EQ(at.line, 9u);
  EXPECT_EQ(b->sm->line_text(steps[10].range.begin).substr(at.column - 1, 9), "Pass=Blur");
}

// One warning per mistake, at the column of the word inside the string.
TEST(DxsasScript, MistakesAreLocatedInsideTheString) {
  auto b = test::build(R"(float4 Colour;
texture Plain;
float4 PS() : COLOR0 { return 1; }
technique T < string Script = "RenderColorTarget0=Plain; ClearSetDepth=Colour; Pass=Bulr; Drow=Geometry; LoopEnd=;"; > {
  pass Blur < string Script = "Pass=Blur; Draw=Triangles;"; > { PixelShader = compile ps_2_0 PS(); }
}
)");
  struct Expected {
    const char* id;
    const char* at;  // the text the warning starts at
  };
  const Expected expected[] = {
      {"script-wrong-type", "Plain; Clear"}, {"script-wrong-type", "Colour; Pass"}, {"script-unknown-name", "Bulr"},
      {"script-unknown-command", "Drow"},    {"script-loop-unbalanced", "LoopEnd"}, {"script-misplaced", "Pass=Blur"},
      {"script-unknown-name", "Triangles"},
  };
  const auto& diags = b->diags.diagnostics();
  ASSERT_EQ(diags.size(), std::size(expected)) << b->text();
  for (size_t i = 0; i < diags.size(); ++i) {
    EXPECT_EQ(diags[i].id, expected[i].id) << diags[i].message;
    EXPECT_EQ(diags[i].severity, Severity::warning);
    const PresumedLocation at = b->sm->presumed(diags[i].range.begin);
    const std::string_view line = b->sm->line_text(diags[i].range.begin);
    EXPECT_EQ(line.substr(at.column - 1, std::string_view(expected[i].at).size()), expected[i].at) << diags[i].message;
  }
  EXPECT_NE(diags[2].message.find("did you mean 'Blur'"), std::string::npos) << diags[2].message;
  EXPECT_NE(diags[3].message.find("did you mean 'Draw'"), std::string::npos) << diags[3].message;
}

}  // namespace
}  // namespace fx
