// Each state family verified by rendering through real .fx passes (effect states ->
// model summary -> pipeline state / sampler -> image): blend factors, depth, stencil, cull
// (which also pins the winding convention), sampler address modes.
#include <gtest/gtest.h>

#include "effect_test_util.h"

namespace fx::vk::testing {
namespace {

class EffectStatesTest : public VulkanTest {};

// A quad facing the camera; `passes` are the technique's pass bodies (shaders appended).
std::string effect_with(const std::string& passes) {
  return R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture Checker < string Generator = "pow"; int Width = 4; int Height = 4; float Exponent = 1; string Format = "unorm8"; >;
struct V { float4 pos : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V o; o.pos = mul(p, WorldViewProjection); o.uv = uv; return o; }
float4 Solid(uniform float4 c) : COLOR0 { return c; }
)" + passes;
}

#define SHADERS(color) "VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Solid(" color ");"

std::array<int, 4> centre(const fx::Image& image) {
  const uint8_t* p = image.at(image.width / 2, image.height / 2);
  return {p[0], p[1], p[2], p[3]};
}

std::unique_ptr<RenderedEffect> bind_text(Context& ctx, const std::string& name, const std::string& text,
                                          const std::string& technique) {
  return bind_effect(ctx, write_effect(name, text), technique, "quad", 32);
}

TEST_F(EffectStatesTest, BlendFactorsFromPassStates) {
  auto r = bind_text(ctx(), "blend.fx",
                     effect_with(R"(
technique alpha { pass p0 { AlphaBlendEnable = true; SrcBlend = SrcAlpha; DestBlend = InvSrcAlpha; )" SHADERS(
                         "float4(1, 0, 0, 0.5)") R"( } }
technique additive { pass p0 { AlphaBlendEnable = true; SrcBlend = One; DestBlend = One; )" SHADERS("float4(0.5, 0.25, "
                                                                                                    "0, 1)") R"( }
                     pass p1 { AlphaBlendEnable = true; SrcBlend = One; DestBlend = One; )" SHADERS("float4(0.25, "
                                                                                                    "0.25, 0, 1)") R"( } }
technique opaque { pass p0 { )" SHADERS("float4(1, 0, 0, 0.5)") R"( } }
)"),
                     "alpha");
  ASSERT_TRUE(r);
  auto alpha = r->render();
  r->technique = r->effect->find_technique("additive");
  auto additive = r->render();
  r->technique = r->effect->find_technique("opaque");
  auto opaque = r->render();
  ASSERT_TRUE(alpha && additive && opaque);
  // Clear is (0.08, 0.08, 0.1): 0.5 * 1 + 0.5 * 0.08 = 0.54 -> 138; 0.5 * 0.08 -> 10.
  EXPECT_NEAR(centre(*alpha)[0], 138, 2);
  EXPECT_NEAR(centre(*alpha)[1], 10, 2);
  // 0.08 + 0.5 + 0.25 = 0.83 -> 212; 0.08 + 0.25 + 0.25 -> 148.
  EXPECT_NEAR(centre(*additive)[0], 212, 2);
  EXPECT_NEAR(centre(*additive)[1], 148, 2);
  EXPECT_EQ(centre(*opaque)[0], 255);
  EXPECT_EQ(centre(*opaque)[1], 0);
}

TEST_F(EffectStatesTest, CullModesFollowDirect3DWinding) {
  auto r = bind_text(ctx(), "cull.fx", effect_with(R"(
technique ccw { pass p0 { CullMode = CCW; )" SHADERS("float4(0, 1, 0, 1)") R"( } }
technique cw { pass p0 { CullMode = CW; )" SHADERS("float4(0, 1, 0, 1)") R"( } }
technique none { pass p0 { CullMode = None; )" SHADERS("float4(0, 1, 0, 1)") R"( } }
)"),
                     "ccw");
  ASSERT_TRUE(r);
  auto ccw = r->render();
  r->technique = r->effect->find_technique("cw");
  auto cw = r->render();
  r->technique = r->effect->find_technique("none");
  auto none = r->render();
  ASSERT_TRUE(ccw && cw && none);
  // D3D's default (CCW culled) keeps front faces: the quad faces the camera.
  EXPECT_EQ(centre(*ccw)[1], 255);
  EXPECT_LT(centre(*cw)[1], 30);
  EXPECT_EQ(centre(*none)[1], 255);
}

TEST_F(EffectStatesTest, DepthCompareBetweenPasses) {
  auto r = bind_text(
      ctx(), "depth.fx",
      effect_with(R"(
technique equal { pass p0 { )" SHADERS(
          "float4(1, 0, 0, 1)") R"( } pass p1 { ZFunc = Equal; ZWriteEnable = false; )" SHADERS("float4(0, 0, 1, "
                                                                                                "1)") R"( } }
technique less { pass p0 { )" SHADERS("float4(1, 0, 0, 1)") R"( } pass p1 { ZFunc = Less; )" SHADERS("float4(0, 0, 1, "
                                                                                                     "1)") R"( } }
technique off { pass p0 { )" SHADERS("float4(1, 0, 0, 1)") R"( } pass p1 { ZEnable = false; ZFunc = Never; )" SHADERS("float4(0, 0, 1, 1)") R"( } }
)"),
      "equal");
  ASSERT_TRUE(r);
  auto equal = r->render();
  r->technique = r->effect->find_technique("less");
  auto less = r->render();
  r->technique = r->effect->find_technique("off");
  auto off = r->render();
  ASSERT_TRUE(equal && less && off);
  EXPECT_EQ(centre(*equal)[2], 255);  // same depth passes Equal
  EXPECT_EQ(centre(*less)[0], 255);   // and fails Less: the first pass stays
  EXPECT_EQ(centre(*off)[2], 255);    // no depth test at all
}

// DepthBiasClamp reaches the device (it needs the depthBiasClamp feature, which fxkit
// enables where the device has it). The second quad is drawn 0.001 behind the first; a bias
// of -10^6 units (at least -0.0019 of the depth range wherever the quad lies beyond 1/32)
// pulls it in front, and the same bias clamped to -0.0001 leaves it behind.
TEST_F(EffectStatesTest, DepthBiasClampLimitsTheBias) {
  if (!ctx().features().depth_bias_clamp) GTEST_SKIP() << "the device has no depthBiasClamp";
  auto r = bind_text(ctx(), "bias_clamp.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 VS(float4 p : POSITION, uniform float behind) : SV_Position {
  float4 o = mul(p, WorldViewProjection);
  o.z += behind * o.w;
  return o;
}
float4 Solid(uniform float4 c) : SV_Target { return c; }
RasterizerState Plain { CullMode = None; };
RasterizerState Pulled { CullMode = None; DepthBias = -1000000; };
RasterizerState PulledClamped { CullMode = None; DepthBias = -1000000; DepthBiasClamp = -0.0001; };
#define FIRST SetRasterizerState(Plain); SetVertexShader(CompileShader(vs_4_0, VS(0))); \
  SetPixelShader(CompileShader(ps_4_0, Solid(float4(1, 0, 0, 1))));
#define SECOND(state) SetRasterizerState(state); SetVertexShader(CompileShader(vs_4_0, VS(0.001))); \
  SetPixelShader(CompileShader(ps_4_0, Solid(float4(0, 0, 1, 1))));
technique10 pulled { pass p0 { FIRST } pass p1 { SECOND(Pulled) } }
technique10 clamped { pass p0 { FIRST } pass p1 { SECOND(PulledClamped) } }
technique10 unbiased { pass p0 { FIRST } pass p1 { SECOND(Plain) } }
)",
                     "pulled");
  ASSERT_TRUE(r);
  const size_t errors = ctx().validation_error_count();
  auto pulled = r->render();
  r->technique = r->effect->find_technique("clamped");
  auto clamped = r->render();
  r->technique = r->effect->find_technique("unbiased");
  auto unbiased = r->render();
  ASSERT_TRUE(pulled && clamped && unbiased);
  EXPECT_EQ(ctx().validation_error_count(), errors) << describe_messages(ctx());
  EXPECT_EQ(centre(*unbiased)[0], 255);  // behind: the first quad stays
  EXPECT_EQ(centre(*pulled)[2], 255);    // the bias brings the second in front
  EXPECT_EQ(centre(*clamped)[0], 255);   // the clamped bias does not
}

TEST_F(EffectStatesTest, StencilWrittenByOnePassMasksTheNext) {
  const std::string mark =
      R"(pass mark { StencilEnable = true; StencilFunc = Always; StencilPass = Replace; StencilRef = 1; ColorWriteEnable = 0; )" SHADERS(
          "float4(1, 1, 1, 1)") " }";
  auto r = bind_text(
      ctx(), "stencil.fx",
      effect_with(
          "technique match { " + mark +
          R"( pass p1 { StencilEnable = true; StencilFunc = Equal; StencilRef = 1; ZFunc = LessEqual; )" SHADERS(
              "float4(1, 0, 1, 1)") R"( } }
technique mismatch { )" +
          mark +
          R"( pass p1 { StencilEnable = true; StencilFunc = Equal; StencilRef = 2; )" SHADERS(
              "float4(1, 0, 1, 1)") R"( } }
)"),
      "match");
  ASSERT_TRUE(r);
  auto match = r->render();
  r->technique = r->effect->find_technique("mismatch");
  auto mismatch = r->render();
  ASSERT_TRUE(match && mismatch);
  EXPECT_EQ(centre(*match)[0], 255);
  EXPECT_EQ(centre(*match)[2], 255);
  EXPECT_LT(centre(*mismatch)[0], 30);  // masked out, and the mark pass wrote no colour
}

TEST_F(EffectStatesTest, SamplerAddressModes) {
  auto sampler = [](const char* mode) {
    return std::string("sampler2D S_") + mode +
           " = sampler_state { Texture = <Checker>; MinFilter = Point; MagFilter = Point; MipFilter = None; AddressU "
           "= " +
           mode + "; AddressV = " + mode + "; BorderColor = 0xFFFFFFFF; };\n" + "float4 PS_" + mode +
           "(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(S_" + mode + ", uv * 3.0 - 1.0); }\n" + "technique " +
           mode + " { pass p0 { CullMode = None; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS_" +
           mode + "(); } }\n";
  };
  auto r = bind_text(ctx(), "address.fx",
                     effect_with(sampler("Wrap") + sampler("Clamp") + sampler("Mirror") + sampler("Border")), "Wrap");
  ASSERT_TRUE(r);
  std::map<std::string, fx::Image> images;
  for (const char* mode : {"Wrap", "Clamp", "Mirror", "Border"}) {
    r->technique = r->effect->find_technique(mode);
    auto image = r->render();
    ASSERT_TRUE(image) << mode;
    images[mode] = *image;
  }
  // The middle third of the quad samples inside [0, 1]: every mode agrees there.
  EXPECT_EQ(centre(images["Wrap"]), centre(images["Clamp"]));
  EXPECT_EQ(centre(images["Wrap"]), centre(images["Border"]));
  // Outside, the four modes differ; Border reads the border colour (opaque white; other colours are approximated).
  EXPECT_NE(images["Wrap"].pixels, images["Clamp"].pixels);
  EXPECT_NE(images["Wrap"].pixels, images["Mirror"].pixels);
  EXPECT_NE(images["Clamp"].pixels, images["Mirror"].pixels);
  size_t white = 0;
  for (uint32_t y = 0; y < images["Border"].height; ++y)
    for (uint32_t x = 0; x < images["Border"].width; ++x) {
      const uint8_t* p = images["Border"].at(x, y);
      white += p[0] == 255 && p[1] == 255 && p[2] == 255;
    }
  EXPECT_GT(white, 100u);
}

// A vertex input the mesh does not have comes from a zero stream in the input's own shape
// and type: an integer BLENDINDICES read as float, or a matrix (an instanced world matrix,
// four locations) fed in its first column only, is a validation error (the fixture fails on
// it). `inputs` are the vertex shader's extra parameters, `color` what it outputs from them.
std::array<int, 4> centre_with_missing_inputs(Context& ctx, const std::string& name, const std::string& inputs,
                                              const std::string& color) {
  auto r = bind_text(ctx, name,
                     R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct V { float4 pos : POSITION; float4 color : COLOR0; };
V VS(float4 p : POSITION, )" +
                         inputs + R"() { V o; o.pos = mul(p, WorldViewProjection); o.color = )" + color +
                         R"(; return o; }
float4 PS(float4 c : COLOR0) : COLOR0 { return c; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                     "t");
  if (!r) return {};
  auto image = r->render();
  return image ? centre(*image) : std::array<int, 4>{};
}

TEST_F(EffectStatesTest, MissingIntegerVertexInputsReadZeroAsIntegers) {
  EXPECT_EQ(centre_with_missing_inputs(ctx(), "skin_inputs.fx", "uint4 bones : BLENDINDICES0, int4 flags : TEXCOORD5",
                                       "float4(bones.x == 0, flags.y == 0, 0, 1)"),
            (std::array<int, 4>{255, 255, 0, 255}));
}

TEST_F(EffectStatesTest, MissingMatrixVertexInputsFeedEveryColumn) {
  EXPECT_EQ(centre_with_missing_inputs(ctx(), "instanced.fx", "float4x4 instance : TEXCOORD4",
                                       "float4(1, 1, 1, 1) + instance[3]"),
            (std::array<int, 4>{255, 255, 255, 255}));
}

// A texture the effect names but gives no data gets a white stand-in in the shape the shader
// samples: a 2D view bound to a 1D sampler crashed lavapipe, and array samplers need array
// views (the fixture fails on the validation error).
TEST_F(EffectStatesTest, StandInTexturesTakeTheShapeTheShaderSamples) {
  if (!ctx().features().image_cube_array) GTEST_SKIP() << "the device cannot sample cube arrays";
  auto r = bind_text(ctx(), "shapes.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture Ramp; sampler1D RampSampler = sampler_state { Texture = <Ramp>; };
texture Volume; sampler3D VolumeSampler = sampler_state { Texture = <Volume>; };
Texture1D Line; Texture2DArray Layers; TextureCube Sky; TextureCubeArray Skies; SamplerState Linear;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target {
  return tex1D(RampSampler, 0.5) * tex3D(VolumeSampler, 0.5) * Line.Sample(Linear, 0.5) *
         Layers.Sample(Linear, float3(0.5, 0.5, 0)) * Sky.Sample(Linear, float3(1, 0, 0)) *
         Skies.Sample(Linear, float4(1, 0, 0, 0));
}
technique10 t { pass p { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)",
                     "t");
  ASSERT_TRUE(r);
  auto image = r->render();
  ASSERT_TRUE(image);
  EXPECT_EQ(centre(*image), (std::array<int, 4>{255, 255, 255, 255}));
}

// D3D9's pixel shader system values: VPOS is the pixel's integer position, VFACE is positive
// on front faces. glslang reads both as varyings nothing writes (a validation error).
TEST_F(EffectStatesTest, Ps30VposAndVfaceAreThePixelAndItsFacing) {
  // As parameters, and as members of the pixel shader's input struct beside a varying.
  for (const char* ps : {R"(float4 PS(float2 vpos : VPOS, float face : VFACE) : COLOR0 {
  return float4(all(frac(vpos) == 0) ? 1 : 0, face > 0 ? 1 : 0, face < 0 ? 1 : 0, vpos.x / 255);
})",
                         R"(struct PSIn { float4 tint : COLOR0; float2 vpos : VPOS; float face : VFACE; };
float4 PS(PSIn i) : COLOR0 {
  return float4(all(frac(i.vpos) == 0) ? 1 : 0, i.face > 0 ? 1 : 0, i.face < 0 ? 1 : 0, i.vpos.x / 255) * i.tint;
})"}) {
    auto r = bind_text(ctx(), "vpos.fx", std::string(R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
void VS(float4 p : POSITION, out float4 pos : POSITION, out float4 tint : COLOR0) { pos = mul(p, WorldViewProjection); tint = 1; }
)") + ps + R"(
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                       "t");
    ASSERT_TRUE(r) << ps;
    auto image = r->render();
    ASSERT_TRUE(image) << ps;
    // The centre pixel of the 32x32 image is (16, 16): alpha 16/255.
    EXPECT_EQ(centre(*image), (std::array<int, 4>{255, 255, 0, 16})) << ps;
  }
}

// A skinning palette, float4x3 Bones[4]: each element three registers (48 bytes), and the
// values set for element 1 are what the shader reads there.
TEST_F(EffectStatesTest, MatrixArrayElementsLandWhereTheShaderReadsThem) {
  auto r = bind_text(ctx(), "palette.fx", R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4x3 Bones[4];
struct V { float4 pos : POSITION; float4 color : COLOR0; };
V VS(float4 p : POSITION) { V o; o.pos = mul(p, WorldViewProjection); o.color = float4(Bones[1][0], 1); return o; }
float4 PS(float4 c : COLOR0) : COLOR0 { return c; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                     "t");
  ASSERT_TRUE(r);
  std::vector<float> bones(4 * 12, 0.0f);
  bones[12 + 0] = 0.25f, bones[12 + 1] = 0.5f, bones[12 + 2] = 0.75f;  // element 1, row 0
  ASSERT_TRUE(r->effect->params->set(r->effect->params->find("Bones"), std::span<const float>(bones)));
  auto image = r->render();
  ASSERT_TRUE(image);
  const std::array<int, 4> c = centre(*image);
  EXPECT_NEAR(c[0], 64, 1);
  EXPECT_NEAR(c[1], 128, 1);
  EXPECT_NEAR(c[2], 191, 1);
}

}  // namespace
}  // namespace fx::vk::testing
