// The generated texture stages against the CPU model of the D3D formulas
// (texture_stage_model.h), per operation, per argument register and modifier, with Temp
// and ResultArg, the seed's multi-stage listings, bump environment mapping, specular add,
// fog and the alpha test: rendered on the Vulkan device into a float target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fixed_function_rig.h"
#include "texture_stage_model.h"

namespace fx::vk::testing {
namespace {

using ff_model::Color;

// Tolerance, absolute, per channel. The inputs reach the GPU exactly (texels k/255 from
// UNORM, colours as float vertex attributes); each stage is a few float32 multiplies and
// adds of values <= 4 in magnitude, a few ULPs of 4 (2.4e-7 each); the interpolated colours
// carry the rasterizer's float barycentrics (about 1e-6 here). 1e-4 leaves two orders of
// magnitude over that and is still 39x finer than one 8-bit level (1/255), so a formula
// wrong by a level fails.
constexpr double kTolerance = 1e-4;
constexpr uint32_t kSize = 16;

// The affine colours across the quad (exact under linear interpolation).
Color diffuse_at(double u, double v) { return {u, v, 1 - u, 0.2 + 0.6 * v}; }
Color specular_at(double u, double v) { return {0.5 * v, 1 - v, 0.3 + 0.4 * u, u}; }

std::vector<FixedVertex> screen_quad() {
  auto vertex = [](float x, float y) {
    const float u = (x + 1) / 2, v = (y + 1) / 2;
    const Color d = diffuse_at(u, v), s = specular_at(u, v);
    return FixedVertex{x,
                       y,
                       0.5f,
                       0,
                       0,
                       -1,
                       {float(d[0]), float(d[1]), float(d[2]), float(d[3])},
                       {float(s[0]), float(s[1]), float(s[2]), float(s[3])},
                       u,
                       v};
  };
  const FixedVertex a = vertex(-1, -1), b = vertex(1, -1), c = vertex(1, 1), d = vertex(-1, 1);
  return {a, c, b, a, d, c};
}

class FixedFunctionRender : public VulkanTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(ctx().validation_warning_count(), 0u) << describe_messages(ctx());
    VulkanTest::TearDown();
  }
  static void TearDownTestSuite() {
    std::printf("[ fixed-function ] largest |GPU - CPU model| over every case: %.3g (tolerance %.0e)\n", worst_,
                kTolerance);
    VulkanTest::TearDownTestSuite();
  }

