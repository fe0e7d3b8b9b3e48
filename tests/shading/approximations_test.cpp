// Cross-check of the accuracy report: a few figures of docs/accuracy.json recomputed by a
// separate, straightforward double-precision implementation (own table, own bilinear
// fetch, own reference formulas) that shares only the sample set with the library.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "fx/shading/error_measure.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

nlohmann::json report() {
  std::ifstream f(std::string(FXKIT_SOURCE_DIR) + "/docs/accuracy.json");
  if (!f) return {};
  return nlohmann::json::parse(f, nullptr, false);
}

double reported_max_abs(const nlohmann::json& r, const std::string& id) {
  for (const auto& row : r["approximations"])
    if (row["id"] == id) return row["error"]["max_abs"].get<double>();
  ADD_FAILURE() << id << " missing from docs/accuracy.json";
  return -1;
}

// The shader's float N.H (as the benchmark computes it), then everything else in double.
double float_n_dot_h(const fx::shading::ShadingSample& s) {
  float h[3], n[3], len = 0;
  for (int i = 0; i < 3; ++i) h[i] = float(s.l[i]) + float(s.v[i]), n[i] = float(s.n[i]);
  for (float c : h) len += c * c;
  len = std::sqrt(len);
  if (!(len > 0)) return 0;
  float d = 0;
  for (int i = 0; i < 3; ++i) d += n[i] * (h[i] / len);
  return d;
}

TEST(AccuracyReport, SquaringIn8BitRegistersMatchesIndependentComputation) {
  nlohmann::json r = report();
  ASSERT_TRUE(r.is_object()) << "run scripts/accuracy-report";
  double worst = 0;
  for (const auto& s : fx::shading::shading_samples()) {
    double x = std::min(1.0, std::max(0.0, float_n_dot_h(s)));
    double q = std::round(x * 255) / 255;
    for (int i = 0; i < 4; ++i) q = std::round(q * q * 255) / 255;
    worst = std::max(worst, std::abs(q - std::pow(x, 16)));
  }
  EXPECT_NEAR(reported_max_abs(r, "specular/squaring_8bit"), worst, 2e-6);
}

TEST(AccuracyReport, HemisphereSeedFormIsOffByTheClosedFormGap) {
  nlohmann::json r = report();
  ASSERT_TRUE(r.is_object());
  // Closed forms: cosine-weighted sky fraction 0.5 + 0.5 cos q, seed 1 - 0.5 sin q / 0.5 sin q.
  double worst = 0;
  for (int i = 0; i <= 180; ++i) {
    double q = kPi * i / 180, exact = 0.5 + 0.5 * std::cos(q);
    double seed = q <= kPi / 2 ? 1 - 0.5 * std::sin(q) : 0.5 * std::sin(q);
    worst = std::max(worst, std::abs(seed - exact));
  }
  EXPECT_NEAR(worst, (std::sqrt(2.0) - 1) / 2, 1e-9);
  // The report measures against quadrature, which is itself ~1e-4 off.
  EXPECT_NEAR(reported_max_abs(r, "hemisphere/seed_float"), worst, 1e-3);
  EXPECT_LT(reported_max_abs(r, "hemisphere/cosine_float"), 1e-3);
}

// Strand specular (V.R')^32 from a 64^2 float table indexed by cosine, texel-centre mapping.
TEST(AccuracyReport, StrandFloatTableMatchesIndependentComputation) {
  nlohmann::json r = report();
  ASSERT_TRUE(r.is_object());
  const int n = 64;
  auto exact = [](double lt, double vt) {  // from the cosines, in double
    lt = std::clamp(lt, -1.0, 1.0), vt = std::clamp(vt, -1.0, 1.0);
    double c = std::sin(std::acos(lt)) * std::sin(std::acos(vt)) - lt * vt;
    return c > 0 ? std::pow(c, 32) : 0.0;
  };
  std::vector<float> table(n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) table[j * n + i] = float(exact(2.0 * i / (n - 1) - 1, 2.0 * j / (n - 1) - 1));
  auto fetch = [&](double a, double b) {  // bilinear, clamp, texel centres at (i + 0.5) / n
    double x = std::clamp((0.5 * a + 0.5) * (n - 1), 0.0, double(n - 1));
    double y = std::clamp((0.5 * b + 0.5) * (n - 1), 0.0, double(n - 1));
    int x0 = std::min(int(x), n - 2), y0 = std::min(int(y), n - 2);
    double fx = x - x0, fy = y - y0;
    auto t = [&](int i, int j) { return double(table[j * n + i]); };
    return (1 - fy) * ((1 - fx) * t(x0, y0) + fx * t(x0 + 1, y0)) +
           fy * ((1 - fx) * t(x0, y0 + 1) + fx * t(x0 + 1, y0 + 1));
  };
  double worst = 0;
  for (const auto& s : fx::shading::shading_samples()) {
    auto angle = [](const glm::dvec3& a, const glm::dvec3& b) {
      return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
    };
    double ref = -std::cos(angle(s.l, s.t) + angle(s.v, s.t));
    ref = ref > 0 ? std::pow(ref, 32) : 0;
    worst = std::max(worst, std::abs(fetch(glm::dot(s.l, s.t), glm::dot(s.v, s.t)) - ref));
  }
  double reported = reported_max_abs(r, "strand_lut/dot/float32/n32/s64");
  EXPECT_NEAR(reported, worst, 0.01 * worst + 1e-4) << "independent " << worst << ", report " << reported;
}

// The seed's unnormalized Gram-Schmidt tangent (bump/unnormalized/diffuse/tilt15): each
// uniform sample's normal tilted 15 degrees toward T cos(phi) + (N x T) sin(phi), phi the
// golden angle times the sample's rank, as the report builds it; then sqrt(1 - (L.T')^2)
// against |L x T'/|T'|| in double.
TEST(AccuracyReport, UnnormalizedBumpTangentMatchesIndependentComputation) {
  nlohmann::json r = report();
  ASSERT_TRUE(r.is_object());
  const double tilt = 15 * kPi / 180;
  double worst = 0;
  int k = 0;
  for (const auto& s : fx::shading::shading_samples()) {
    if (s.kind != fx::shading::SampleKind::uniform) continue;
    const double phi = 2.399963 * k++;
    const glm::dvec3 n =
        std::cos(tilt) * s.n + std::sin(tilt) * (std::cos(phi) * s.t + std::sin(phi) * glm::cross(s.n, s.t));
    const glm::dvec3 t = s.t - glm::dot(n, s.t) * n;
    const double lt = std::clamp(glm::dot(s.l, t), -1.0, 1.0);
    const double approx = std::sqrt(1 - lt * lt);
    const double exact = glm::length(glm::cross(s.l, t / glm::length(t)));
    worst = std::max(worst, std::abs(approx - exact));
  }
  double reported = reported_max_abs(r, "bump/unnormalized/diffuse/tilt15");
  EXPECT_NEAR(reported, worst, 0.01 * worst + 1e-4) << "independent " << worst << ", report " << reported;
}

}  // namespace
