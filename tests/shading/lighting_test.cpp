// Hemisphere lighting (quadrature check of the closed form), GLSL anisotropic highlights,
// the Ward-like Gaussian, and the wood shader's math.
#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "fx/shading/error_measure.h"
#include "fx/shading/hemisphere.h"
#include "fx/shading/highlight.h"
#include "fx/shading/ward.h"
#include "fx/shading/wood.h"

namespace fx::shading {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Hemisphere, CosineFormIsTheExactIntegral) {
  // Midpoint quadrature with 600 x 1200 cells. The integrand is smooth except for the
  // sky/ground boundary, a great circle: the cells it cuts cover a band of width ~h
  // (h = pi/1200) around a curve of length <= 2 pi, each contributing at most its own
  // weighted area, so |error| <= 2 pi h / pi = 2h ~ 5e-3 as a hard bound; cancellation
  // across the band makes the observed error far smaller. Tolerance: 2h.
  const int steps = 600;
  const double tol = 2.0 * kPi / (2 * steps);
  double worst_cos = 0, worst_seed = 0;
  for (double deg = 0; deg <= 180; deg += 7.5) {
    double q = deg * kPi / 180;
    double numeric = hemisphere_sky_fraction_quadrature(q, steps);
    EXPECT_NEAR(hemisphere_sky_fraction(std::cos(q)), numeric, tol) << deg;
    worst_cos = std::max(worst_cos, std::abs(hemisphere_sky_fraction(std::cos(q)) - numeric));
    worst_seed = std::max(worst_seed, std::abs(hemisphere_sky_fraction_seed(std::cos(q)) - numeric));
  }
  std::printf("[ measured ] hemisphere: |0.5+0.5cos q - quadrature| max %.2e; seed's 1-0.5 sin q off by %.3f\n",
              worst_cos, worst_seed);
  EXPECT_GT(worst_seed, 0.2);  // the seed's "actual integral" is a different model
}

TEST(Hemisphere, SeedFormDiffersByAtMostPoint207) {
  double worst = 0, at = 0;
  for (int i = 0; i <= 18000; ++i) {
    double q = i * kPi / 18000;
    double d = std::abs(hemisphere_sky_fraction(std::cos(q)) - hemisphere_sky_fraction_seed(std::cos(q)));
    if (d > worst) worst = d, at = q * 180 / kPi;
  }
  EXPECT_NEAR(worst, 0.5 * (std::sqrt(2.0) - 1.0), 1e-6);  // at 45 and 135 degrees
  EXPECT_NEAR(std::fmod(at, 90.0), 45.0, 0.02);
}

TEST(Hemisphere, ThreeTermWithOcclusionAndSun) {
  HemisphereLight<float> h;
  h.sky_color = {0.4f, 0.6f, 1.0f};
  h.ground_color = {0.2f, 0.1f, 0.0f};
  h.sun_direction = {0, 0, 1};
  // Facing the sky, unoccluded, no sun: the sky colour.
  glm::vec3 up = hemisphere_lighting(h, glm::vec3(0, 0, 1), 0.0f);
  EXPECT_NEAR(up.z, 1.0f, 1e-6);
  // Facing down: ground; fully occluded: black.
  EXPECT_NEAR(hemisphere_lighting(h, glm::vec3(0, 0, -1), 0.0f).x, 0.2f, 1e-6);
  EXPECT_EQ(hemisphere_lighting(h, glm::vec3(0, 0, 1), 1.0f), glm::vec3(0.0f));
  // Half occluded, sideways: half of the sky/ground average.
  EXPECT_NEAR(hemisphere_lighting(h, glm::vec3(1, 0, 0), 0.5f).y, 0.5f * 0.35f, 1e-6);
  // The sun adds saturate(N.S) sun_color, and ignores the hemisphere occlusion.
  h.sun_color = {1, 1, 1};
  EXPECT_NEAR(hemisphere_lighting(h, glm::vec3(0, 0, 1), 1.0f).x, 1.0f, 1e-6);
  // NaN normal: a = 0.5, no sun; finite.
  glm::vec3 bad = hemisphere_lighting(h, glm::vec3(std::numeric_limits<float>::quiet_NaN()), 0.0f);
  EXPECT_TRUE(finite(bad));
}

HighlightInputs<float> to_float(const HighlightInputs<double>& d) {
  return {glm::vec3(d.n), glm::vec3(d.t), glm::vec3(d.e), glm::vec3(d.l), float(d.exponent)};
}

