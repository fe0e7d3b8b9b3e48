// Generated fixed-function vertex processing against the CPU model of the D3D lighting and
// fog formulas (vertex_lighting_model.h): transformed positions and normals, a directional,
// a point and a spot light with every material colour source, ambient, specular and vertex
// fog, per vertex, interpolated across the quad and drawn into a float target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../model/model_test_util.h"
#include "fixed_function_rig.h"
#include "vertex_lighting_model.h"

namespace fx::vk::testing {
namespace {

using ff_model::Color;
using ff_model::Vec3;

// Tolerance: as the texture stages' (1e-4) and for the same reasons; lighting adds pow
// (exp2(p log2 x) in float, a few ULPs relative) and normalisations, which stay within it.
constexpr double kTolerance = 1e-4;
constexpr uint32_t kSize = 16;

// 90 degrees about z (x, y) -> (-y, x), then z scaled by 2: normals need the inverse transpose.
const std::array<float, 16> kWorld = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1};
const std::array<float, 16> kView = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1};           // camera 5 units back
const std::array<float, 16> kProjection = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.1f, 0, 0, 0, 0, 1};  // z 5 -> 0.5, w 1

// The quad's corners: screen corner (X, Y) comes from object (Y, -X) through kWorld.
struct Corner {
  float x, y;
  Vec3 normal;
};
const Corner kCorners[4] = {
    {-1, -1, {0.3, 0.2, -1}}, {1, -1, {-0.4, 0.1, -1}}, {1, 1, {0.2, -0.5, -1}}, {-1, 1, {-0.1, -0.3, -1}}};

ff_model::VertexIn vertex_in(const Corner& c) {
  const double u = (c.x + 1) / 2, v = (c.y + 1) / 2;
  return {{c.y, -c.x, 0}, c.normal, {u, v, 1 - u, 0.2 + 0.6 * v}, {0.5 * v, 1 - v, 0.3 + 0.4 * u, u}};
}

FixedVertex fixed_vertex(const ff_model::VertexIn& in, const Corner& c) {
  return {float(in.position[0]),
          float(in.position[1]),
          float(in.position[2]),
          float(in.normal[0]),
          float(in.normal[1]),
          float(in.normal[2]),
          {float(in.diffuse[0]), float(in.diffuse[1]), float(in.diffuse[2]), float(in.diffuse[3])},
          {float(in.specular[0]), float(in.specular[1]), float(in.specular[2]), float(in.specular[3])},
          (c.x + 1) / 2,
          (c.y + 1) / 2};
}

// The quad's triangles: a = 0 (u 0, v 0), b = 1 (1, 0), c = 2 (1, 1), d = 3 (0, 1) as a c b and a d c.
std::vector<FixedVertex> quad(const std::array<FixedVertex, 4>& v) { return {v[0], v[2], v[1], v[0], v[3], v[2]}; }

// The corners' barycentric weights at pixel (x, y)'s centre, in the triangle holding it
// (linear interpolation: w is 1 everywhere).
std::array<double, 4> corner_weights(uint32_t x, uint32_t y) {
  const double u = (x + 0.5) / kSize, w = (y + 0.5) / kSize;
  return u >= w ? std::array<double, 4>{1 - u, u - w, w, 0} : std::array<double, 4>{1 - w, 0, u, w - u};
}

// The corners processed by the CPU model and the quad drawn with the generated shaders (or
// the generated vertex shader and `pixel_shader`).
struct DrawnQuad {
  std::array<ff_model::VertexOut, 4> corners;
  fx::ImageF image;
};
DrawnQuad draw_quad(Context& ctx, const FixedFunctionState& s, const std::string& pixel_shader = {}) {
  DrawnQuad q;
  FixedFunctionRig rig(ctx, kSize);
  EXPECT_TRUE(rig.build(s, pixel_shader));
  std::array<FixedVertex, 4> v;
  for (int i = 0; i < 4; ++i) {
    const ff_model::VertexIn in = vertex_in(kCorners[i]);
    q.corners[i] = ff_model::process_vertex(s, in);
    v[i] = fixed_vertex(in, kCorners[i]);
  }
  q.image = rig.render(quad(v));
  EXPECT_EQ(q.image.width, kSize);
  return q;
}

