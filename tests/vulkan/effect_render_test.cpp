// Seed effects rendered through EffectBinding on the validated device: golden images,
// every technique of every effect, and the dynamic and static pipeline paths agreeing.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "effect_test_util.h"

namespace fx::vk::testing {
namespace {

class EffectRenderTest : public VulkanTest {
 protected:
  // Renders technique T of `source` (written to a temporary file) at 32x32 with no new
  // validation message; returns the centre pixel (RGBA).
  std::array<uint8_t, 4> centre_of(const std::string& name, const std::string& source) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / (name + ".fx");
    std::ofstream(file) << source;
    auto r = bind_effect(ctx(), file.string(), "T", "sphere", 32);
    std::filesystem::remove(file);
    EXPECT_TRUE(r);
    if (!r) return {};
    const size_t errors = ctx().validation_error_count();
    auto image = r->render();
    EXPECT_TRUE(image);
    EXPECT_EQ(ctx().validation_error_count(), errors) << describe_messages(ctx());
    if (!image) return {};
    const uint8_t* p = &image->pixels[(16 * image->width + 16) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
};

struct GoldenCase {
  const char* file;
  const char* technique;
  const char* mesh;
  const char* golden;
  const char* float_param = nullptr;  // one float parameter set before rendering
  float value = 0;
};

const GoldenCase kGoldenCases[] = {
    {"strand_aniso.fx", "strand_lut", "sphere", "strand_lut_sphere"},
    {"strand_aniso.fx", "strand_analytic", "torus", "strand_analytic_torus"},
    {"hemisphere.fx", "hemisphere_two_term", "teapot", "hemisphere_two_term_teapot"},
    {"hemisphere.fx", "hemisphere_sun", "sphere", "hemisphere_sun_sphere"},
    {"wood.fx", "wood", "teapot", "wood_teapot"},
    // The default turbulence (1.0, noise period 1/8 unit) scrambles the rings on a unit
    // sphere; at 0.08 the concentric rings around x show as the seed describes.
    {"wood.fx", "wood", "sphere", "wood_rings_sphere", "turbulence", 0.08f},
    {"brdf.fx", "brdf_ps20", "sphere", "brdf_ps20_sphere"},
    {"aniso_lut_ward.fx", "gaussian_per_pixel", "sphere", "ward_gaussian_sphere"},
    {"per_pixel_lighting.fx", "specular_pow_ps20", "sphere", "ppl_specular_pow_sphere"},
    {"aniso_highlights_glsl.fx", "aniso_blinn_phong", "torus", "glsl_aniso_blinn_phong_torus"},
};

TEST_F(EffectRenderTest, SeedEffectsMatchGoldenImages) {
  for (const GoldenCase& c : kGoldenCases) {
    SCOPED_TRACE(c.golden);
    auto r = bind_effect(ctx(), effects_dir() + "/" + c.file, c.technique, c.mesh, 128);
    ASSERT_TRUE(r);
    if (c.float_param) {
      ASSERT_TRUE(r->effect->params->set(r->effect->params->find(c.float_param), c.value));
    }
    auto image = r->render();
    ASSERT_TRUE(image);
    // Not a blank frame: the object covers a good part of the image.
    const uint8_t* corner = image->at(0, 0);
    size_t covered = 0;
    for (uint32_t y = 0; y < image->height; ++y)
      for (uint32_t x = 0; x < image->width; ++x) covered += std::memcmp(image->at(x, y), corner, 3) != 0;
    EXPECT_GT(covered, image->width * image->height / 6);
    expect_golden(*image, c.golden);
  }
}

// Every technique of every effect either renders without a validation message or says
// why it cannot (shader model 1 assembly is translated to HLSL and the fixed-function
// stages are generated, so the seeds' techniques all render).
TEST_F(EffectRenderTest, EveryEffectTechniqueRendersOrHasAReason) {
  size_t rendered = 0, skipped = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(effects_dir())) {
    if (entry.path().extension() != ".fx") continue;
    SCOPED_TRACE(entry.path().string());
    auto r = bind_effect(ctx(), entry.path().string(), "", "sphere", 48);
    ASSERT_TRUE(r);
    for (uint32_t t = 0; t < r->binding->technique_count(); ++t) {
      SCOPED_TRACE(r->effect->model->techniques[t].name);
      if (!r->binding->technique_ok(t)) {
        EXPECT_FALSE(r->binding->technique_reason(t).empty());
        ++skipped;
        continue;
      }
      r->use_technique(t);
      const size_t errors = ctx().validation_error_count();
      EXPECT_TRUE(r->render());
      EXPECT_EQ(ctx().validation_error_count(), errors) << describe_messages(ctx());
      ++rendered;
    }
  }
  EXPECT_GE(rendered, 25u);
  EXPECT_EQ(skipped, 0u);
}

TEST_F(EffectRenderTest, DynamicAndStaticPipelinePathsGiveIdenticalImages) {
  for (const char* technique : {"strand_bump_renormalized", "strand_four_lights"}) {
    SCOPED_TRACE(technique);
    auto dynamic = bind_effect(ctx(), effects_dir() + "/strand_aniso.fx", technique, "torus", 96,
                               DynamicStateSet::from_features(ctx().features()));
    auto fixed =
        bind_effect(ctx(), effects_dir() + "/strand_aniso.fx", technique, "torus", 96, DynamicStateSet::none());
    ASSERT_TRUE(dynamic && fixed);
    auto a = dynamic->render(), b = fixed->render();
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->pixels, b->pixels);
    EXPECT_GT(dynamic->binding->stats().dynamic_state_calls, fixed->binding->stats().dynamic_state_calls);
  }
}

// A parameter set between frames is packed into its block and changes the picture.
TEST_F(EffectRenderTest, ParameterChangesReachTheImage) {
  auto r = bind_effect(ctx(), effects_dir() + "/hemisphere.fx", "hemisphere_two_term", "sphere", 48);
  ASSERT_TRUE(r);
  auto first = r->render();
  const uint64_t uploads = r->binding->stats().uniform_uploads;
  EXPECT_GT(uploads, 0u);
  auto again = r->render();
  ASSERT_TRUE(first && again);
  EXPECT_EQ(first->pixels, again->pixels);
  Param sky = r->effect->params->find("SkyColor");
  const float red[4] = {1, 0, 0, 1};
  ASSERT_TRUE(r->effect->params->set(sky, std::span<const float>(red)));
  auto changed = r->render();
  ASSERT_TRUE(changed);
  EXPECT_NE(first->pixels, changed->pixels);
}

// A D3D9 sampler array: every element is written to the descriptor set (an unwritten one
// is undefined to sample; lavapipe crashed reading it), all bound to the first element's
// texture, here the white stand-in.
TEST_F(EffectRenderTest, SamplerArrayElementsAreAllBound) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_sampler_array", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture a;
texture b;
sampler s[2] = { sampler_state { Texture = <a>; }, sampler_state { Texture = <b>; } };
float4 VS(float4 p : POSITION, float2 uv : TEXCOORD0, out float2 t : TEXCOORD0) : POSITION {
  t = uv;
  return mul(p, WorldViewProjection);
}
float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(s[1], uv) * 0.5 + tex2D(s[0], uv) * 0.25; }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  EXPECT_NEAR(centre[0], 191, 2);  // white * 0.5 + white * 0.25
}