TEST(Highlight, IsotropicSwitchIsPlainPhongAndBlinn) {
  HighlightInputs<float> in;
  in.l = glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f));
  in.e = glm::normalize(glm::vec3(-0.3f, -0.05f, 1.0f));
  glm::vec3 r = 2.0f * glm::dot(in.n, in.l) * in.n - in.l;
  EXPECT_NEAR(anisotropic_highlight(in, HighlightModel::phong, false), std::pow(glm::dot(r, in.e), 32.0f), 1e-6);
  glm::vec3 h = glm::normalize(in.l + in.e);
  // glm::normalize uses inversesqrt, ours divides by sqrt: a few ulp apart, times n = 32.
  EXPECT_NEAR(anisotropic_highlight(in, HighlightModel::blinn_phong, false), std::pow(h.z, 32.0f), 2e-5);
  // Looking along the strand plane, the projection changes nothing ("a standard Phong
  // reflection if you look along the strain direction").
  in.t = glm::vec3(1, 0, 0);
  in.l = glm::normalize(glm::vec3(0.4f, 0, 1));
  in.e = glm::normalize(glm::vec3(-0.4f, 0, 1));
  EXPECT_NEAR(anisotropic_highlight(in, HighlightModel::phong, true),
              anisotropic_highlight(in, HighlightModel::phong, false), 1e-6);
}

TEST(Highlight, FloatMatchesDoubleAwayFromIllConditionedProjections) {
  // Projection onto the strand plane has condition number 1/sin(a), a = angle between the
  // vector and the plane normal B = N x T / |N x T| (itself conditioned by 1/|N x T|); the
  // half vector's is 1/|L+V|. Where both are below
  // 100 the float error is <= 100 * 4 eps * n(=32) ~ 2e-3 for x^32; checked at 2e-3.
  // Everywhere (down to 1e-8 rad and the exact degeneracies) the result stays in [0, 1].
  SampleSetOptions o;
  o.uniform = 3000;
  auto samples = shading_samples(o);
  for (HighlightModel m : {HighlightModel::phong, HighlightModel::blinn_phong}) {
    double worst = 0;
    for (const auto& s : samples) {
      HighlightInputs<double> d{s.n, s.t, s.v, s.l, 32.0};
      double ref = anisotropic_highlight(d, m, true);
      float f = anisotropic_highlight(to_float(d), m, true);
      ASSERT_TRUE(std::isfinite(f));
      ASSERT_GE(f, 0.0f);
      ASSERT_LE(f, 1.0f + 1e-6f);
      double nt = glm::length(glm::cross(s.n, s.t));
      if (nt < 1e-2) continue;  // the strand plane's own normal: condition 1/|N x T|
      glm::dvec3 b = glm::cross(s.n, s.t) / nt;
      double cond = std::max({1.0 / std::max(1e-300, glm::length(glm::cross(s.v, b))),
                              1.0 / std::max(1e-300, glm::length(glm::cross(s.l, b))),
                              1.0 / std::max(1e-300, glm::length(s.l + s.v))});
      if (cond < 100) worst = std::max(worst, std::abs(f - ref));
    }
    EXPECT_LT(worst, 2e-3) << int(m);
  }
}

TEST(Highlight, HalfVectorGuardedWhenLightOppositeView) {
  glm::vec3 l = glm::normalize(glm::vec3(0.2f, 0.3f, 0.9f));
  EXPECT_EQ(half_vector(l, -l), glm::vec3(0.0f));
  HighlightInputs<float> in;
  in.l = l;
  in.e = -l;
  EXPECT_EQ(anisotropic_highlight(in, HighlightModel::blinn_phong, true), 0.0f);
  EXPECT_EQ(anisotropic_highlight(in, HighlightModel::blinn_phong, false), 0.0f);
  // T parallel to N: no strand plane, shaded isotropically.
  in.t = in.n;
  in.e = glm::normalize(glm::vec3(-0.2f, -0.3f, 0.9f));
  EXPECT_EQ(anisotropic_highlight(in, HighlightModel::phong, true),
            anisotropic_highlight(in, HighlightModel::phong, false));
  in.l = glm::vec3(std::numeric_limits<float>::infinity(), 0, 0);
  EXPECT_EQ(anisotropic_highlight(in, HighlightModel::phong, true), 0.0f);
}