FixedFunctionState lit_state(int variant) {
  FixedFunctionState s;
  s.world.value = kWorld;
  s.view.value = kView;
  s.projection.value = kProjection;
  s.lighting = true;
  s.normalize_normals = variant != 1;
  s.specular_enable = variant != 2;
  s.local_viewer = variant != 3;
  s.ambient.value = {0.2f, 0.2f, 0.25f, 1};
  s.material_diffuse.value = {0.7f, 0.6f, 0.5f, 0.8f};
  s.material_ambient.value = {0.3f, 0.2f, 0.1f, 1};
  s.material_specular.value = {0.5f, 0.5f, 0.5f, 1};
  s.material_emissive.value = {0.05f, 0.02f, 0, 0};
  s.material_power.value = 12;
  s.diffuse_source = static_cast<MaterialSource>(variant % 3);
  s.specular_source = static_cast<MaterialSource>((variant + 2) % 3);
  s.ambient_source = static_cast<MaterialSource>((variant + 1) % 3);
  s.emissive_source = variant == 4 ? MaterialSource::color1 : MaterialSource::material;
  FixedLight& sun = s.lights[0];
  sun.enabled = true;
  sun.direction.value = {0.3f, -0.5f, 1, 0};
  sun.diffuse.value = {0.9f, 0.8f, 0.7f, 1};
  sun.specular.value = {1, 1, 1, 1};
  sun.ambient.value = {0.1f, 0.1f, 0.1f, 1};
  FixedLight& bulb = s.lights[3];
  bulb.enabled = true;
  bulb.type = LightType::point;
  bulb.position.value = {0.5f, 0.5f, -2, 1};
  bulb.range.value = 100;
  bulb.attenuation0.value = 0.5f;
  bulb.attenuation1.value = 0.1f;
  bulb.attenuation2.value = 0.02f;
  bulb.diffuse.value = {0.6f, 0.7f, 0.9f, 1};
  bulb.specular.value = {0.4f, 0.4f, 0.2f, 1};
  FixedLight& spot = s.lights[5];
  spot.enabled = true;
  spot.type = LightType::spot;
  spot.position.value = {-0.5f, 0, -3, 1};
  spot.direction.value = {0.15f, 0, 1, 0};
  spot.theta.value = 0.3f;
  spot.phi.value = 1.2f;
  spot.falloff.value = 1.5f;
  spot.range.value = 50;
  spot.attenuation0.value = 1;
  spot.diffuse.value = {1, 0.5f, 0.25f, 1};
  spot.specular.value = {0.3f, 0.6f, 0.9f, 1};
  s.fog = true;
  s.fog_vertex_mode = static_cast<FogMode>(1 + variant % 3);
  s.fog_start.value = 4;
  s.fog_end.value = 7;
  s.fog_density.value = 0.15f;
  s.range_fog = variant % 2;
  s.fog_color.value = {0.2f, 0.4f, 0.9f, 1};
  // The pixel stage shows the lit diffuse colour (and adds specular when it is enabled).
  s.stages[0].color_op = s.stages[0].alpha_op = TextureOp::select_arg1;
  s.stages[0].color_arg[1] = s.stages[0].alpha_arg[1] = texture_arg::diffuse;
  return s;
}

class FixedFunctionLighting : public VulkanTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(ctx().validation_warning_count(), 0u) << describe_messages(ctx());
    VulkanTest::TearDown();
  }
};

TEST_F(FixedFunctionLighting, LightsMaterialsAndVertexFogMatchTheModel) {
  double worst = 0;
  for (int variant = 0; variant < 6; ++variant) {
    const FixedFunctionState s = lit_state(variant);
    const DrawnQuad q = draw_quad(ctx(), s);
    ASSERT_EQ(q.image.width, kSize) << "variant " << variant;
    const auto& lit = q.corners;
    const fx::ImageF& image = q.image;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const std::array<double, 4> weight = corner_weights(x, y);
        ff_model::PixelInputs in;
        in.diffuse = in.specular = {0, 0, 0, 0};
        in.fog = 0;
        for (int k = 0; k < 4; ++k) {
          for (int c = 0; c < 4; ++c) {
            in.diffuse[c] += weight[k] * lit[k].diffuse[c];
            in.specular[c] += weight[k] * lit[k].specular[c];
          }
          in.fog += weight[k] * lit[k].fog;
        }
        const Color want = ff_model::texture_stages(s, in);
        const float* got = image.at(x, y);
        for (int c = 0; c < 4; ++c) {
          const double e = std::fabs(got[c] - want[c]);
          worst = std::max(worst, e);
          ASSERT_LE(e, kTolerance) << "variant " << variant << " at " << x << "," << y << " channel " << c << ": GPU "
                                   << got[c] << ", model " << want[c] << "\n"
                                   << generate_fixed_function_vertex_shader(s).source;
        }
      }
  }
  std::printf("[ fixed-function ] lighting and vertex fog: largest |GPU - CPU model| %.3g (tolerance %.0e)\n", worst,
              kTolerance);
}