// Depth comparison (a shadow map lookup) with no depth texture: Vulkan compares only against
// depth formats, so a depth of 1.0 stands in, in a format and with a filter the device
// allows; the colour stand-in was a validation error and undefined.
TEST_F(EffectRenderTest, ComparisonSamplingWithoutADepthTextureSeesNothingInShadow) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_comparison", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
Texture2D ShadowMap;
SamplerComparisonState ShadowSampler { ComparisonFunc = LESS; Filter = COMPARISON_MIN_MAG_MIP_LINEAR; };
struct V { float4 p : SV_Position; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V o; o.p = mul(p, WorldViewProjection); o.uv = uv; return o; }
float4 PS(V i) : SV_Target {
  float lit = ShadowMap.SampleCmpLevelZero(ShadowSampler, i.uv, 0.5);
  return float4(lit, lit * 0.5, 0, 1);
}
technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)");
  EXPECT_EQ(centre[0], 255);  // 0.5 < 1.0: lit
  EXPECT_NEAR(centre[1], 128, 1);
}

// The same lookup through a helper function: glslang types the texture parameter, not the
// global, as a depth image, so the global was reflected as a colour texture, given a colour
// stand-in, and the comparison was a validation error (VUID-vkCmdDrawIndexed-None-06479).
TEST_F(EffectRenderTest, ComparisonSamplerHandedToAHelperFunctionComparesAgainstDepth) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_comparison_helper", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
Texture2D ShadowMap;
SamplerComparisonState ShadowSampler { ComparisonFunc = LESS; Filter = COMPARISON_MIN_MAG_MIP_LINEAR; };
float Shadow(SamplerComparisonState s, Texture2D t, float2 uv, float depth) { return t.SampleCmpLevelZero(s, uv, depth); }
struct V { float4 p : SV_Position; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V o; o.p = mul(p, WorldViewProjection); o.uv = uv; return o; }
float4 PS(V i) : SV_Target {
  float lit = Shadow(ShadowSampler, ShadowMap, i.uv, 0.5);
  return float4(lit, lit * 0.5, 0, 1);
}
technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)");
  EXPECT_EQ(centre[0], 255);  // 0.5 < 1.0: lit
  EXPECT_NEAR(centre[1], 128, 1);
}