TEST(Ward, GaussianGuardsTheHorizon) {
  glm::vec3 n(0, 0, 1), t(1, 0, 0);
  EXPECT_EQ(ward_gaussian(n, t, glm::vec3(0, 0, 1), 5.0f), 1.0f);
  EXPECT_EQ(ward_gaussian(n, t, glm::vec3(1, 0, 0), 5.0f), 0.0f);  // w = 0: 0/0 in the seed
  EXPECT_EQ(ward_gaussian(n, t, glm::vec3(0, 1, 0), 5.0f), 0.0f);
  EXPECT_EQ(ward_gaussian(n, t, glm::vec3(NAN), 5.0f), 0.0f);
  // Anisotropic: moving H along T dims it, moving it across T (along B) does not.
  glm::vec3 ht = glm::normalize(glm::vec3(0.4f, 0, 1)), hb = glm::normalize(glm::vec3(0, 0.2f, 1));
  EXPECT_LT(ward_gaussian(n, t, ht, 5.0f), 0.9f);
  EXPECT_EQ(ward_gaussian(n, t, hb, 5.0f), 1.0f);
  // Float vs double on a sweep: exp(-e^2) has |d/de| <= sqrt(2/e) < 0.86, e has ~3 eps
  // relative error, so 1e-6 absolute.
  for (double a = -1.5; a <= 1.5; a += 0.01) {
    glm::dvec3 h(std::sin(a), 0.1, std::cos(a));
    h = glm::normalize(h);
    EXPECT_NEAR(ward_gaussian(glm::vec3(n), glm::vec3(t), glm::vec3(h), 5.0f),
                ward_gaussian(glm::dvec3(n), glm::dvec3(t), h, 5.0), 1e-6);
  }
}

TEST(LnHn, TableTermsAndGaussianLobe) {
  auto b = ln_hn_terms(0.5, 1.0, HalfAngleLobe::blinn_phong, 32.0);
  EXPECT_EQ(b.diffuse, 0.5);
  EXPECT_EQ(b.specular, 1.0);
  auto g = ln_hn_terms(-0.5, std::cos(0.3), HalfAngleLobe::gaussian, 0.3);
  EXPECT_EQ(g.diffuse, 0.0);
  EXPECT_NEAR(g.specular, std::exp(-std::pow(std::tan(0.3) / 0.3, 2)), 1e-12);
  EXPECT_EQ(ln_hn_terms(0.5, -0.1, HalfAngleLobe::gaussian, 0.3).specular, 0.0);
  EXPECT_EQ(ln_hn_terms(0.5, 0.0, HalfAngleLobe::gaussian, 0.3).specular, 0.0);
}

TEST(Wood, SeedSmoothstepIsAHermiteBetweenValues) {
  // The seed's smoothstep(a, b, s) runs from value a to value b, not from edge a to edge b.
  EXPECT_FLOAT_EQ(seed_smoothstep(0.0f, 0.8f, 0.0f), 0.0f);
  EXPECT_FLOAT_EQ(seed_smoothstep(0.0f, 0.8f, 1.0f), 0.8f);
  EXPECT_FLOAT_EQ(seed_smoothstep(0.0f, 0.8f, 0.5f), 0.4f * 0.125f - 0.6f * 0.25f + 0.5f);
  EXPECT_FLOAT_EQ(seed_smoothstep(0.0f, 0.8f, -1.0f), 0.0f);
  EXPECT_FLOAT_EQ(renderman_smoothstep(0.0f, 0.8f, 0.8f), 1.0f);
  // Model difference of the ring profile (seed vs RenderMan smoothstep), reported.
  double worst = 0;
  for (int i = 0; i < 1000; ++i) {
    double r = i / 1000.0;
    worst = std::max(worst, std::abs(wood_ring_seed(r) - wood_ring_renderman(r)));
    ASSERT_TRUE(std::isfinite(wood_ring_seed(float(r))));
  }
  std::printf("[ measured ] wood ring: seed smoothstep vs RenderMan smoothstep max difference %.3f\n", worst);
  EXPECT_GT(worst, 0.1);
}

TEST(Wood, FrcAndShadeStayFinite) {
  EXPECT_EQ(frc(2.25f), 0.25f);
  EXPECT_EQ(frc(-0.25f), 0.75f);
  EXPECT_LT(frc(-1e-30f), 1.0f);
  EXPECT_EQ(frc(std::numeric_limits<float>::quiet_NaN()), 0.0f);
  WoodParams<float> w;
  w.l = glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f));
  auto noise3 = [](const glm::vec3& p) { return 0.1f * glm::vec3(std::sin(p.x), std::cos(p.y), std::sin(p.z)); };
  auto noise1 = [](float x) { return 0.1f * std::sin(3.0f * x); };
  for (float x = -3; x <= 3; x += 0.37f) {
    glm::vec3 c = wood_shade(w, glm::vec3(x, 0.5f * x, 0.2f), glm::vec3(0, 0, 1), 1.0f, noise3, noise1);
    ASSERT_TRUE(finite(c));
  }
  // L = -eye makes the seed's (L + eye) / len(L + eye) a 0/0; guarded to no specular.
  w.i = w.l;
  glm::vec3 c = wood_shade(w, glm::vec3(1, 2, 3), glm::vec3(0, 0, 1), 1.0f, noise3, noise1);
  EXPECT_TRUE(finite(c));
}

}  // namespace
}  // namespace fx::shading
