// The error-measurement helper: sample set coverage and the statistics themselves.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "fx/shading/error_measure.h"

namespace fx::shading {
namespace {

TEST(ErrorMeasure, SampleSetCoversDegeneraciesDownTo1e8) {
  SampleSetOptions o;
  o.uniform = 100;
  o.include_non_finite = true;
  auto samples = shading_samples(o);
  double smallest = 1;
  int exact = 0, non_finite = 0, uniform = 0;
  for (const auto& s : samples) {
    if (s.kind == SampleKind::near_degenerate) smallest = std::min(smallest, s.angle);
    exact += s.kind == SampleKind::exact_degenerate;
    non_finite += s.kind == SampleKind::non_finite;
    uniform += s.kind == SampleKind::uniform;
    if (s.kind == SampleKind::exact_degenerate && s.degeneracy == Degeneracy::l_equals_t) {
      EXPECT_EQ(s.l, s.t);
    }
    if (s.kind == SampleKind::exact_degenerate && s.degeneracy == Degeneracy::l_equals_minus_v) {
      EXPECT_EQ(s.l, -s.v);
    }
    if (s.kind == SampleKind::near_degenerate && s.degeneracy == Degeneracy::t_parallel_n && s.angle > 1e-7) {
      EXPECT_NEAR(std::acos(std::min(1.0, glm::dot(s.t, s.n))), s.angle, 1e-7);
    }
  }
  EXPECT_EQ(uniform, 100);
  EXPECT_NEAR(smallest, 1e-8, 1e-12);
  EXPECT_EQ(exact, 6 * o.frames_per_angle);
  EXPECT_EQ(non_finite, 12);
  // Deterministic.
  EXPECT_EQ(shading_samples(o).size(), samples.size());
  EXPECT_EQ(shading_samples(o)[7].l, samples[7].l);
}

TEST(ErrorMeasure, StatisticsOfAKnownError) {
  auto samples = shading_samples({.uniform = 50});
  ShadingTerm ref = [](const ShadingSample& s) { return s.l.x; };
  ShadingTerm same = ref;
  ShadingTerm shifted = [](const ShadingSample& s) { return s.l.x + 2.0 / 255; };
  ShadingTerm nan_on_degenerate = [](const ShadingSample& s) {
    return s.kind == SampleKind::exact_degenerate ? std::numeric_limits<double>::quiet_NaN() : s.l.x;
  };
  EXPECT_EQ(measure_error(ref, same, samples).all.max_abs, 0.0);
  ErrorReport r = measure_error(ref, shifted, samples);
  EXPECT_NEAR(r.all.max_abs, 2.0 / 255, 1e-15);
  EXPECT_NEAR(r.all.rmse, 2.0 / 255, 1e-15);
  EXPECT_NEAR(r.all.max_lsb8, 2.0, 1e-12);
  EXPECT_EQ(r.all.count, samples.size());
  EXPECT_EQ(r.uniform.count, 50u);
  ErrorReport n = measure_error(ref, nan_on_degenerate, samples);
  EXPECT_EQ(n.exact_degenerate.non_finite, n.exact_degenerate.count);
  EXPECT_GT(n.exact_degenerate.count, 0u);
  EXPECT_EQ(n.uniform.non_finite, 0u);
}

TEST(ErrorMeasure, CompareValues) {
  std::vector<double> a{0, 0.5, 1}, b{0, 0.25, 1};
  ErrorStats s = compare_values(a, b);
  EXPECT_EQ(s.max_abs, 0.25);
  EXPECT_EQ(s.worst.angle, 1.0);  // the index of the worst entry
  EXPECT_NEAR(s.rmse, std::sqrt(0.0625 / 3), 1e-15);
}

}  // namespace
}  // namespace fx::shading
