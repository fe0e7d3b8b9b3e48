// Texture-asset generators: decoded directions and normals are unit vectors where they
// must be, tables tile, bakes are deterministic, patterns point where they say, and bad
// parameters are errors in the registry's usual words.
#include <cmath>

#include <gtest/gtest.h>

#include "fx/shading/asset_generators.h"
#include "fx/shading/generator.h"

namespace fx::shading {
namespace {

constexpr double kPi = 3.14159265358979323846;
// One 8-bit step of a 0.5x+0.5 encoding, decoded: 2/255, plus rounding slack.
constexpr double kEncodedStep = 2.0 / 255.0;

glm::dvec3 decode(const Table& t, int x, int y) {
  return {2.0 * t.fetch(x, y, 0, 0) - 1.0, 2.0 * t.fetch(x, y, 0, 1) - 1.0, 2.0 * t.fetch(x, y, 0, 2) - 1.0};
}

Table baked(std::string_view generator, const GeneratorParams& p) {
  BakeResult r = bake(generator, p);
  EXPECT_TRUE(r.ok()) << generator << ": " << r.message;
  return r.ok() ? *r.table : Table{};
}

TEST(DirectionField, EveryPatternDecodesToUnitVectorsInTheTangentPlane) {
  for (const char* pattern : {"linear", "radial", "circular", "swirl"}) {
    SCOPED_TRACE(pattern);
    Table t = baked("direction_field",
                    GeneratorParams().set("Pattern", pattern).set("Width", 64).set("Amount", 0.4).set("UIName", "x"));
    ASSERT_EQ(t.width, 64);
    ASSERT_EQ(t.channels, 4);
    double worst_len = 0, worst_z = 0;
    for (int y = 0; y < t.height; ++y)
      for (int x = 0; x < t.width; ++x) {
        glm::dvec3 d = decode(t, x, y);
        worst_len = std::max(worst_len, std::abs(glm::length(d) - 1.0));
        worst_z = std::max(worst_z, std::abs(d.z));
        EXPECT_EQ(t.fetch(x, y, 0, 3), 1.0f);  // the ps.1.4 shader relies on alpha = 1
      }
    EXPECT_LT(worst_len, kEncodedStep);
    EXPECT_LT(worst_z, kEncodedStep);
  }
}

TEST(DirectionField, PatternsPointWhereTheySay) {
  DirectionFieldOptions o;
  o.width = o.height = 65;
  // Linear along u by default; Angle 90 turns it to v.
  EXPECT_NEAR(decode(bake_direction_field(o), 10, 20).x, 1.0, kEncodedStep);
  o.direction.angle_deg = 90;
  EXPECT_NEAR(decode(bake_direction_field(o), 10, 20).y, 1.0, kEncodedStep);
  // Right of the centre (texel 60, 32 of 65): radial points along +u, circular along +v.
  o.direction = {.pattern = DirectionPattern::radial};
  EXPECT_NEAR(decode(bake_direction_field(o), 60, 32).x, 1.0, kEncodedStep);
  o.direction.pattern = DirectionPattern::circular;
  glm::dvec3 c = decode(bake_direction_field(o), 60, 32);
  EXPECT_NEAR(std::abs(c.y), 1.0, kEncodedStep);
  // Circular directions are perpendicular to the radius everywhere.
  Table ring = bake_direction_field(o);
  for (int y = 0; y < 65; y += 7)
    for (int x = 0; x < 65; x += 5) {
      glm::dvec2 r((x + 0.5) / 65 - 0.5, (y + 0.5) / 65 - 0.5);
      if (glm::length(r) < 0.05) continue;
      glm::dvec3 d = decode(ring, x, y);
      EXPECT_NEAR(glm::dot(glm::normalize(r), glm::dvec2(d)), 0.0, 2 * kEncodedStep) << x << "," << y;
    }
  // Swirl is circular turned by the pitch.
  DirectionSpec swirl{.pattern = DirectionPattern::swirl, .angle_deg = 30};
  DirectionSpec circular{.pattern = DirectionPattern::circular};
  EXPECT_NEAR(strand_angle(swirl, {0.8, 0.3}) - strand_angle(circular, {0.8, 0.3}), kPi / 6, 1e-12);
}

TEST(DirectionField, JitterTilesAndFollowsTheSeed) {
  DirectionSpec a{.jitter = 0.5, .frequency = 4, .seed = 7};
  for (double v : {0.0, 0.3, 0.71}) EXPECT_NEAR(strand_angle(a, {0.0, v}), strand_angle(a, {1.0, v}), 1e-9);
  for (double u : {0.0, 0.45, 0.9}) EXPECT_NEAR(strand_angle(a, {u, 0.0}), strand_angle(a, {u, 1.0}), 1e-9);
  DirectionSpec b = a;
  b.seed = 8;
  double differ = 0;
  for (int i = 0; i < 16; ++i) differ += std::abs(strand_angle(a, {i / 16.0, 0.3}) - strand_angle(b, {i / 16.0, 0.3}));
  EXPECT_GT(differ, 0.1);
}

TEST(NormalMap, UnitNormalsFacingOutAndSeamless) {
  for (const char* pattern : {"noise", "streaks"}) {
    SCOPED_TRACE(pattern);
    Table t = baked("normal_map", GeneratorParams().set("Pattern", pattern).set("Width", 64).set("Strength", 3));
    double worst = 0, min_z = 1, max_tilt = 0;
    for (int y = 0; y < t.height; ++y)
      for (int x = 0; x < t.width; ++x) {
        glm::dvec3 n = decode(t, x, y);
        worst = std::max(worst, std::abs(glm::length(n) - 1.0));
        min_z = std::min(min_z, n.z);
        max_tilt = std::max(max_tilt, std::hypot(n.x, n.y));
      }
    EXPECT_LT(worst, 2 * kEncodedStep);
    EXPECT_GT(min_z, 0.0);
    EXPECT_GT(max_tilt, 0.3);  // there are bumps to see
    // Across the wrap seam the normals change no more than between inner neighbours.
    double seam = 0, inner = 0;
    for (int y = 0; y < t.height; ++y) {
      seam = std::max(seam, glm::length(decode(t, 0, y) - decode(t, t.width - 1, y)));
      inner = std::max(inner, glm::length(decode(t, 1, y) - decode(t, 0, y)));
    }
    for (int x = 0; x < t.width; ++x) seam = std::max(seam, glm::length(decode(t, x, 0) - decode(t, x, t.height - 1)));
    EXPECT_LT(seam, 2 * inner + kEncodedStep);
  }
}

TEST(NormalMap, StrengthZeroIsFlatAndOcclusionDarkensValleys) {
  NormalMapOptions flat;
  flat.width = flat.height = 32;
  flat.strength = 0;
  flat.alpha = NormalMapAlpha::occlusion;
  Table f = bake_normal_map(flat);
  for (int i = 0; i < 32; ++i) {
    EXPECT_NEAR(decode(f, i, (i * 7) % 32).z, 1.0, kEncodedStep);
    EXPECT_EQ(f.fetch(i, (i * 7) % 32, 0, 3), 0.0f);  // nothing occludes a plane
  }
  NormalMapOptions o;
  o.width = o.height = 64;
  o.strength = 2;
  o.alpha = NormalMapAlpha::occlusion;
  Table t = bake_normal_map(o);
  // Occlusion correlates negatively with height: valleys see less sky than peaks.
  double sh = 0, sa = 0, shh = 0, saa = 0, sha = 0, n = 64 * 64;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      double h = height_at(o.relief, {(x + 0.5) / 64, (y + 0.5) / 64}), a = t.fetch(x, y, 0, 3);
      sh += h, sa += a, shh += h * h, saa += a * a, sha += h * a;
    }
  double corr = (sha / n - sh / n * sa / n) / std::sqrt((shh / n - sh * sh / n / n) * (saa / n - sa * sa / n / n));
  EXPECT_LT(corr, -0.3);
  EXPECT_GT(sa / n, 0.001);
}

TEST(AssetGenerators, HeightMapsTileAndAgreeWithTheHeightField) {
  HeightSpec spec{.frequency = 4, .octaves = 3, .seed = 3};
  for (double v : {0.1, 0.5, 0.93}) EXPECT_NEAR(height_at(spec, {0.0, v}), height_at(spec, {1.0, v}), 1e-9);
  HeightSpec streaks = spec;
  streaks.pattern = HeightPattern::streaks;
  for (double u : {0.1, 0.5, 0.93}) EXPECT_NEAR(height_at(streaks, {u, 0.0}), height_at(streaks, {u, 1.0}), 1e-9);
  Table t =
      baked("height_map", GeneratorParams().set("Frequency", 4).set("Octaves", 3).set("Seed", 3).set("Width", 32));
  double lo = 1, hi = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      double h = t.fetch(x, y, 0, 0);
      EXPECT_NEAR(h, height_at(spec, {(x + 0.5) / 32, (y + 0.5) / 32}), 0.5 / 255 + 1e-6);
      EXPECT_EQ(t.fetch(x, y, 0, 3), t.fetch(x, y, 0, 0));
      lo = std::min(lo, h), hi = std::max(hi, h);
    }
  EXPECT_GT(hi - lo, 0.4);  // relief worth embossing
}