// Reads the generated vertex shader's TEXCOORD0 back through a pixel shader that writes it.
const char* kShowTexcoord = R"(
float4 PS(float4 d : COLOR0, float4 s : COLOR1, float4 tc : TEXCOORD0) : COLOR0 { return tc; }
)";

TEST_F(FixedFunctionLighting, TexgenAndTextureTransformsMatchTheModel) {
  double worst = 0;
  const uint32_t gens[] = {texcoord_gen::passthru, texcoord_gen::camera_space_normal,
                           texcoord_gen::camera_space_position, texcoord_gen::camera_space_reflection_vector,
                           texcoord_gen::sphere_map};
  for (uint32_t gen : gens)
    for (int transformed = 0; transformed < 2; ++transformed)
      for (bool local_viewer : {true, false}) {
        FixedFunctionState s = lit_state(0);
        s.lighting = false;
        s.fog = false;
        s.local_viewer = local_viewer;
        s.stages[0].color_arg[1] = texture_arg::texture;
        s.stages[0].texture = StageTexture::tex2d;
        s.stages[0].tex_coord_index = gen;
        if (transformed) {
          s.stages[0].texture_transform_flags = 3;
          s.stages[0].texture_transform.value = {0.5f, 0.1f, 0,    0.2f, -0.3f, 0.8f,  0.1f, 0,
                                                 0.2f, 0,    1.5f, 0.3f, 0.25f, -0.5f, 0,    1};
        }
        const DrawnQuad q = draw_quad(ctx(), s, kShowTexcoord);
        ASSERT_EQ(q.image.width, kSize);
        const fx::ImageF& image = q.image;
        for (uint32_t y = 0; y < kSize; ++y)
          for (uint32_t x = 0; x < kSize; ++x) {
            const std::array<double, 4> weight = corner_weights(x, y);
            std::array<double, 4> want{};
            for (int k = 0; k < 4; ++k) {
              const auto tc = ff_model::texture_coordinates(s, s.stages[0], q.corners[k], (kCorners[k].x + 1) / 2,
                                                            (kCorners[k].y + 1) / 2);
              for (int c = 0; c < 4; ++c) want[c] += weight[k] * tc[c];
            }
            const float* got = image.at(x, y);
            for (int c = 0; c < 4; ++c) {
              const double e = std::fabs(got[c] - want[c]);
              worst = std::max(worst, e);
              ASSERT_LE(e, kTolerance) << "texgen " << (gen >> 16) << " transformed " << transformed << " local viewer "
                                       << local_viewer << " at " << x << "," << y << " component " << c << ": GPU "
                                       << got[c] << ", model " << want[c];
            }
          }
      }
  std::printf("[ fixed-function ] texgen and texture transforms: largest |GPU - CPU model| %.3g\n", worst);
}

