// Pass state summaries: the D3D9 and D3D10/11 forms of one state set must agree.
#include <gtest/gtest.h>

#include "model_test_util.h"

namespace fx {
namespace {

TEST(PassState, D3D9Defaults) {
  auto b = test::build("technique T { pass P { } }", true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const PassStateSummary& s = b->model.techniques[0].passes[0].summary;
  EXPECT_EQ(s, PassStateSummary{});
  EXPECT_EQ(s.cull, CullMode::back);  // D3D9 CullMode = CCW with clockwise front faces
  EXPECT_EQ(s.front_face, FrontFace::clockwise);
  EXPECT_TRUE(s.depth_test);
  EXPECT_EQ(s.depth_compare, CompareOp::less_or_equal);
}

TEST(PassState, D3D9AndD3D11FormsAgree) {
  auto d3d9 = test::build(R"(
    technique T { pass P {
      ZEnable = TRUE; ZWriteEnable = FALSE; ZFunc = Less;
      CullMode = CW; FillMode = Wireframe; ScissorTestEnable = TRUE;
      AlphaBlendEnable = TRUE; SrcBlend = SrcAlpha; DestBlend = InvSrcAlpha; BlendOp = Add;
      SeparateAlphaBlendEnable = TRUE; SrcBlendAlpha = One; DestBlendAlpha = Zero; BlendOpAlpha = Max;
      ColorWriteEnable = Red | Green | Blue;
      StencilEnable = TRUE; StencilFunc = Equal; StencilPass = Replace; StencilFail = Keep; StencilZFail = IncrSat;
      TwoSidedStencilMode = TRUE; CCW_StencilFunc = Always; CCW_StencilPass = Decr;
      StencilRef = 3; StencilMask = 0xFF; StencilWriteMask = 0x0F;
      BlendFactor = 0x80402010; MultiSampleAntialias = FALSE; MultiSampleMask = 0xFFFFFFFF;
    } }
  )",
                          true);
  auto d3d11 = test::build(R"(
    BlendState B {
      BlendEnable[0] = TRUE; SrcBlend = SRC_ALPHA; DestBlend = INV_SRC_ALPHA; BlendOp = ADD;
      SrcBlendAlpha = ONE; DestBlendAlpha = ZERO; BlendOpAlpha = MAX; RenderTargetWriteMask[0] = 7;
    };
    DepthStencilState D {
      DepthEnable = TRUE; DepthWriteMask = ZERO; DepthFunc = LESS; StencilEnable = TRUE;
      StencilReadMask = 0xFF; StencilWriteMask = 0x0F;
      FrontFaceStencilFunc = EQUAL; FrontFaceStencilPass = REPLACE; FrontFaceStencilFail = KEEP;
      FrontFaceStencilDepthFail = INCR_SAT;
      BackFaceStencilFunc = ALWAYS; BackFaceStencilPass = DECR; BackFaceStencilFail = KEEP;
      BackFaceStencilDepthFail = KEEP;
    };
    RasterizerState R { CullMode = FRONT; FillMode = WIREFRAME; ScissorEnable = TRUE; FrontCounterClockwise = FALSE; };
    technique11 T { pass P {
      SetBlendState(B, float4(0x40 / 255.0, 0x20 / 255.0, 0x10 / 255.0, 0x80 / 255.0), 0xFFFFFFFF);
      SetDepthStencilState(D, 3);
      SetRasterizerState(R);
    } }
  )",
                           true);
  ASSERT_FALSE(d3d9->diags.has_errors()) << d3d9->text();
  ASSERT_FALSE(d3d11->diags.has_errors()) << d3d11->text();
  PassStateSummary a = d3d9->model.techniques[0].passes[0].summary;
  PassStateSummary b = d3d11->model.techniques[0].passes[0].summary;
  // D3D9's mask keeps its upper 24 bits; D3D11's is 8 bits: compare what a stencil uses.
  EXPECT_EQ(a.stencil_read_mask & 0xFF, b.stencil_read_mask & 0xFF);
  a.stencil_read_mask = b.stencil_read_mask = 0;
  a.stencil_write_mask &= 0xFF;
  // Depth bias units differ by API even at zero; the flag says which.
  a.depth_bias_normalized = b.depth_bias_normalized = false;
  EXPECT_EQ(a.blend[0], b.blend[0]);
  EXPECT_EQ(a.stencil_front, b.stencil_front);
  EXPECT_EQ(a.stencil_back, b.stencil_back);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(a.blend_constants[i], b.blend_constants[i], 1e-6) << i;
  a.blend_constants = b.blend_constants;
  // Targets beyond the first: D3D9 ColorWriteEnable touches target 0 only, D3D11 without
  // independent blending replicates target 0; compare target 0's blend, then drop the rest.
  for (int i = 1; i < kMaxRenderTargets; ++i) a.blend[i] = b.blend[i];
  EXPECT_EQ(a, b);
  EXPECT_EQ(b.cull, CullMode::front);
  EXPECT_EQ(b.depth_compare, CompareOp::less);
  EXPECT_FALSE(b.depth_write);
  EXPECT_EQ(b.stencil_ref, 3u);
  EXPECT_EQ(b.blend[0].write_mask, 7);
  EXPECT_EQ(b.blend[0].alpha_op, BlendOp::max);
  EXPECT_EQ(b.fill, FillMode::wireframe);
}

TEST(PassState, D3D9AlphaFollowsColourWithoutSeparateBlend) {
  auto b = test::build(
      "technique T { pass P { AlphaBlendEnable = TRUE; SrcBlend = One; DestBlend = One; BlendOp = RevSubtract; } }",
      true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const TargetBlend& t = b->model.techniques[0].passes[0].summary.blend[3];
  EXPECT_TRUE(t.enable);
  EXPECT_EQ(t.src_alpha, BlendFactor::one);
  EXPECT_EQ(t.dst_alpha, BlendFactor::one);
  EXPECT_EQ(t.alpha_op, BlendOp::reverse_subtract);
}

TEST(PassState, D3D9TwoSidedOffCopiesFrontToBack) {
  auto b =
      test::build("technique T { pass P { StencilEnable = TRUE; StencilFunc = NotEqual; StencilPass = Zero; } }", true);
  const PassStateSummary& s = b->model.techniques[0].passes[0].summary;
  EXPECT_EQ(s.stencil_back, s.stencil_front);
  EXPECT_EQ(s.stencil_front.compare, CompareOp::not_equal);
  EXPECT_EQ(s.stencil_front.pass, StencilOp::zero);
}

TEST(PassState, StateObjectDefaultsApplyWhenSet) {
  auto b = test::build(R"(
    DepthStencilState D { StencilEnable = FALSE; };
    technique10 T { pass P { SetDepthStencilState(D, 0); } }
  )",
                       true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const PassStateSummary& s = b->model.techniques[0].passes[0].summary;
  EXPECT_EQ(s.depth_compare, CompareOp::less);  // D3D10 DepthFunc default, not D3D9's LessEqual
  EXPECT_TRUE(s.depth_write);
}

// An array of state objects written one `{ }` per element: a pass takes the element it
// names, and the array's name alone is element 0.
TEST(PassState, StateObjectArrayElementsAreObjectsOfTheirOwn) {
  auto b = test::build(R"(
    RasterizerState Cull[3] { { CullMode = NONE; }, { CullMode = FRONT; }, { CullMode = BACK; } };
    technique10 T {
      pass P0 { SetRasterizerState(Cull[1]); }
      pass P1 { SetRasterizerState(Cull[0]); }
      pass P2 { SetRasterizerState(Cull); }
    }
  )",
                       true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const auto& passes = b->model.techniques[0].passes;
  EXPECT_EQ(passes[0].summary.cull, CullMode::front);
  EXPECT_EQ(passes[1].summary.cull, CullMode::none);
  EXPECT_EQ(passes[2].summary.cull, CullMode::none);
}

// `StateBlock = <sb>;` applies the stateblock's states at that point of the pass (D3DX9
// applies the block it captured), shaders included; a later state of the pass wins.
TEST(PassState, StateBlockStatesApplyWhereThePassNamesIt) {
  auto b = test::build(R"(
    float4 VS(float4 p : POSITION) : POSITION { return p; }
    stateblock Opaque = stateblock_state {
      CullMode = None; ZWriteEnable = false; VertexShader = compile vs_2_0 VS();
    };
    technique T {
      pass P0 { StateBlock = <Opaque>; }
      pass P1 { StateBlock = <Opaque>; ZWriteEnable = true; }
      pass P2 { ZWriteEnable = false; }
    }
  )",
                       true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  EXPECT_EQ(b->model.find_parameter("Opaque"), kNoIndex);  // states, not a parameter
  const auto& passes = b->model.techniques[0].passes;
  EXPECT_EQ(passes[0].summary.cull, CullMode::none);
  EXPECT_FALSE(passes[0].summary.depth_write);
  ASSERT_NE(passes[0].shader(PassStage::vertex), nullptr);
  EXPECT_EQ(passes[0].shader(PassStage::vertex)->entry, "VS");
  EXPECT_TRUE(passes[1].summary.depth_write);
  EXPECT_EQ(passes[2].summary.cull, CullMode::back);
  EXPECT_EQ(passes[2].shader(PassStage::vertex), nullptr);
}

// A state computed from a call of an effect function, or from a parameter the application
// sets, is an expression fxc leaves to the effect runtime at apply time: a located
// unsupported-state-expression, not a claim that the value is no constant.
TEST(PassState, StateExpressionsOverParametersAreLocatedAsUnsupported) {
  auto b = test::build(R"(
    float4 a;
    float3 f, g;
    float bias() { return a.x * 2; }
    SamplerState S { MipLODBias = bias(); BorderColor = sin(a) + 1; };
    BlendState B { BlendEnable[0] = f * g; };
    technique10 T { pass P { SetBlendState(B, float4(0, 0, 0, 0), 0xFFFFFFFF); } }
  )",
                       true);
  std::vector<std::pair<std::string, uint32_t>> found;
  for (const Diagnostic& d : b->diags.diagnostics())
    if (d.severity == Severity::error) found.emplace_back(d.id, b->sm->presumed(d.range.begin).line);
  using Row = std::pair<std::string, uint32_t>;
  EXPECT_EQ(found, (std::vector<Row>{{"unsupported-state-expression", 5},
                                     {"unsupported-state-expression", 5},
                                     {"unsupported-state-expression", 6}}))
      << b->text();
  EXPECT_NE(b->text().find("depends on a call of 'bias'"), std::string::npos) << b->text();
}

}  // namespace
}  // namespace fx
