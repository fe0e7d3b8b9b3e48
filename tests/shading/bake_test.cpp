// Generator registry (vocabulary, errors as values), noise volumes, BRDF factorization.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "fx/shading/bakers.h"
#include "fx/shading/brdf_factorization.h"
#include "fx/shading/generator.h"

namespace fx::shading {
namespace {

TEST(Generator, StrandFromAnnotationsMatchesDirectBake) {
  GeneratorParams p;
  p.set("Width", 64).set("Exponent", 32).set("Format", "float32").set("UIName", "Strand LUT");
  BakeResult r = bake("strand", p);
  ASSERT_TRUE(r.ok()) << r.message;
  Table direct = bake_strand_table({.size = 64, .exponent = 32, .format = TableFormat::float32});
  EXPECT_EQ(r.table->width, 64);
  EXPECT_EQ(r.table->channels, 4);
  EXPECT_EQ(r.table->float32, direct.float32);
  // Names are case-insensitive.
  GeneratorParams q;
  q.set("width", 64).set("EXPONENT", 32).set("format", "FLOAT32");
  EXPECT_EQ(bake("Strand", q).table->float32, direct.float32);
}

TEST(Generator, ErrorsAreValuesWithReasons) {
  BakeResult r = bake("strnad", {});
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error_id, "unknown-generator");
  EXPECT_NE(r.message.find("did you mean 'strand'"), std::string::npos) << r.message;

  auto fails = [](std::string_view gen, GeneratorParams p, std::string_view needle) {
    BakeResult b = bake(gen, p);
    EXPECT_FALSE(b.ok());
    EXPECT_EQ(b.error_id, "bad-generator-parameter");
    EXPECT_NE(b.message.find(needle), std::string::npos) << b.message;
  };
  fails("strand", GeneratorParams().set("Width", -4), "Width");
  fails("strand", GeneratorParams().set("Width", 1e9), "Width");
  fails("strand", GeneratorParams().set("Width", 64.5), "integer");
  fails("strand", GeneratorParams().set("Widht", 64), "did you mean 'Width'");
  fails("strand", GeneratorParams().set("Exponent", "high"), "must be a number");
  fails("strand", GeneratorParams().set("Exponent", NAN), "finite");
  fails("strand", GeneratorParams().set("Mapping", "texel_center"), "did you mean 'texel_centre'");
  fails("strand", GeneratorParams().set("Mapping", "seed_wrap").set("Width", 63), "even");
  fails("noise3d", GeneratorParams().set("Channels", 5), "Channels");
  fails("noise3d", GeneratorParams().set("Width", 4096).set("Height", 4096).set("Depth", 4096), "too large");
  fails("brdf_factor", GeneratorParams().set("Factor", "middle"), "Factor");
  fails("brdf_factor", GeneratorParams().set("Format", "unorm8"), "float32");

  DiagnosticSink sink;
  EXPECT_FALSE(bake("pow", GeneratorParams().set("Height", 0), sink, SourceRange{}).has_value());
  ASSERT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "bad-generator-parameter");
}

TEST(Generator, EveryGeneratorBakesWithDefaults) {
  for (std::string_view g : generator_names()) {
    GeneratorParams p;
    if (g == "brdf_factor") p.set("Width", 8).set("Samples", 2000).set("Iterations", 40);
    if (g == "noise3d") p.set("Width", 8);
    BakeResult r = bake(g, p);
    ASSERT_TRUE(r.ok()) << g << ": " << r.message;
    EXPECT_GT(r.table->value_count(), 0u) << g;
  }
}