TEST(AssetGenerators, ColorMapPatterns) {
  GeneratorParams checker;
  checker.set("Pattern", "checker").set("Checks", 2).set("Width", 8).set("Color0", "1 0 0").set("Color1", "0, 0, 1");
  checker.set("Gloss0", 0.25).set("Gloss1", 0.75);
  Table c = baked("color_map", checker);
  EXPECT_EQ(c.fetch(0, 0, 0, 0), 1.0f);
  EXPECT_EQ(c.fetch(0, 0, 0, 2), 0.0f);
  EXPECT_EQ(c.fetch(5, 0, 0, 2), 1.0f);
  EXPECT_NEAR(c.fetch(5, 0, 0, 3), 0.75, 0.5 / 255);
  EXPECT_NEAR(c.fetch(5, 5, 0, 3), 0.25, 0.5 / 255);
  Table spot =
      baked("color_map",
            GeneratorParams().set("Pattern", "spot").set("Width", 33).set("Color0", "0 0 0").set("Color1", "1 1 1"));
  EXPECT_GT(spot.fetch(16, 16, 0, 0), 0.99f);
  EXPECT_LT(spot.fetch(0, 0, 0, 0), 0.2f);
  // noise: both colours appear, and the bake is deterministic per seed.
  Table a = baked("color_map", GeneratorParams().set("Width", 64).set("Seed", 5));
  Table b = baked("color_map", GeneratorParams().set("Width", 64).set("Seed", 5));
  Table other = baked("color_map", GeneratorParams().set("Width", 64).set("Seed", 6));
  EXPECT_EQ(a.unorm8, b.unorm8);
  EXPECT_NE(a.unorm8, other.unorm8);
  float lo = 1, hi = 0;
  for (int i = 0; i < 64 * 64; ++i)
    lo = std::min(lo, a.fetch(i % 64, i / 64, 0, 0)), hi = std::max(hi, a.fetch(i % 64, i / 64, 0, 0));
  EXPECT_LT(lo, 0.15f);
  EXPECT_GT(hi, 0.85f);
}