// `float2 Offsets[] = { ... };` takes its size from its initializer, as fxc sizes it (it
// was bad-array-size at render while check called it clean), and its values reach the shader.
TEST_F(EffectRenderTest, UnsizedArrayParameterIsSizedByItsInitializer) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_unsized_array", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float2 Offsets[] = { float2(0.2, 0.4), float2(0.0, 0.0), float2(0.6, 0.8) };
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return float4(Offsets[0].x, Offsets[2].y, Offsets[1].x, 1); }
technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)");
  EXPECT_NEAR(centre[0], 51, 1);   // 0.2
  EXPECT_NEAR(centre[1], 204, 1);  // 0.8
  EXPECT_EQ(centre[2], 0);
}

// "Simulate, then draw": a compute pass writes a structured buffer (a zeroed stand-in) and
// the draw after it reads what it wrote, ordered by the barrier dispatch() records. Without
// the compute pass the buffer holds zeros and the sphere is black.
TEST_F(EffectRenderTest, ComputePassWritesAStructuredBufferALaterDrawReads) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_compute_buffer", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
RWStructuredBuffer<float4> Colors;
[numthreads(4, 1, 1)] void Simulate(uint3 id : SV_DispatchThreadID) {
  Colors[id.x] = float4(0.25 * id.x, 1, 0.5, 1);
}
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return Colors[2]; }
technique11 T {
  pass Simulate < int3 Dispatch = {1, 1, 1}; > { SetComputeShader(CompileShader(cs_5_0, Simulate())); }
  pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
}
)");
  EXPECT_NEAR(centre[0], 128, 1);  // element 2 of the 4 the dispatch wrote
  EXPECT_EQ(centre[1], 255);
  EXPECT_NEAR(centre[2], 128, 1);
}

// A pass that sets a compute shader beside its vertex and pixel shaders (FX11 binds all three
// at Apply): a preview dispatches it before it draws the pass, as it does a compute pass.
TEST_F(EffectRenderTest, APassWithComputeBesideGraphicsShadersDispatchesThenDraws) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_compute_beside_graphics", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
RWStructuredBuffer<float4> Colors;
[numthreads(4, 1, 1)] void Simulate(uint3 id : SV_DispatchThreadID) { Colors[id.x] = float4(0.25 * id.x, 1, 0.5, 1); }
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return Colors[2]; }
technique11 T { pass P < int3 Dispatch = {1, 1, 1}; > {
  SetVertexShader(CompileShader(vs_5_0, VS()));
  SetPixelShader(CompileShader(ps_5_0, PS()));
  SetComputeShader(CompileShader(cs_5_0, Simulate()));
} }
)");
  EXPECT_NEAR(centre[0], 128, 1);  // element 2 of the 4 the dispatch wrote
  EXPECT_EQ(centre[1], 255);
  EXPECT_NEAR(centre[2], 128, 1);
}