// Each face's texel (s, t) looks along the direction Vulkan's (and D3D's) cube lookup
// selects that texel for: the major axis picks the face, the other two give s and t.
TEST(CubeTable, FaceDirectionsFollowTheCubeLookup) {
  for (int face = 0; face < 6; ++face)
    for (double s : {0.1, 0.5, 0.8})
      for (double t : {0.2, 0.5, 0.9}) {
        const glm::dvec3 d = cube_direction(face, s, t);
        const int axis = std::abs(d.x) >= std::abs(d.y) && std::abs(d.x) >= std::abs(d.z) ? 0
                         : std::abs(d.y) >= std::abs(d.z)                                 ? 1
                                                                                          : 2;
        const double ma = d[axis];
        EXPECT_EQ(axis * 2 + (ma < 0), face);
        // The specification's (sc, tc) for each face.
        const double sc[6] = {-d.z, d.z, d.x, d.x, d.x, -d.x}, tc[6] = {-d.y, -d.y, d.z, -d.z, -d.y, -d.y};
        EXPECT_NEAR(0.5 * (sc[face] / std::abs(ma) + 1), s, 1e-12) << face;
        EXPECT_NEAR(0.5 * (tc[face] / std::abs(ma) + 1), t, 1e-12) << face;
      }
}

// Shape = "cube": the parabolic factor resampled on six faces, as luminance (rgb equal).
TEST(Generator, BrdfFactorCubeReadsTheParabolicMapAlongEachTexelsDirection) {
  GeneratorParams p;
  p.set("Width", 8).set("Samples", 2000).set("Iterations", 40).set("Factor", "half");
  BakeResult flat = bake("brdf_factor", p);
  BakeResult cube = bake("brdf_factor", GeneratorParams(p).set("Shape", "cube"));
  ASSERT_TRUE(flat.ok() && cube.ok()) << flat.message << cube.message;
  EXPECT_FALSE(flat.table->cube);
  ASSERT_TRUE(cube.table->cube);
  EXPECT_EQ(cube.table->depth, 6);
  EXPECT_EQ(cube.table->channels, 3);
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < 8; y += 3)
      for (int x = 0; x < 8; x += 3) {
        const glm::dvec3 w = glm::normalize(cube_direction(face, (x + 0.5) / 8, (y + 0.5) / 8));
        const glm::dvec2 st = parabolic_coords(w);
        const float want = sample_linear(*flat.table, glm::vec3(float(st.x), float(st.y), 0), AddressMode::clamp).x;
        for (int c = 0; c < 3; ++c) EXPECT_EQ(cube.table->fetch(x, y, face, c), want) << face << " " << x << "," << y;
      }
  EXPECT_FALSE(bake("brdf_factor", GeneratorParams(p).set("Shape", "sphere")).ok());
}

TEST(Noise, DeterministicPeriodicAndTileable) {
  NoiseTableOptions o{.width = 16,
                      .height = 16,
                      .depth = 16,
                      .channels = 3,
                      .noise = {.period = 4, .seed = 7},
                      .format = TableFormat::float32};
  Table a = bake_noise_table(o), b = bake_noise_table(o);
  EXPECT_EQ(a.float32, b.float32);
  o.noise.seed = 8;
  EXPECT_NE(bake_noise_table(o).float32, a.float32);
  // The function repeats every period (up to the rounding of p + period).
  for (NoiseKind kind : {NoiseKind::gradient, NoiseKind::value})
    for (int oct : {1, 3}) {
      NoiseSpec s{.period = 4, .seed = 3, .kind = kind, .octaves = oct};
      for (double x = -5.3; x < 5; x += 0.71) {
        glm::dvec3 p(x, 0.37 * x + 0.1, 1.9 - x);
        double v = lattice_noise(s, p, 1);
        EXPECT_NEAR(v, lattice_noise(s, p + glm::dvec3(4, 0, 0), 1), 1e-12);
        EXPECT_NEAR(v, lattice_noise(s, p + glm::dvec3(0, -8, 4), 1), 1e-12);
        EXPECT_LE(std::abs(v), 1.5);
      }
    }
  // Tileable texture: the step across the wrap seam (last texel -> first) is no larger
  // than the largest step between interior neighbours.
  double interior = 0, seam = 0;
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y) {
      for (int x = 0; x + 1 < 16; ++x)
        interior = std::max(interior, double(std::abs(a.fetch(x + 1, y, z, 0) - a.fetch(x, y, z, 0))));
      seam = std::max(seam, double(std::abs(a.fetch(0, y, z, 0) - a.fetch(15, y, z, 0))));
    }
  EXPECT_LE(seam, interior);
  EXPECT_GT(interior, 0.0);
}