  // Renders `state` with a random texture per sampling stage; compares every pixel and
  // channel with the model. `texel_of` may move a stage's lookup (bump mapping).
  void expect_matches_model(FixedFunctionState state, const std::string& what, uint32_t seed = 1) {
    for (TextureStageState& st : state.stages) st.tex_coord_index = 0;  // every stage reads TEXCOORD0
    std::mt19937 rng(seed);
    FixedFunctionRig rig(ctx(), kSize);
    ASSERT_TRUE(rig.build(state)) << what;
    std::array<fx::Image, kTextureStages> images;
    for (int i = 0; i < kTextureStages; ++i) {
      images[i] = random_image(kSize, rng);
      if (state.stages[i].texture != StageTexture::none && bump_bytes_ && i == 0) bumpify(images[0], rng);
      if (rig.samples(i)) {
        ASSERT_TRUE(rig.bind_texture(i, images[i]));
      }
    }
    if (tfactor_uniform_) {
      ASSERT_TRUE(rig.set_uniform(state.texture_factor.parameter.name.c_str(), state.texture_factor.value.data(), 16));
    }
    const fx::ImageF image = rig.render(screen_quad());
    int ambiguous = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const double u = (x + 0.5) / kSize, v = (y + 0.5) / kSize;
        ff_model::PixelInputs in;
        in.diffuse = diffuse_at(u, v);
        in.specular = specular_at(u, v);
        in.fog = in.specular[3];  // vertex fog mode none: the specular alpha
        for (int i = 0; i < kTextureStages; ++i) in.texel[i] = texel(images[i], x, y);
        if (bump_bytes_) bump(state, images, x, y, in);
        bool passes = true;
        const Color want = ff_model::texture_stages(state, in, &passes);
        const float* got = image.at(x, y);
        if (state.alpha_test) {
          const double a8 = ff_model::sat(want[3]) * 255;
          if (std::fabs(a8 - std::floor(a8) - 0.5) < 1e-3) {  // on a rounding edge: either answer
            ++ambiguous;
            continue;
          }
          ASSERT_EQ(got[0] == -1.0f && got[3] == -1.0f, !passes) << what << " alpha test at " << x << "," << y;
          if (!passes) continue;
        }
        for (int c = 0; c < 4; ++c) {
          const double e = std::fabs(got[c] - want[c]);
          worst_ = std::max(worst_, e);
          ASSERT_LE(e, kTolerance) << what << " at " << x << "," << y << " channel " << c << ": GPU " << got[c]
                                   << ", model " << want[c] << "\n"
                                   << generate_fixed_function_pixel_shader(state).source;
        }
      }
    EXPECT_LE(ambiguous, 2) << what;
  }

  static Color texel(const fx::Image& image, uint32_t x, uint32_t y) {
    const uint8_t* p = image.at(x % image.width, y % image.height);
    return {p[0] / 255.0, p[1] / 255.0, p[2] / 255.0, p[3] / 255.0};
  }

  // Bump map bytes: du, dv either 0 or 255 so the offsets below land on texel centres.
  static void bumpify(fx::Image& image, std::mt19937& rng) {
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = 0; x < image.width; ++x)
        for (int c = 0; c < 2; ++c) image.at(x, y)[c] = (rng() & 1) ? 255 : 0;
  }
  // D3D: u' = u + M00 du + M10 dv, v' = v + M01 du + M11 dv; luminance L = sat(l * LScale +
  // LOffset) scales the next stage's texel colour.
  void bump(const FixedFunctionState& s, const std::array<fx::Image, kTextureStages>& images, uint32_t x, uint32_t y,
            ff_model::PixelInputs& in) const {
    const Color b = in.texel[0];
    const auto& m = s.stages[0].bump_env_mat;
    const double du = b[0], dv = b[1];
    const double ou = (m[0].value * du + m[2].value * dv) * kSize, ov = (m[1].value * du + m[3].value * dv) * kSize;
    const int tx = int(x) + int(std::lround(ou)), ty = int(y) + int(std::lround(ov));
    in.texel[1] = texel(images[1], uint32_t((tx % int(kSize) + int(kSize)) % int(kSize)),
                        uint32_t((ty % int(kSize) + int(kSize)) % int(kSize)));
    if (s.stages[0].color_op == TextureOp::bump_env_map_luminance) {
      const double l = ff_model::sat(b[2] * s.stages[0].bump_env_lscale.value + s.stages[0].bump_env_loffset.value);
      for (int c = 0; c < 3; ++c) in.texel[1][c] *= l;
    }
  }

  bool bump_bytes_ = false;
  bool tfactor_uniform_ = false;
  static inline double worst_ = 0;
};

FixedFunctionState one_stage(TextureOp color, TextureOp alpha, std::array<uint32_t, 3> color_args,
                             std::array<uint32_t, 3> alpha_args) {
  FixedFunctionState s;
  s.lighting = false;
  s.texture_factor.value = {0.3f, 0.65f, 0.9f, 0.45f};
  s.stages[0].color_op = color;
  s.stages[0].alpha_op = alpha;
  s.stages[0].color_arg = color_args;
  s.stages[0].alpha_arg = alpha_args;
  s.stages[0].texture = StageTexture::tex2d;
  s.stages[0].constant.value = {0.8f, 0.1f, 0.55f, 0.7f};
  return s;
}

namespace ta = texture_arg;