TEST_F(FixedFunctionLighting, WithAPixelShaderTheVertexShaderWritesWhatItReads) {
  // A pass with an HLSL pixel shader reading TEXCOORD1 alone: stage 1's coordinates (set 0,
  // transformed), no colours (the fixture fails on Vulkan's unconsumed-output warning).
  FixedFunctionState s = lit_state(0);
  s.fog = false;
  s.pixel_shader = true;
  s.pixel_shader_inputs = {true, false, false, false, 0b10};
  s.stages[1].tex_coord_index = 0;
  s.stages[1].texture_transform_flags = 2;
  s.stages[1].texture_transform.value = {2, 0, 0, 0, 0, 0.5f, 0, 0, 0.25f, 0, 1, 0, 0, 0, 0, 1};
  const std::string vs = generate_fixed_function_vertex_shader(s).source;
  const std::string outputs =
      vs.substr(vs.find("struct fx_ff_vs_out"), vs.find("fx_ff_vs_out fx_ff_vs(") - vs.find("struct fx_ff_vs_out"));
  EXPECT_EQ(outputs.find("COLOR"), std::string::npos) << outputs;
  EXPECT_NE(outputs.find("TEXCOORD1"), std::string::npos) << outputs;
  const DrawnQuad q = draw_quad(ctx(), s, "float4 PS(float4 tc : TEXCOORD1) : COLOR0 { return tc; }");
  ASSERT_EQ(q.image.width, kSize);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const double u = (x + 0.5) / kSize, v = (y + 0.5) / kSize;
      const double want[4] = {2 * u + 0.25, 0.5 * v, 1, 0};  // (u, v, 1, 0) * M
      for (int c = 0; c < 4; ++c) ASSERT_NEAR(q.image.at(x, y)[c], want[c], kTolerance) << x << "," << y << " " << c;
    }
}

TEST_F(FixedFunctionLighting, AnEffectPassDrawsAsTheModelSays) {
  // From .fx text to pixels: the pass's states read by fixed_function_state, the parameters
  // it binds uploaded by name, both generated stages drawn and compared with the model.
  auto b = test::build(R"(
static const float4x4 World = {0, 1, 0, 0,  -1, 0, 0, 0,  0, 0, 2, 0,  0, 0, 0, 1};
float3 LightDir = {0.3, -0.5, 1};
float4 Tint = {0.8, 0.6, 0.4, 0.7};
technique t {
  pass p {
    WorldTransform[0] = <World>;
    Lighting = TRUE;
    NormalizeNormals = TRUE;
    LightEnable[0] = TRUE;
    LightType[0] = Directional;
    LightDirection[0] = <LightDir>;
    LightDiffuse[0] = {1, 0.9, 0.8, 1};
    MaterialDiffuse = {0.9, 0.8, 0.7, 1};
    MaterialAmbient = {1, 1, 1, 1};
    DiffuseMaterialSource = Material;
    Ambient = 0x00203040;
    TextureFactor = <Tint>;
    ColorOp[0] = Modulate;
    ColorArg1[0] = Diffuse;
    ColorArg2[0] = TFactor;
    AlphaOp[0] = SelectArg1;
    AlphaArg1[0] = TFactor;
  }
}
)");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  DiagnosticSink diags;
  FixedFunctionState s = fixed_function_state(b->model, b->model.techniques[0].passes[0], diags);
  EXPECT_FALSE(s.world.parameter.bound());  // static: its value, not a uniform
  ASSERT_TRUE(s.lights[0].direction.parameter.bound());
  s.vertex_specular = false;
  FixedFunctionRig rig(ctx(), kSize);
  ASSERT_TRUE(rig.build(s));
  const float light_dir[3] = {0.3f, -0.5f, 1}, tint[4] = {0.8f, 0.6f, 0.4f, 0.7f};
  ASSERT_TRUE(rig.set_uniform("LightDir", light_dir, sizeof light_dir));
  ASSERT_TRUE(rig.set_uniform("Tint", tint, sizeof tint));
  std::array<ff_model::VertexOut, 4> lit;
  std::array<FixedVertex, 4> v;
  for (int i = 0; i < 4; ++i) {
    ff_model::VertexIn in = vertex_in(kCorners[i]);
    in.specular = {0, 0, 0, 0};  // the mesh has none: D3D's default
    lit[i] = ff_model::process_vertex(s, in);
    v[i] = fixed_vertex(in, kCorners[i]);
  }
  const fx::ImageF image = rig.render(quad(v));
  ASSERT_EQ(image.width, kSize);
  double worst = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const std::array<double, 4> weight = corner_weights(x, y);
      ff_model::PixelInputs in;
      in.diffuse = in.specular = {0, 0, 0, 0};
      for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 4; ++c) {
          in.diffuse[c] += weight[k] * lit[k].diffuse[c];
          in.specular[c] += weight[k] * lit[k].specular[c];
        }
      const Color want = ff_model::texture_stages(s, in);
      for (int c = 0; c < 4; ++c) {
        worst = std::max(worst, std::fabs(image.at(x, y)[c] - want[c]));
        ASSERT_NEAR(image.at(x, y)[c], want[c], kTolerance) << x << "," << y << " channel " << c;
      }
    }
  // Lit, tinted and not flat: the light direction reached the shader.
  EXPECT_GT(std::fabs(image.at(0, 0)[0] - image.at(kSize - 1, kSize - 1)[0]), 0.01);
  std::printf("[ fixed-function ] effect pass end to end: largest |GPU - CPU model| %.3g\n", worst);
}