TEST(GlossMap, TheSeedsEncoding) {
  EXPECT_EQ(gloss_angle_code(0.0), 182);      // along the tangent = 180 degrees
  EXPECT_EQ(gloss_angle_code(kPi / 180), 3);  // 1 degree: the seed's lowest code
  EXPECT_EQ(gloss_angle_code(kPi / 2), 92);
  EXPECT_EQ(gloss_angle_code(-kPi / 2), 92);  // strands have no sign
  EXPECT_EQ(gloss_angle_code(3 * kPi / 2), 92);
  Table t = baked("gloss_map",
                  GeneratorParams().set("Width", 16).set("Angle", 45).set("Exponent", 32).set("Brightness", 0.8));
  for (int i = 0; i < 16; ++i) {
    EXPECT_NEAR(t.fetch(i, i, 0, 0), 0.8, 0.5 / 255);
    EXPECT_NEAR(t.fetch(i, i, 0, 1) * t.fetch(i, i, 0, 1) * 128.0, 32.0, 0.6);  // the seed's decode
    EXPECT_NEAR(t.fetch(i, i, 0, 2) * 255.0 - 2.0, 45.0, 1e-3);
  }
  Table iso = baked("gloss_map", GeneratorParams().set("Width", 4).set("Pattern", "isotropic"));
  EXPECT_EQ(iso.fetch(1, 2, 0, 2), 0.0f);
  Table fibres = baked("gloss_map", GeneratorParams().set("Width", 32).set("Variation", 0.8));
  float lo = 1, hi = 0;
  for (int y = 0; y < 32; ++y) lo = std::min(lo, fibres.fetch(3, y, 0, 0)), hi = std::max(hi, fibres.fetch(3, y, 0, 0));
  EXPECT_GT(hi - lo, 0.2f);  // brightness varies across the fibres
}

