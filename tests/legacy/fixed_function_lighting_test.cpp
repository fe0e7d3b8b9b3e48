// Generated fixed-function vertex processing against the CPU model of the D3D lighting and
// fog formulas (vertex_lighting_model.h): transformed positions and normals, a directional,
// a point and a spot light with every material colour source, ambient, specular and vertex
// fog, per vertex, interpolated across the quad and drawn into a float target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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
const std::array<float, 16> kView = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1};  // camera 5 units back
const std::array<float, 16> kProjection = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.1f, 0, 0, 0, 0, 1};  // z 5 -> 0.5, w 1

// The quad's corners: screen corner (X, Y) comes from object (Y, -X) through kWorld.
struct Corner {
  float x, y;
  Vec3 normal;
};
const Corner kCorners[4] = {{-1, -1, {0.3, 0.2, -1}}, {1, -1, {-0.4, 0.1, -1}}, {1, 1, {0.2, -0.5, -1}}, {-1, 1, {-0.1, -0.3, -1}}};

ff_model::VertexIn vertex_in(const Corner& c) {
  const double u = (c.x + 1) / 2, v = (c.y + 1) / 2;
  return {{c.y, -c.x, 0}, c.normal, {u, v, 1 - u, 0.2 + 0.6 * v}, {0.5 * v, 1 - v, 0.3 + 0.4 * u, u}};
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
    FixedFunctionRig rig(ctx(), kSize);
    ASSERT_TRUE(rig.build(s)) << "variant " << variant;
    std::array<ff_model::VertexOut, 4> lit;
    std::array<FixedVertex, 4> v;
    for (int i = 0; i < 4; ++i) {
      const ff_model::VertexIn in = vertex_in(kCorners[i]);
      lit[i] = ff_model::process_vertex(s, in);
      v[i] = {float(in.position[0]), float(in.position[1]), float(in.position[2]), float(in.normal[0]), float(in.normal[1]),
              float(in.normal[2]), {float(in.diffuse[0]), float(in.diffuse[1]), float(in.diffuse[2]), float(in.diffuse[3])},
              {float(in.specular[0]), float(in.specular[1]), float(in.specular[2]), float(in.specular[3])},
              (kCorners[i].x + 1) / 2, (kCorners[i].y + 1) / 2};
    }
    // a = 0 (u 0, v 0), b = 1 (1, 0), c = 2 (1, 1), d = 3 (0, 1): triangles a c b and a d c.
    const fx::ImageF image = rig.render({v[0], v[2], v[1], v[0], v[3], v[2]});
    ASSERT_EQ(image.width, kSize);
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const double u = (x + 0.5) / kSize, w = (y + 0.5) / kSize;
        // Barycentric weights of the triangle holding the pixel centre (linear: w is 1).
        const std::array<double, 4> weight =
            u >= w ? std::array<double, 4>{1 - u, u - w, w, 0} : std::array<double, 4>{1 - w, 0, u, w - u};
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

}  // namespace
}  // namespace fx::vk::testing