// fxc's asuint(double, out uint, out uint) gives the exact bits of a double (fxkit defines the
// overload glslang lacks): hard cases, each built from its bits or computed in double, must
// give back those bits. The sphere is green when every case does, red otherwise.
TEST_F(EffectRenderTest, AsuintOfADoubleGivesItsExactBits) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_asuint_double", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
RWStructuredBuffer<float4> Result;
bool Same(double d, uint low, uint high) {
  uint l, h;
  asuint(d, l, h);
  return l == low && h == high;
}
[numthreads(1, 1, 1)] void Check(uint3 id : SV_DispatchThreadID) {
  double ten = 10.0;
  bool ok = Same(3.0 / (ten - 8.0), 0u, 0x3FF80000u)              // 1.5
         && Same(-1.0 / ten, 0x9999999Au, 0xBFB99999u)          // -0.1, rounded to nearest
         && Same(0.0, 0u, 0u) && Same(asdouble(0u, 0x80000000u), 0u, 0x80000000u)
         && Same(asdouble(0x54442D18u, 0x400921FBu), 0x54442D18u, 0x400921FBu)  // pi
         && Same(asdouble(0xFFFFFFFFu, 0x7FEFFFFFu), 0xFFFFFFFFu, 0x7FEFFFFFu)  // largest finite
         && Same(asdouble(0u, 0x00100000u), 0u, 0x00100000u)    // smallest normal
         && Same(asdouble(1u, 0x3FF00000u), 1u, 0x3FF00000u)    // 1 + 2^-52
         && Same(asdouble(0u, 0xFFF00000u), 0u, 0xFFF00000u)    // -infinity
         && Same(asdouble(0u, 0x7FF80000u), 0u, 0x7FF80000u)    // NaN
         && Same(asdouble(0x8800759Cu, 0x7E37E43Cu), 0x8800759Cu, 0x7E37E43Cu);  // 1e300
  Result[0] = ok ? float4(0, 1, 0, 1) : float4(1, 0, 0, 1);
}
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return Result[0]; }
technique11 T {
  pass Check { SetComputeShader(CompileShader(cs_5_0, Check())); }
  pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
}
)");
  EXPECT_EQ(centre[0], 0);
  EXPECT_EQ(centre[1], 255);
}

// vvvv's Softedge.fx form: a bool varying (carried as uint between the stages, as fxc
// carries it) true on every vertex, and a float1 member written through `.x`, reach the
// pixel shader: the sphere is (0.75, 1, 0).
TEST_F(EffectRenderTest, BoolVaryingAndOneComponentSwizzleReachThePixelShader) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_bool_varying", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct V { float4 p : SV_Position; float1 u : TEXCOORD0; bool on : TEXCOORD1; };
V VS(float4 p : POSITION) { V o; o.p = mul(p, WorldViewProjection); o.u.x = 0.75; o.on = p.w > 0; return o; }
float4 PS(V i) : SV_Target { return i.on ? float4(i.u.x, 1, 0, 1) : float4(0, 0, 1, 1); }
technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)");
  EXPECT_NEAR(centre[0], 191, 1);
  EXPECT_EQ(centre[1], 255);
  EXPECT_EQ(centre[2], 0);
}