TEST(AssetGenerators, BadParametersAreErrorsWithReasons) {
  auto fails = [](std::string_view gen, GeneratorParams p, std::string_view needle) {
    BakeResult b = bake(gen, p);
    EXPECT_FALSE(b.ok()) << gen;
    EXPECT_EQ(b.error_id, "bad-generator-parameter") << gen;
    EXPECT_NE(b.message.find(needle), std::string::npos) << b.message;
  };
  fails("direction_field", GeneratorParams().set("Pattern", "circulr"), "did you mean 'circular'");
  fails("direction_field", GeneratorParams().set("Width", 0), "Width");
  fails("direction_field", GeneratorParams().set("Width", 4097), "Width");
  fails("direction_field", GeneratorParams().set("Amount", 9), "Amount");
  fails("direction_field", GeneratorParams().set("Agnle", 9), "did you mean 'Angle'");
  fails("normal_map", GeneratorParams().set("Alpha", "ao"), "Alpha must be one of height, occlusion, one");
  fails("normal_map", GeneratorParams().set("Strength", -1), "Strength");
  fails("normal_map", GeneratorParams().set("Octaves", 9), "Octaves");
  fails("normal_map", GeneratorParams().set("Strenght", 2), "did you mean 'Strength'");
  fails("height_map", GeneratorParams().set("Frequency", 0), "Frequency");
  fails("height_map", GeneratorParams().set("Seed", -1), "Seed");
  fails("color_map", GeneratorParams().set("Color0", "red"), "Color0 must be three numbers");
  fails("color_map", GeneratorParams().set("Color1", "0.1 0.2"), "Color1 must be three numbers");
  fails("color_map", GeneratorParams().set("Color1", "0 2 0"), "Color1");
  fails("color_map", GeneratorParams().set("Color0", 0.5), "must be a string");
  fails("color_map", GeneratorParams().set("Pattern", "checkers"), "did you mean 'checker'");
  fails("gloss_map", GeneratorParams().set("Exponent", 200), "Exponent");
  fails("gloss_map", GeneratorParams().set("Brightness", "high"), "must be a number");
  // Invalid option structs bake empty tables (no abort).
  NormalMapOptions negative;
  negative.width = -3;
  EXPECT_EQ(bake_normal_map(negative).width, 0);
  GlossMapOptions nan;
  nan.exponent = NAN;
  EXPECT_EQ(bake_gloss_map(nan).width, 0);
}

TEST(AssetGenerators, RegisteredAndDeterministic) {
  std::vector<std::string_view> names = generator_names();
  for (const char* g : {"direction_field", "normal_map", "height_map", "color_map", "gloss_map"}) {
    SCOPED_TRACE(g);
    EXPECT_NE(std::find(names.begin(), names.end(), g), names.end());
    GeneratorParams p;
    p.set("Width", 16).set("UIName", "An engine binds its own texture here");
    Table a = baked(g, p), b = baked(g, p);
    EXPECT_EQ(a.width, 16);
    EXPECT_EQ(a.height, 16);
    EXPECT_EQ(a.unorm8, b.unorm8);
    Table f = baked(g, GeneratorParams(p).set("Format", "float32"));
    ASSERT_EQ(f.float32.size(), a.unorm8.size());
    for (size_t i = 0; i < a.unorm8.size(); ++i) EXPECT_NEAR(f.float32[i] * 255.0, a.unorm8[i], 0.5 + 1e-3);
  }
}

}  // namespace
}  // namespace fx::shading