TEST_F(FixedFunctionRender, EveryOperationAsColourAndAlphaOperation) {
  for (int op = kTextureOpFirst; op <= kTextureOpLast; ++op) {
    const TextureOp o = static_cast<TextureOp>(op);
    if (o == TextureOp::disable || o == TextureOp::bump_env_map || o == TextureOp::bump_env_map_luminance) continue;
    // Arg1 the texture, Arg2 diffuse, Arg0 specular: three different values per pixel.
    expect_matches_model(
        one_stage(o, o, {ta::specular, ta::texture, ta::diffuse}, {ta::specular, ta::texture, ta::diffuse}),
        to_string(o));
    // And a second stage reading Current, so the result of the first is checked as an input.
    FixedFunctionState s = one_stage(TextureOp::modulate, TextureOp::add, {ta::current, ta::texture, ta::diffuse},
                                     {ta::current, ta::texture, ta::diffuse});
    s.stages[1] = s.stages[0];
    s.stages[1].color_op = s.stages[1].alpha_op = o;
    s.stages[1].color_arg = s.stages[1].alpha_arg = {ta::tfactor, ta::current, ta::texture};
    expect_matches_model(s, std::string("stage 1 ") + to_string(o), 7);
  }
}

TEST_F(FixedFunctionRender, EveryRegisterWithEveryModifier) {
  const uint32_t mods[] = {0, ta::complement, ta::alpha_replicate, ta::complement | ta::alpha_replicate};
  for (uint32_t reg = ta::diffuse; reg <= ta::constant; ++reg)
    for (uint32_t m : mods) {
      // Stage 0 writes Temp (ResultArg) so that Temp and Current differ at stage 1.
      FixedFunctionState s = one_stage(TextureOp::add_smooth, TextureOp::subtract, {0, ta::texture, ta::specular},
                                       {0, ta::texture | ta::complement, ta::diffuse});
      s.stages[0].result_arg = ta::temp;
      s.stages[1] = s.stages[0];
      s.stages[1].result_arg = ta::current;
      s.stages[1].color_op = TextureOp::multiply_add;
      s.stages[1].alpha_op = TextureOp::lerp;
      s.stages[1].color_arg = {ta::tfactor, reg | m, ta::texture};
      s.stages[1].alpha_arg = {reg | m, ta::texture, ta::temp};
      expect_matches_model(s, "register " + std::to_string(reg) + " modifiers " + std::to_string(m), reg * 4 + m);
    }
}

TEST_F(FixedFunctionRender, SeedListings) {
  // DOTPRODUCT3 fallback: ColorOp[0] = DotProduct3 (Texture, Diffuse), ColorOp[1] = Modulate (Texture, Current).
  FixedFunctionState dot3 = one_stage(TextureOp::dot_product3, TextureOp::select_arg1,
                                      {ta::current, ta::texture, ta::diffuse}, {ta::current, ta::texture, ta::current});
  dot3.stages[1] = dot3.stages[0];
  dot3.stages[1].color_op = TextureOp::modulate;
  dot3.stages[1].alpha_op = TextureOp::disable;
  dot3.stages[1].color_arg = {ta::current, ta::texture, ta::current};
  expect_matches_model(dot3, "dot3 fallback");
  // Emboss: SelectArg1 (Texture), then AddSigned (Texture | Complement, Current).
  FixedFunctionState emboss = dot3;
  emboss.stages[0].color_op = TextureOp::select_arg1;
  emboss.stages[1].color_op = TextureOp::add_signed;
  emboss.stages[1].color_arg = {ta::current, ta::texture | ta::complement, ta::current};
  expect_matches_model(emboss, "emboss");
  // Specular emboss: SelectArg1 (Texture), then Subtract (Current, Texture).
  FixedFunctionState specular = emboss;
  specular.stages[1].color_op = TextureOp::subtract;
  specular.stages[1].color_arg = {ta::current, ta::current, ta::texture};
  expect_matches_model(specular, "specular emboss");
}