// A geometry shader that takes the vertex struct with its SV_ClipDistance member and passes
// it on (glslang#2392's form, rewritten by the unit) clips: the half of the sphere below the
// plane y = 0 is not drawn, the half above is.
TEST_F(EffectRenderTest, GeometryShaderPassesClipDistancesOn) {
  const std::filesystem::path file = std::filesystem::path(FXKIT_SOURCE_DIR) /
                                     "tests/compile/data/fxc_accepts/geometry_shader_reading_clip_distances.fx";
  auto r = bind_effect(ctx(), file.string(), "ClipThroughTheGeometryShader", "sphere", 32);
  ASSERT_TRUE(r);
  const size_t errors = ctx().validation_error_count();
  auto image = r->render();
  ASSERT_TRUE(image);
  EXPECT_EQ(ctx().validation_error_count(), errors) << describe_messages(ctx());
  auto red = [&](uint32_t y) { return image->pixels[(y * image->width + 16) * 4]; };
  EXPECT_GT(red(10), 100);  // above the plane: the orange surface
  EXPECT_LT(red(24), 60);   // below it: the clear colour
}

// A compute pass writes an RWTexture2D (a stand-in the size of the target, one thread per
// pixel by default) that the pixel shader then reads at its own pixel.
TEST_F(EffectRenderTest, ComputePassWritesAStorageImageThePixelShaderReads) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_compute_image", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
RWTexture2D<float4> Canvas;
[numthreads(8, 8, 1)] void Paint(uint3 id : SV_DispatchThreadID) {
  Canvas[id.xy] = float4(id.x / 32.0, 0.75, id.y / 32.0, 1);
}
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS(float4 pos : SV_Position) : SV_Target { return Canvas[uint2(pos.xy)]; }
technique11 T {
  pass Paint { SetComputeShader(CompileShader(cs_5_0, Paint())); }
  pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
}
)");
  EXPECT_NEAR(centre[0], 128, 1);  // x = 16 of 32
  EXPECT_NEAR(centre[1], 191, 1);
  EXPECT_NEAR(centre[2], 128, 1);
}

// Storage images of every other shape get stand-ins too: an RWTexture1D (target-wide), an
// RWTexture3D (target-sized, EffectStorage::kStandInLayers deep), an RWTexture1DArray and an
// RWTexture2DArray (kStandInLayers layers), each written at one texel by a compute pass and
// read back by the pixel shader.
TEST_F(EffectRenderTest, ComputePassWritesOneDThreeDAndArrayStorageImageStandIns) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_compute_image_shapes", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
RWTexture1D<float4> Line;
RWTexture3D<float4> Volume;
RWTexture1DArray<float4> Lines;
RWTexture2DArray<float4> Layers;
[numthreads(1, 1, 1)] void Paint() {
  Line[5] = float4(0.25, 0, 0, 0);
  Volume[uint3(1, 2, 3)] = float4(0, 0.5, 0, 0);
  Lines[uint2(3, 1)] = float4(0, 0, 0.25, 0);
  Layers[uint3(4, 5, 2)] = float4(0, 0, 0.5, 0);
}
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target {
  return float4(Line[5].r, Volume[uint3(1, 2, 3)].g, Lines[uint2(3, 1)].b + Layers[uint3(4, 5, 2)].b, 1);
}
technique11 T {
  pass Paint < int3 Dispatch = {1, 1, 1}; > { SetComputeShader(CompileShader(cs_5_0, Paint())); }
  pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
}
)");
  EXPECT_NEAR(centre[0], 64, 1);   // Line[5].r = 0.25
  EXPECT_NEAR(centre[1], 128, 1);  // Volume[1, 2, 3].g = 0.5
  EXPECT_NEAR(centre[2], 191, 1);  // 0.25 from layer 1 of Lines, 0.5 from layer 2 of Layers
}

// Texel buffers: an RWBuffer<float4> (a storage texel buffer, a zeroed stand-in in
// R32G32B32A32_SFLOAT) written by a compute pass and read by the pixel shader, beside a
// Buffer<float4> (a uniform texel buffer) that holds zeros.
TEST_F(EffectRenderTest, ComputePassWritesATexelBufferThePixelShaderReads) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_compute_texel", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
RWBuffer<float4> Written;
Buffer<float4> Zeros;
[numthreads(4, 1, 1)] void Fill(uint3 id : SV_DispatchThreadID) { Written[id.x] = float4(0.25 * id.x, 0.5, 1, 1); }
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target { return Written[1] + Zeros[0]; }
technique11 T {
  pass Fill < int3 Dispatch = {1, 1, 1}; > { SetComputeShader(CompileShader(cs_5_0, Fill())); }
  pass Draw { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
}
)");
  EXPECT_NEAR(centre[0], 64, 1);  // Written[1] = (0.25, 0.5, 1)
  EXPECT_NEAR(centre[1], 128, 1);
  EXPECT_EQ(centre[2], 255);
}

