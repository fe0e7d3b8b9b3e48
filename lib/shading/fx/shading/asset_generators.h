// Procedural texture assets: the direction maps, normal maps, height maps, colour maps and
// gloss maps the seed effects sample, baked from a few parameters so every effect renders
// its seed's picture without image files (an engine binds its own textures instead).
// Each has an options struct, a validator (empty string = valid) and a baker; an invalid
// options struct bakes an empty Table (width 0). All tables are 2D RGBA; unorm8 unless
// said otherwise. Registry names and annotation vocabulary: docs/shading-math.md.
#pragma once
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "fx/shading/noise.h"
#include "fx/shading/table.h"

namespace fx::shading {

// How a strand direction varies over the texture. The centred patterns turn around the
// uv centre (0.5, 0.5): `circular` runs around it (CD grooves, a brushed disc's rings),
// `radial` points away from it, `swirl` is `circular` turned by a fixed pitch (a spiral).
enum class DirectionPattern { linear, radial, circular, swirl };

// Shared by direction_field and gloss_map: the pattern and its jitter.
struct DirectionSpec {
  DirectionPattern pattern = DirectionPattern::linear;
  double angle_deg = 0;  // linear: angle from +u toward +v; swirl: pitch off the circle
  double jitter = 0;     // radians of noise rotation at noise amplitude 1 (hair strands)
  int frequency = 16;    // jitter noise cells per texture edge (tiles seamlessly)
  uint32_t seed = 1;
};

// The strand angle (radians, from +u toward +v) at texture coordinate uv in [0, 1]^2.
double strand_angle(const DirectionSpec& spec, const glm::dvec2& uv);

// direction_field: rgb = 0.5 T + 0.5 with T = (cos a, sin a, 0), a = strand_angle; a = 1
// (the seed's ps.1.4 shader reads the direction map's alpha as 1).
struct DirectionFieldOptions {
  int width = 256, height = 256;
  TableFormat format = TableFormat::unorm8;  // float32 stores the same encoded values
  DirectionSpec direction;
};
std::string validate(const DirectionFieldOptions& o);
Table bake_direction_field(const DirectionFieldOptions& o);

// The height field behind normal_map, height_map and the `noise` colour pattern:
// fractal lattice noise over a tile of `frequency` cells (tileable), or `streaks`
// (fibres along u: noise that varies across v `stretch` times faster, with a little
// 2D noise so the fibres break up).
enum class HeightPattern { noise, streaks };
struct HeightSpec {
  HeightPattern pattern = HeightPattern::noise;
  int frequency = 8;  // lattice cells per texture edge
  int octaves = 4;
  int stretch = 8;  // streaks only: fibres per lattice cell across v
  NoiseKind kind = NoiseKind::gradient;
  uint32_t seed = 1;
};

// Height in [0, 1] at texture coordinate uv; periodic with period 1 in u and v.
double height_at(const HeightSpec& spec, const glm::dvec2& uv);

// normal_map: rgb = 0.5 N + 0.5, N = normalize(-s dH/dx, -s dH/dy, 1) with H the height
// field, x, y in lattice cells (central differences on the texel grid, wrapped) and s =
// strength; alpha = height, or occlusion: the fraction of the sky hemisphere the relief
// blocks (0 on a plane), 1 - the mean over 8 directions of cos^2 of the horizon elevation
// (cos^2 h is the cosine-weighted visible fraction under a horizon at elevation h), as the
// hemisphere effect's `ambient * (1 - occlusion)` reads it; or 1.
enum class NormalMapAlpha { height, occlusion, one };
struct NormalMapOptions {
  int width = 256, height = 256;
  TableFormat format = TableFormat::unorm8;
  HeightSpec relief;
  double strength = 1.0;
  NormalMapAlpha alpha = NormalMapAlpha::height;
};
std::string validate(const NormalMapOptions& o);
Table bake_normal_map(const NormalMapOptions& o);

// height_map: rgb = a = height (for emboss bump mapping, which subtracts two shifted reads).
struct HeightMapOptions {
  int width = 256, height = 256;
  TableFormat format = TableFormat::unorm8;
  HeightSpec relief;
};
std::string validate(const HeightMapOptions& o);
Table bake_height_map(const HeightMapOptions& o);

// color_map: a base colour. `noise` blends colour0 -> colour1 where the height field
// crosses `threshold` (blend width `softness`: earth-like land and sea); `streaks` blends
// by the streak field (brushed metal, hair); `checker` alternates `checks` squares per
// edge; `spot` is colour1 in a Gaussian spot of radius `radius` at the centre over
// colour0 (the specular-emboss highlight texture). alpha = gloss0 -> gloss1 by the same
// blend weight.
enum class ColorPattern { noise, streaks, checker, spot };
struct ColorMapOptions {
  int width = 256, height = 256;
  TableFormat format = TableFormat::unorm8;
  ColorPattern pattern = ColorPattern::noise;
  HeightSpec relief;  // noise and streaks
  glm::dvec3 color0{0.1, 0.1, 0.1}, color1{0.9, 0.9, 0.9};
  double gloss0 = 1.0, gloss1 = 1.0;
  double threshold = 0.5, softness = 0.1;
  int checks = 8;
  double radius = 0.25;
};
std::string validate(const ColorMapOptions& o);
Table bake_color_map(const ColorMapOptions& o);

// gloss_map, the GLSL anisotropic-highlights seed's layout: r = highlight brightness,
// g = sqrt(exponent / 128), b = strand angle code (0 isotropic, 3..182 = 1..180 degrees
// from the tangent, the seed's `b * 255 - 2`), a = 1. Brightness varies by
// `brightness_variation` times the streak field (fibres along the strands).
struct GlossMapOptions {
  int width = 256, height = 256;
  TableFormat format = TableFormat::unorm8;
  bool isotropic = false;
  DirectionSpec direction;
  double brightness = 1.0, brightness_variation = 0.0;
  double exponent = 32;
  HeightSpec fibres{.pattern = HeightPattern::streaks};
};
std::string validate(const GlossMapOptions& o);
Table bake_gloss_map(const GlossMapOptions& o);

// The gloss map's angle code for a strand angle (radians, any value: strands have no
// sign, so it is reduced to (0, 180] degrees).
int gloss_angle_code(double angle_rad);

}  // namespace fx::shading