TEST(BrdfFactorization, SeparableLobesReconstructCloselyPhongLessSo) {
  // Blinn-Phong (N.H)^n cos(theta_i) and Ward are exactly p(wi) q(wh) p(wo): the only
  // error left is 32x32 bilinear interpolation of the factors. Phong's (R.V)^n is not a
  // product of those three functions, so it keeps a visibly larger error.
  BrdfFactorizationOptions fit;
  fit.size = 32;
  fit.samples = 12000;
  fit.iterations = 200;
  double rel[3];
  for (BrdfLobe lobe : {BrdfLobe::blinn_phong, BrdfLobe::ward, BrdfLobe::phong}) {
    AnalyticBrdf brdf;
    brdf.lobe = lobe;
    brdf.exponent = 8;
    brdf.alpha_x = 0.3;
    brdf.alpha_y = 0.5;
    BrdfFactors f = factorize_brdf(brdf, fit);
    FactorizationError e = measure_factorization(f, brdf, 4000, 99);
    rel[int(lobe)] = e.relative_rmse;
    std::printf(
        "[ measured ] BRDF factorization 3x%dx%d, lobe %d: relative RMSE %.3f, max abs %.3f, "
        "log residual %.3f\n",
        fit.size, fit.size, int(lobe), e.relative_rmse, e.max_abs, f.log_residual_rms);
    EXPECT_TRUE(std::isfinite(e.rmse));
  }
  // Blinn-Phong: only interpolation error is left (measured 2.5%). Ward: exact in form,
  // but its 1/sqrt(cos_i cos_o) is singular at the horizon, which 32x32 texels cannot
  // follow (measured ~46%, all at grazing angles). Phong: a poor fit (see the docs).
  EXPECT_LT(rel[int(BrdfLobe::blinn_phong)], 0.05);
  EXPECT_LT(rel[int(BrdfLobe::ward)], 0.6);
  EXPECT_GT(rel[int(BrdfLobe::phong)], 5 * rel[int(BrdfLobe::blinn_phong)]);
}

// Iterating far past convergence must not break the factors: CGLS used to run until q.q
// was denormal, alpha went to Inf and every texel to NaN (size 8, smoothness 0.3, 300
// iterations converge in about 50).
TEST(BrdfFactorization, IteratingPastConvergenceKeepsFactorsFinite) {
  AnalyticBrdf brdf;
  brdf.lobe = BrdfLobe::phong;
  brdf.exponent = 8;
  BrdfFactorizationOptions fit;
  fit.size = 8;
  fit.smoothness = 0.3;
  BrdfFactors converged = factorize_brdf(brdf, (fit.iterations = 100, fit));
  BrdfFactors f = factorize_brdf(brdf, (fit.iterations = 300, fit));
  for (const Table* t : {&f.in, &f.half, &f.out}) {
    ASSERT_GT(t->float32.size(), 0u);
    for (float v : t->float32) ASSERT_TRUE(std::isfinite(v));
  }
  EXPECT_NEAR(f.log_residual_rms, converged.log_residual_rms, 1e-6);
  EXPECT_TRUE(std::isfinite(measure_factorization(f, brdf, 1000, 5).rmse));
}

TEST(BrdfFactorization, InvalidOptionsGiveEmptyFactors) {
  BrdfFactorizationOptions fit;
  fit.size = 1;
  BrdfFactors f = factorize_brdf({}, fit);
  EXPECT_EQ(f.in.value_count(), 0u);
  EXPECT_EQ(evaluate_factored(f, glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1)), 0.0);
}

}  // namespace
}  // namespace fx::shading