// A multisampled texture read with Load(coord, sample): the stand-in is a multisampled image
// (a single-sample one is a validation error), every sample cleared white.
TEST_F(EffectRenderTest, MultisampledTextureLoadsReadAMultisampledStandIn) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_multisampled", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
Texture2DMS<float4, 4> Colour;
Texture2DMSArray<float4, 4> Layers;
struct V { float4 p : SV_Position; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V o; o.p = mul(p, WorldViewProjection); o.uv = uv; return o; }
float4 PS(V i) : SV_Target {
  float4 c = Colour.Load(int2(0, 0), 1) * 0.5 + Layers.Load(int3(0, 0, 0), 0) * 0.25;
  return float4(c.rgb, 1);
}
technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_1, PS())); } }
)");
  EXPECT_NEAR(centre[0], 191, 2);  // white * 0.5 + white * 0.25
}

// Texture2D<uint> and <int> read with Load need views of integer formats (a float stand-in is
// VUID-07753): zeros stand in, as Direct3D 11 reads zeros from an unbound view, in every shape.
TEST_F(EffectRenderTest, IntegerTexturesReadZerosFromIntegerStandIns) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_integer_textures", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
Texture2D<uint> Counts;
Texture2DArray<int4> Offsets;
Texture3D<uint2> Cells;
Texture1D<int> Row;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, WorldViewProjection); }
float4 PS() : SV_Target {
  uint n = Counts.Load(int3(0, 0, 0)) + Cells.Load(int4(0, 0, 0, 0)).y;
  int m = Offsets.Load(int4(0, 0, 0, 0)).w + Row.Load(int2(0, 0));
  return float4(n == 0 ? 1 : 0, m == 0 ? 1 : 0, 0.5, 1);
}
technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)");
  EXPECT_EQ(centre[0], 255);
  EXPECT_EQ(centre[1], 255);
  EXPECT_NEAR(centre[2], 128, 1);
}

// Defaults of cbuffer members inside arrays of structs and structs inside structs reach the
// shader: an array inside a struct has std140's 16-byte stride (glslang's reflection said 4,
// so scale[1] read 0).
TEST_F(EffectRenderTest, StructMembersOfACbufferReachTheShader) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_struct_members", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct Light { float3 direction; float4 colour; };
struct Rig { Light key; float scale[2]; };
cbuffer Lights {
  Light g_lights[2] = { { float3(0, 0, 1), float4(0.25, 0, 0, 1) }, { float3(0, 1, 0), float4(0, 0.5, 0, 1) } };
  Rig g_rig = { { float3(1, 0, 0), float4(0, 0, 0.75, 1) }, { 0.5, 2 } };
};
int g_index = 1;
struct V { float4 p : SV_Position; };
V VS(float4 p : POSITION) { V o; o.p = mul(p, WorldViewProjection); return o; }
float4 PS(V i) : SV_Target {
  return float4(g_lights[0].colour.r, g_lights[g_index].colour.g, g_rig.key.colour.b * g_rig.scale[1] * 0.5, 1);
}
technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)");
  EXPECT_NEAR(centre[0], 64, 1);
  EXPECT_NEAR(centre[1], 128, 1);
  EXPECT_NEAR(centre[2], 191, 1);
}