TEST_F(FixedFunctionRender, PreModulateMultipliesByTheNextStagesTexture) {
  FixedFunctionState s = one_stage(TextureOp::premodulate, TextureOp::premodulate,
                                   {ta::current, ta::texture, ta::current}, {ta::current, ta::texture, ta::current});
  s.stages[1] = one_stage(TextureOp::add, TextureOp::modulate, {ta::current, ta::diffuse, ta::current},
                          {ta::current, ta::texture, ta::current})
                    .stages[0];
  expect_matches_model(s, "PreModulate");
}

TEST_F(FixedFunctionRender, ProjectedCoordinatesAreDividedByTheirLastComponent) {
  // (u, v, 1, 0) * diag(3, 3, 3, 1) = (3u, 3v, 3): only the divide brings the lookup back to
  // texel (x, y) (without it the repeat-addressed lookup lands on texel 3x mod 16).
  FixedFunctionState s = one_stage(TextureOp::select_arg1, TextureOp::select_arg1,
                                   {ta::current, ta::texture, ta::current}, {ta::current, ta::texture, ta::current});
  s.stages[0].texture_transform_flags = 3 | texture_transform::projected;
  s.stages[0].texture_transform.value = {3, 0, 0, 0, 0, 3, 0, 0, 0, 0, 3, 0, 0, 0, 0, 1};
  expect_matches_model(s, "Count3 | Projected");
}

TEST_F(FixedFunctionRender, BumpEnvironmentMapMovesTheNextStagesLookup) {
  bump_bytes_ = true;
  for (TextureOp op : {TextureOp::bump_env_map, TextureOp::bump_env_map_luminance}) {
    // The DirectX 6 listing's shape: a bump stage, then a stage sampling at the moved coordinates.
    FixedFunctionState s = one_stage(op, TextureOp::disable, {ta::current, ta::texture, ta::current},
                                     {ta::current, ta::texture, ta::current});
    const float t = 1.0f / kSize;
    s.stages[0].bump_env_mat = {FixedScalar{2 * t, {}}, FixedScalar{-t, {}}, FixedScalar{t, {}},
                                FixedScalar{3 * t, {}}};
    s.stages[0].bump_env_lscale.value = 1.5f;
    s.stages[0].bump_env_loffset.value = -0.2f;
    s.stages[1] = one_stage(TextureOp::add, TextureOp::select_arg1, {ta::current, ta::texture, ta::diffuse},
                            {ta::current, ta::texture, ta::current})
                      .stages[0];
    expect_matches_model(s, to_string(op));
  }
}

TEST_F(FixedFunctionRender, SpecularFogAndAlphaTest) {
  FixedFunctionState s = one_stage(TextureOp::modulate, TextureOp::select_arg2, {ta::current, ta::texture, ta::diffuse},
                                   {ta::current, ta::texture, ta::diffuse});
  s.specular_enable = true;
  expect_matches_model(s, "specular add");
  s.fog = true;
  s.fog_color.value = {0.2f, 0.4f, 0.9f, 1.0f};
  expect_matches_model(s, "fog from the specular alpha");
  for (int f = 0; f <= 7; ++f) {
    s.alpha_test = true;
    s.alpha_func = static_cast<CompareOp>(f);
    s.alpha_ref.value = 128;
    expect_matches_model(s, "alpha test " + std::to_string(f));
  }
}

TEST_F(FixedFunctionRender, TextureFactorBoundToAParameterIsRead) {
  FixedFunctionState s = one_stage(TextureOp::modulate, TextureOp::select_arg2, {ta::current, ta::texture, ta::tfactor},
                                   {ta::current, ta::texture, ta::tfactor});
  // Named as the cascade's register would be in HLSL: the generated locals must not hide it.
  s.texture_factor.parameter = {"current", "float4"};
  s.texture_factor.value = {0.25f, 0.5f, 0.75f, 0.6f};  // uploaded to the parameter, not a literal
  tfactor_uniform_ = true;
  expect_matches_model(s, "TextureFactor = <current>");
  EXPECT_EQ(generate_fixed_function_pixel_shader(s).source.find("0.75"), std::string::npos);
}