TEST_F(FixedFunctionLighting, TableFogUsesTheEyeDepth) {
  for (FogMode mode : {FogMode::linear, FogMode::exp, FogMode::exp2}) {
    FixedFunctionState s;
    s.lighting = false;
    s.view.value = kView;
    s.projection.value = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.1f, 1, 0, 0, 0, 0};  // w = eye z
    s.stages[0].color_op = s.stages[0].alpha_op = TextureOp::select_arg1;
    s.stages[0].color_arg[1] = s.stages[0].alpha_arg[1] = texture_arg::diffuse;
    s.fog = true;
    s.fog_table_mode = mode;
    s.fog_start.value = 4;
    s.fog_end.value = 7;
    s.fog_density.value = 0.15f;
    s.fog_color.value = {0.2f, 0.4f, 0.9f, 1};
    FixedFunctionRig rig(ctx(), kSize);
    ASSERT_TRUE(rig.build(s));
    auto vertex = [](float x, float y) {  // eye depth 5: clip x, y = +-5 fill the target
      return FixedVertex{x, y, 0, 0, 0, -1, {0.9f, 0.6f, 0.3f, 1}, {0, 0, 0, 0}, 0, 0};
    };
    const FixedVertex a = vertex(-5, -5), b = vertex(5, -5), c = vertex(5, 5), d = vertex(-5, 5);
    const fx::ImageF image = rig.render({a, c, b, a, d, c});
    const double f = ff_model::fog_factor(mode, 5, 4, 7, 0.15);
    const double want[3] = {f * 0.9 + (1 - f) * 0.2, f * 0.6 + (1 - f) * 0.4, f * 0.3 + (1 - f) * 0.9};
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x)
        for (int ch = 0; ch < 3; ++ch)
          ASSERT_NEAR(image.at(x, y)[ch], want[ch], kTolerance) << "fog mode " << int(mode) << " at " << x << "," << y;
  }
}

TEST_F(FixedFunctionLighting, PretransformedVerticesLandOnTheirPixels) {
  FixedFunctionState s;
  s.pretransformed = true;
  s.lighting = false;
  s.stages[0].color_op = s.stages[0].alpha_op = TextureOp::select_arg1;
  s.stages[0].color_arg[1] = s.stages[0].alpha_arg[1] = texture_arg::diffuse;
  FixedFunctionRig rig(ctx(), kSize);
  ASSERT_TRUE(rig.build(s));
  // Vulkan's +Y down, positive viewport: clip = screen * (2/W, 2/H) + (-1 + 1/W, -1 + 1/H).
  const float screen_to_clip[4] = {2.0f / kSize, 2.0f / kSize, -1 + 1.0f / kSize, -1 + 1.0f / kSize};
  ASSERT_TRUE(rig.set_uniform("fx_ff_screen_to_clip", screen_to_clip, sizeof screen_to_clip));
  // D3D pixel centres are integers: x in [2.25, 12.25), y in [3.25, 14.25) covers pixels 3..12 x 4..14.
  auto vertex = [](float x, float y) {
    return FixedVertex{x, y, 0.5f, 0.5f /* rhw */, 0, 0, {0.25f, 0.5f, 0.75f, 1}, {0, 0, 0, 0}, 0, 0};
  };
  const FixedVertex a = vertex(2.25f, 3.25f), b = vertex(12.25f, 3.25f), c = vertex(12.25f, 14.25f),
                    d = vertex(2.25f, 14.25f);
  const fx::ImageF image = rig.render({a, c, b, a, d, c});
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const bool inside = x >= 3 && x <= 12 && y >= 4 && y <= 14;
      const float* got = image.at(x, y);
      if (inside) EXPECT_TRUE(got[0] == 0.25f && got[1] == 0.5f && got[2] == 0.75f) << x << "," << y << ": " << got[0];
      else EXPECT_EQ(got[0], -1.0f) << x << "," << y;
    }
}

}  // namespace
}  // namespace fx::vk::testing