// SV_ClipDistance needs shaderClipDistance enabled on the device (creating the module was a
// validation error without it); a negative distance clips the whole sphere away.
TEST_F(EffectRenderTest, ClipDistancesClipWhereTheDeviceHasTheFeature) {
  if (!ctx().features().has_shader_feature("shaderClipDistance")) GTEST_SKIP() << "no shaderClipDistance";
  auto effect = [](const char* distance) {
    return std::string(R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct V { float4 p : SV_Position; float clip : SV_ClipDistance0; };
V VS(float4 p : POSITION) { V o; o.p = mul(p, WorldViewProjection); o.clip = )") +
           distance + R"(; return o; }
float4 PS(V i) : SV_Target { return float4(1, 0.5, 0, 1); }
technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)";
  };
  const std::array<uint8_t, 4> kept = centre_of("fxkit_clip_kept", effect("1"));
  EXPECT_EQ(kept[0], 255);
  EXPECT_NEAR(kept[1], 128, 1);
  const std::array<uint8_t, 4> clipped = centre_of("fxkit_clip_clipped", effect("-1"));
  EXPECT_NE(clipped[0], 255) << "the sphere was not clipped";
}

// A Direct3D 10 geometry shader that emits points writes no point size (Direct3D 10 has
// none): valid only while the context leaves shaderTessellationAndGeometryPointSize off.
TEST_F(EffectRenderTest, GeometryShaderPointsNeedNoPointSize) {
  if (!ctx().features().geometry_shader) GTEST_SKIP() << "no geometryShader";
  centre_of("fxkit_gs_points", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct V { float4 p : SV_Position; };
V VS(float4 p : POSITION) { V o; o.p = mul(p, WorldViewProjection); return o; }
[maxvertexcount(1)]
void GS(triangle V input[3], inout PointStream<V> points) { points.Append(input[0]); }
float4 PS(V i) : SV_Target { return 1; }
technique10 T { pass P {
  SetVertexShader(CompileShader(vs_4_0, VS()));
  SetGeometryShader(CompileShader(gs_4_0, GS()));
  SetPixelShader(CompileShader(ps_4_0, PS()));
} }
)");
}

// A pixel shader reading a float4 TEXCOORD0 the vertex shader writes as a float2 (D3D9
// code does; `_centroid` names the same register): the missing components read 0 and 1,
// and the validation layer sees them written.
TEST_F(EffectRenderTest, NarrowVaryingsReadPaddedComponents) {
  const std::array<uint8_t, 4> centre =
      centre_of("fxkit_narrow_varyings", R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct V { float4 p : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION) { V o; o.p = mul(p, WorldViewProjection); o.uv = float2(0.5, 0.5); return o; }
float4 PS(float4 uv : TEXCOORD0_centroid) : COLOR0 { return float4(uv.x, uv.z, uv.w, 1); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  EXPECT_NEAR(centre[0], 128, 1);
  EXPECT_EQ(centre[1], 0);
  EXPECT_EQ(centre[2], 255);
}

// fx_5_0 class linkage bound statically: BindInterfaces names a class instance, so the pass
// runs that instance's class; the same shader bound to the other instance draws the other.
TEST_F(EffectRenderTest, BindInterfacesToAClassInstanceRunsThatClass) {
  auto effect = [](const std::string& instance) {
    return R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
interface iColour { float3 Colour(float3 base); };
class cRed : iColour { float3 Colour(float3 base) { return base.xyz; } };
class cGreen : iColour { float3 Colour(float3 base) { return base.zxy; } };
cRed g_red;
cGreen g_green;
struct V { float4 p : SV_Position; };
V VS(float4 p : POSITION) { V o; o.p = mul(p, WorldViewProjection); return o; }
float4 PS(V i, iColour colour) : SV_Target { return float4(colour.Colour(float3(1, 0, 0)), 1); }
technique11 T { pass P {
  SetVertexShader(CompileShader(vs_5_0, VS()));
  SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), )" +
           instance + R"());
} }
)";
  };
  const std::array<uint8_t, 4> red = centre_of("fxkit_bound_red", effect("g_red"));
  const std::array<uint8_t, 4> green = centre_of("fxkit_bound_green", effect("g_green"));
  EXPECT_EQ(red, (std::array<uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(green, (std::array<uint8_t, 4>{0, 255, 0, 255}));
}

}  // namespace
}  // namespace fx::vk::testing