TEST_F(FixedFunctionRender, BesideAnHlslVertexShaderTheStagesReadWhatItWrites) {
  // The vertex shader writes a three-component diffuse, TEXCOORD1 as float2 and TEXCOORD3
  // (read by no stage), and no specular, TEXCOORD0 or fog: those read D3D's defaults
  // (specular 0, coordinates (0, 0, 0, 1), fog 1) and the diffuse alpha is 1.
  const char* vertex_shader = R"(
struct Out { float4 position : POSITION; float3 colour : COLOR0; float2 uv : TEXCOORD1; float4 other : TEXCOORD3; };
Out VS(float3 p : POSITION, float2 uv : TEXCOORD0) {
  Out o;
  o.position = float4(p, 1);
  o.colour = float3(uv, 1 - uv.x);
  o.uv = uv;
  o.other = float4(uv, 0, 1);
  return o;
})";
  FixedFunctionState s;
  s.vertex_shader = true;
  s.vertex_shader_outputs.known = true;
  s.vertex_shader_outputs.diffuse = 3;
  s.vertex_shader_outputs.texcoords[1] = 2;
  s.vertex_shader_outputs.texcoords[3] = 4;
  TextureStageState& st0 = s.stages[0];
  st0.texture = StageTexture::tex2d;
  st0.tex_coord_index = 1;
  st0.color_op = TextureOp::modulate;
  st0.color_arg = {ta::current, ta::texture, ta::diffuse};
  st0.alpha_op = TextureOp::select_arg1;
  st0.alpha_arg = {ta::current, ta::diffuse, ta::current};
  TextureStageState& st1 = s.stages[1];
  st1.texture = StageTexture::tex2d;
  st1.tex_coord_index = 0;
  st1.color_op = TextureOp::multiply_add;  // specular + current * texture
  st1.color_arg = {ta::specular, ta::current, ta::texture};
  st1.alpha_op = TextureOp::subtract;  // current - specular
  st1.alpha_arg = {ta::current, ta::current, ta::specular};
  s.fog = true;
  s.fog_color.value = {0.9f, 0.1f, 0.1f, 1.0f};
  const std::string ps = generate_fixed_function_pixel_shader(s).source;
  for (const char* unread : {"COLOR1", "TEXCOORD0", "FOG"})
    EXPECT_EQ(ps.find(unread), std::string::npos) << unread << "\n" << ps;
  EXPECT_NE(ps.find("float3 fx_diffuse : COLOR0"), std::string::npos) << ps;
  EXPECT_NE(ps.find("float4 fx_tc3 : TEXCOORD3"), std::string::npos) << ps;

  std::mt19937 rng(7);
  FixedFunctionRig rig(ctx(), kSize);
  ASSERT_TRUE(rig.build(s, {}, vertex_shader));
  const fx::Image texture0 = random_image(kSize, rng), texture1 = random_image(4, rng);
  ASSERT_TRUE(rig.bind_texture(0, texture0));
  ASSERT_TRUE(rig.bind_texture(1, texture1));
  const fx::ImageF image = rig.render(screen_quad());
  ASSERT_EQ(image.width, kSize);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const double u = (x + 0.5) / kSize, v = (y + 0.5) / kSize;
      ff_model::PixelInputs in;
      in.diffuse = {u, v, 1 - u, 1};
      in.specular = {0, 0, 0, 0};
      in.texel[0] = texel(texture0, x, y);
      in.texel[1] = texel(texture1, 0, 0);  // TEXCOORD0 unwritten: (0, 0)
      in.fog = 1;
      const Color want = ff_model::texture_stages(s, in);
      for (int c = 0; c < 4; ++c) {
        const double e = std::fabs(image.at(x, y)[c] - want[c]);
        worst_ = std::max(worst_, e);
        ASSERT_LE(e, kTolerance) << x << "," << y << " channel " << c << ": GPU " << image.at(x, y)[c] << ", model "
                                 << want[c] << "\n"
                                 << ps;
      }
    }
}

}  // namespace
}  // namespace fx::vk::testing
