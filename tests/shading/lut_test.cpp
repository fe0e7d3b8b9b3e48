// Lookup tables: texel-centre vs naive mapping, the seed's wrap trick, angle vs dot
// indexing on the highlight ridge, 8-bit vs float, and the LightEval pow table.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "fx/shading/bakers.h"
#include "fx/shading/error_measure.h"
#include "fx/shading/specular_power.h"

namespace fx::shading {
namespace {

// Max |lookup - exact| for the strand table over a grid of cosines (lt, vt) in [-1, 1]^2.
struct TableError {
  double diffuse = 0, specular = 0;
};

TableError strand_table_error_on_grid(const StrandTableOptions& o, int grid) {
  Table t = bake_strand_table(o);
  TableError e;
  for (int j = 0; j <= grid; ++j)
    for (int i = 0; i <= grid; ++i) {
      double lt = -1.0 + 2.0 * i / grid, vt = -1.0 + 2.0 * j / grid;
      StrandTerms<double> exact = strand_from_cosines(lt, vt, o.exponent);
      StrandTerms<float> got =
          lookup_strand_table(t, o, lut_u_from_cosine(o.index, float(lt)), lut_u_from_cosine(o.index, float(vt)));
      e.diffuse = std::max(e.diffuse, std::abs(got.diffuse - exact.diffuse));
      e.specular = std::max(e.specular, std::abs(got.specular - exact.specular));
    }
  return e;
}

TEST(StrandTable, TexelCentreMappingIsExactAtTexelsAndEnds) {
  // With texel-centre mapping every texel is hit at its centre: the lookup at the baked
  // cosines returns the stored value (float table: only float rounding, < 1e-6).
  StrandTableOptions o{.size = 64, .exponent = 16, .mapping = LutMapping::texel_centre, .format = TableFormat::float32};
  Table t = bake_strand_table(o);
  for (int i = 0; i < o.size; i += 7)
    for (int j = 0; j < o.size; j += 5) {
      double lt = lut_cosine_of_u(o.index, lut_texel_u(o.mapping, o.size, i));
      double vt = lut_cosine_of_u(o.index, lut_texel_u(o.mapping, o.size, j));
      StrandTerms<float> got =
          lookup_strand_table(t, o, lut_u_from_cosine(o.index, float(lt)), lut_u_from_cosine(o.index, float(vt)));
      StrandTerms<double> exact = strand_from_cosines(lt, vt, o.exponent);
      EXPECT_NEAR(got.diffuse, exact.diffuse, 1e-5);
      EXPECT_NEAR(got.specular, exact.specular, 1e-5);
    }
  // The ends L.T = +-1 (on the strand): diffuse exactly 0.
  EXPECT_NEAR(lookup_strand_table(t, o, 1.0f, 0.5f).diffuse, 0.0f, 1e-6);
  EXPECT_NEAR(lookup_strand_table(t, o, 0.0f, 0.5f).diffuse, 0.0f, 1e-6);
}

TEST(StrandTable, MappingErrorsNaiveSeedWrapAndTexelCentre) {
  const int n = 64, grid = 512;
  auto err = [&](LutMapping m) {
    return strand_table_error_on_grid({.size = n, .exponent = 16, .mapping = m, .format = TableFormat::float32}, grid);
  };
  TableError naive = err(LutMapping::naive), wrap = err(LutMapping::seed_wrap), centre = err(LutMapping::texel_centre),
             centre_wrap = err(LutMapping::texel_centre_wrap);
  std::printf("[ measured ] strand table %dx%d float, max error over [-1,1]^2 (diffuse / specular^16):\n", n, n);
  std::printf(
      "[ measured ]   naive+clamp %.4f / %.4f; seed wrap %.4f / %.4f; texel-centre %.4f / %.4f; "
      "texel-centre wrap %.4f / %.4f\n",
      naive.diffuse, naive.specular, wrap.diffuse, wrap.specular, centre.diffuse, centre.specular, centre_wrap.diffuse,
      centre_wrap.specular);
  // Naive with wrap blends the opposite end of the table in at the corners: the specular
  // error there is half the table's range.
  EXPECT_GE(wrap.specular, 0.49);
  EXPECT_GT(wrap.specular, naive.specular);
  EXPECT_LT(centre.diffuse, naive.diffuse);
  EXPECT_LT(centre.diffuse, wrap.diffuse / 2);
  // The half-texel fix folded into the wrap trick's scale is as good as clamp addressing.
  EXPECT_NEAR(centre_wrap.diffuse, centre.diffuse, 1e-5);
  EXPECT_NEAR(centre_wrap.specular, centre.specular, 1e-5);
}

TEST(StrandTable, AngleIndexingOnTheRidge) {
  // The ridge: V.T = -L.T (the specular maximum) with L close to the strand, angles from
  // 1e-4 to 0.2 rad. In dot space sqrt(1 - x^2) has an infinite slope at x = 1, so
  // linear interpolation between texels is worst there; in angle space it is sin(a).
  const int n = 64;
  StrandTableOptions dot{.size = n,
                         .exponent = 16,
                         .mapping = LutMapping::texel_centre,
                         .index = LutIndex::cosine,
                         .format = TableFormat::float32};
  StrandTableOptions ang = dot;
  ang.index = LutIndex::angle;
  Table td = bake_strand_table(dot), ta = bake_strand_table(ang);
  std::vector<double> exact_d, exact_s, dot_d, dot_s, ang_d, ang_s;
  for (double a = 1e-4; a < 0.2; a *= 1.05) {
    glm::vec3 t(0, 0, 1);
    glm::vec3 l(std::sin(a), 0, std::cos(a)), v(std::sin(a), 0, -std::cos(a));  // V.T = -L.T
    StrandTerms<double> ex = strand_reference(glm::dvec3(l), glm::dvec3(v), glm::dvec3(t), 16.0);
    StrandTerms<float> gd = lookup_strand_table(td, dot, lut_u_from_vectors(LutIndex::cosine, l, t),
                                                lut_u_from_vectors(LutIndex::cosine, v, t));
    StrandTerms<float> ga = lookup_strand_table(ta, ang, lut_u_from_vectors(LutIndex::angle, l, t),
                                                lut_u_from_vectors(LutIndex::angle, v, t));
    exact_d.push_back(ex.diffuse);
    exact_s.push_back(ex.specular);
    dot_d.push_back(gd.diffuse);
    dot_s.push_back(gd.specular);
    ang_d.push_back(ga.diffuse);
    ang_s.push_back(ga.specular);
  }
  ErrorStats e_dot_d = compare_values(exact_d, dot_d), e_ang_d = compare_values(exact_d, ang_d);
  ErrorStats e_dot_s = compare_values(exact_s, dot_s), e_ang_s = compare_values(exact_s, ang_s);
  std::printf("[ measured ] ridge, %dx%d float: diffuse dot %s | angle %s (ratio %.0fx)\n", n, n,
              describe(e_dot_d).c_str(), describe(e_ang_d).c_str(), e_dot_d.max_abs / e_ang_d.max_abs);
  std::printf("[ measured ] ridge, %dx%d float: specular dot %s | angle %s (ratio %.0fx)\n", n, n,
              describe(e_dot_s).c_str(), describe(e_ang_s).c_str(), e_dot_s.max_abs / e_ang_s.max_abs);
  EXPECT_GT(e_dot_d.max_abs, 10 * e_ang_d.max_abs);
  EXPECT_GT(e_dot_s.max_abs, 10 * e_ang_s.max_abs);
}

TEST(StrandTable, EightBitAddsAtMostHalfAnLsb) {
  // unorm8 rounds each texel to nearest: |stored - exact| <= 0.5/255; linear filtering is
  // a convex combination, so the lookup moves by at most that (plus float rounding).
  StrandTableOptions f{.size = 64, .exponent = 8, .format = TableFormat::float32};
  StrandTableOptions q = f;
  q.format = TableFormat::unorm8;
  Table tf = bake_strand_table(f), tq = bake_strand_table(q);
  double worst = 0;
  for (float lu = 0; lu <= 1.0f; lu += 0.01f)
    for (float vu = 0; vu <= 1.0f; vu += 0.013f) {
      auto a = lookup_strand_table(tf, f, lu, vu), b = lookup_strand_table(tq, q, lu, vu);
      worst = std::max({worst, double(std::abs(a.diffuse - b.diffuse)), double(std::abs(a.specular - b.specular))});
    }
  EXPECT_LE(worst, 0.5 / 255 + 1e-6);
  std::printf("[ measured ] strand table unorm8 vs float32: max %.3g (%.2f LSB8)\n", worst, worst * 255);
}

TEST(PowTable, LightEvalTableVsNativeAndSquaring) {
  // x^16 three ways against pow in double, over x in [0, 1].
  PowTableOptions o{.width = 4, .height = 256, .exponent = 16, .format = TableFormat::unorm8};
  Table t = bake_pow_table(o);
  std::vector<double> exact, table, squaring, squaring8, native;
  for (int i = 0; i <= 4096; ++i) {
    float x = float(i) / 4096.0f;
    exact.push_back(specular_power_reference(x, 16.0));
    table.push_back(lookup_pow_table(t, o, x));
    squaring.push_back(pow16_by_squaring(x, false));
    squaring8.push_back(pow16_by_squaring(x, true));
    native.push_back(specular_power(x, 16.0f));
  }
  ErrorStats et = compare_values(exact, table), es = compare_values(exact, squaring),
             e8 = compare_values(exact, squaring8), en = compare_values(exact, native);
  std::printf("[ measured ] x^16: table 256 unorm8 (naive/D3DX mapping) %s\n", describe(et).c_str());
  std::printf("[ measured ] x^16: squaring float %s; squaring 8-bit registers %s; native pow %s\n",
              describe(es).c_str(), describe(e8).c_str(), describe(en).c_str());
  // Float squaring: 4 roundings, relative error <= 16 * 2^-24 ~ 1e-6.
  EXPECT_LT(es.max_abs, 2e-6);
  EXPECT_LT(en.max_abs, 1e-4);  // DESIGN.md's pow tolerance
  // 8-bit registers: banding. Count distinct output levels where x^16 > 0.5: the float
  // path has as many as samples, the ps.1.1 path only a handful.
  std::vector<double> levels;
  for (size_t i = 0; i < exact.size(); ++i)
    if (exact[i] > 0.5 && (levels.empty() || levels.back() != squaring8[i])) levels.push_back(squaring8[i]);
  EXPECT_LT(levels.size(), 20u);
  EXPECT_GT(e8.max_abs, 2.0 / 255);
  std::printf("[ measured ] 8-bit squaring: %zu distinct levels in the top half of the highlight\n", levels.size());
}

}  // namespace
}  // namespace fx::shading
