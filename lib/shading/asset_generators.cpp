// Procedural texture assets (direction, normal, height, colour and gloss maps) and their
// annotation readers for the generator registry.
#include "fx/shading/asset_generators.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "param_reader.h"

namespace fx::shading {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Same edge bound as the table bakers (bakers.cpp; 4096^2 is their 2^24-texel cap):
// annotation typos must not exhaust memory.
constexpr int kMaxEdge = 4096;

std::string check_size(int width, int height) {
  for (auto [what, n] : {std::pair{"Width", width}, std::pair{"Height", height}})
    if (n < 1 || n > kMaxEdge)
      return std::string(what) + " must be in [1, " + std::to_string(kMaxEdge) + "], got " + std::to_string(n);
  return {};
}

std::string check_range(const char* what, double v, double lo, double hi) {
  if (!std::isfinite(v) || v < lo || v > hi) {
    std::ostringstream s;
    s << what << " must be a number in [" << lo << ", " << hi << "]";
    return s.str();
  }
  return {};
}

std::string check_direction(const DirectionSpec& d) {
  if (auto e = check_range("Angle", d.angle_deg, -360, 360); !e.empty()) return e;
  if (auto e = check_range("Amount", d.jitter, 0, kPi); !e.empty()) return e;
  if (d.frequency < 1 || d.frequency > 256) return "Frequency must be in [1, 256]";
  return {};
}

std::string check_relief(const HeightSpec& h) {
  if (h.frequency < 1 || h.frequency > 256) return "Frequency must be in [1, 256]";
  if (h.octaves < 1 || h.octaves > 8) return "Octaves must be in [1, 8]";
  if (h.stretch < 1 || h.stretch > 64) return "Stretch must be in [1, 64]";
  return {};
}

glm::dvec2 texel_uv(const Table& t, int x, int y) { return {(x + 0.5) / t.width, (y + 0.5) / t.height}; }

int wrap(int i, int n) { return ((i % n) + n) % n; }

// 0 below edge0, 1 above edge1, smooth between; a step when the edges meet.
double smoothstep(double edge0, double edge1, double x) {
  if (edge1 <= edge0) return x < edge0 ? 0.0 : 1.0;
  double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The height field sampled at texel centres (x fastest), for finite differences.
std::vector<double> height_grid(const HeightSpec& spec, int width, int height) {
  std::vector<double> h(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) h[size_t(y) * width + x] = height_at(spec, {(x + 0.5) / width, (y + 0.5) / height});
  return h;
}

}  // namespace

double strand_angle(const DirectionSpec& spec, const glm::dvec2& uv) {
  const double pitch = spec.angle_deg * kPi / 180.0;
  double a = pitch;
  if (spec.pattern != DirectionPattern::linear) {
    const double around = std::atan2(uv.y - 0.5, uv.x - 0.5);  // atan2(0, 0) = 0 at the centre
    a = spec.pattern == DirectionPattern::radial     ? around
        : spec.pattern == DirectionPattern::circular ? around + 0.5 * kPi
                                                     : around + 0.5 * kPi + pitch;
  }
  if (spec.jitter > 0) {
    NoiseSpec n{.period = spec.frequency, .seed = spec.seed, .kind = NoiseKind::gradient, .octaves = 2};
    a += spec.jitter * lattice_noise(n, {uv.x * spec.frequency, uv.y * spec.frequency, 0.5}, 0);
  }
  return a;
}

double height_at(const HeightSpec& spec, const glm::dvec2& uv) {
  NoiseSpec n{.period = spec.frequency, .seed = spec.seed, .kind = spec.kind, .octaves = spec.octaves};
  const double f = spec.frequency;
  double v = lattice_noise(n, {uv.x * f, uv.y * f, 0.5}, 0);
  if (spec.pattern == HeightPattern::streaks) {
    // Fibres: noise constant along u (x fixed off the lattice, where gradient noise is 0).
    NoiseSpec fibre = n;
    fibre.period = spec.frequency * spec.stretch;
    double across = lattice_noise(fibre, {0.37, uv.y * fibre.period, 0.5}, 1);
    v = 0.75 * across + 0.25 * v;
  }
  // Gradient fractal noise spans about [-0.7, 0.7]; widen it to use the 8-bit range.
  return std::clamp(0.5 + 0.7 * v, 0.0, 1.0);
}

std::string validate(const DirectionFieldOptions& o) {
  if (auto e = check_size(o.width, o.height); !e.empty()) return e;
  return check_direction(o.direction);
}

Table bake_direction_field(const DirectionFieldOptions& o) {
  if (!validate(o).empty()) return {};
  Table t = Table::make(o.width, o.height, 1, 4, o.format);
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      double a = strand_angle(o.direction, texel_uv(t, x, y));
      t.store(x, y, 0, 0, 0.5 * std::cos(a) + 0.5);
      t.store(x, y, 0, 1, 0.5 * std::sin(a) + 0.5);
      t.store(x, y, 0, 2, 0.5);
      t.store(x, y, 0, 3, 1.0);
    }
  return t;
}

std::string validate(const NormalMapOptions& o) {
  if (auto e = check_size(o.width, o.height); !e.empty()) return e;
  if (auto e = check_relief(o.relief); !e.empty()) return e;
  return check_range("Strength", o.strength, 0, 64);
}

Table bake_normal_map(const NormalMapOptions& o) {
  if (!validate(o).empty()) return {};
  const int w = o.width, h = o.height;
  const std::vector<double> hg = height_grid(o.relief, w, h);
  auto at = [&](int x, int y) { return hg[size_t(wrap(y, h)) * w + wrap(x, w)]; };
  // Texel spacing in lattice cells: slopes (and so Strength) do not depend on resolution.
  const double dx = double(o.relief.frequency) / w, dy = double(o.relief.frequency) / h;
  Table t = Table::make(w, h, 1, 4, o.format);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::dvec3 n(-o.strength * (at(x + 1, y) - at(x - 1, y)) / (2 * dx),
                   -o.strength * (at(x, y + 1) - at(x, y - 1)) / (2 * dy), 1.0);
      n = glm::normalize(n);
      for (int c = 0; c < 3; ++c) t.store(x, y, 0, c, 0.5 * n[c] + 0.5);
      double alpha = 1.0;
      if (o.alpha == NormalMapAlpha::height) alpha = at(x, y);
      if (o.alpha == NormalMapAlpha::occlusion) {
        // Horizon per direction over half a lattice cell (at least 4 texels).
        const int reach = std::max(4, int(0.5 / std::min(dx, dy)));
        double visible = 0.0;
        for (int d = 0; d < 8; ++d) {
          const double phi = d * kPi / 4;
          double horizon = 0.0;  // tangent of the highest elevation seen
          for (int s = 1; s <= 8; ++s) {
            const double r = reach * s / 8.0;
            const int sx = int(std::lround(x + r * std::cos(phi))), sy = int(std::lround(y + r * std::sin(phi)));
            const double run = std::hypot((sx - x) * dx, (sy - y) * dy);
            if (run > 0) horizon = std::max(horizon, o.strength * (at(sx, sy) - at(x, y)) / run);
          }
          visible += 1.0 / (1.0 + horizon * horizon);  // cos^2 of the horizon elevation
        }
        alpha = 1.0 - visible / 8.0;  // the blocked fraction, as the hemisphere effect reads it
      }
      t.store(x, y, 0, 3, alpha);
    }
  return t;
}

std::string validate(const HeightMapOptions& o) {
  if (auto e = check_size(o.width, o.height); !e.empty()) return e;
  return check_relief(o.relief);
}

Table bake_height_map(const HeightMapOptions& o) {
  if (!validate(o).empty()) return {};
  Table t = Table::make(o.width, o.height, 1, 4, o.format);
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      double v = height_at(o.relief, texel_uv(t, x, y));
      for (int c = 0; c < 4; ++c) t.store(x, y, 0, c, v);
    }
  return t;
}

std::string validate(const ColorMapOptions& o) {
  if (auto e = check_size(o.width, o.height); !e.empty()) return e;
  if (auto e = check_relief(o.relief); !e.empty()) return e;
  for (int c = 0; c < 3; ++c) {
    if (auto e = check_range("Color0 components", o.color0[c], 0, 1); !e.empty()) return e;
    if (auto e = check_range("Color1 components", o.color1[c], 0, 1); !e.empty()) return e;
  }
  if (auto e = check_range("Gloss0", o.gloss0, 0, 1); !e.empty()) return e;
  if (auto e = check_range("Gloss1", o.gloss1, 0, 1); !e.empty()) return e;
  if (auto e = check_range("Threshold", o.threshold, 0, 1); !e.empty()) return e;
  if (auto e = check_range("Softness", o.softness, 0, 1); !e.empty()) return e;
  if (auto e = check_range("Radius", o.radius, 1e-3, 4); !e.empty()) return e;
  if (o.checks < 1 || o.checks > 1024) return "Checks must be in [1, 1024]";
  return {};
}

Table bake_color_map(const ColorMapOptions& o) {
  if (!validate(o).empty()) return {};
  HeightSpec relief = o.relief;
  if (o.pattern == ColorPattern::streaks) relief.pattern = HeightPattern::streaks;
  Table t = Table::make(o.width, o.height, 1, 4, o.format);
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      const glm::dvec2 uv = texel_uv(t, x, y);
      double weight = 0.0;
      switch (o.pattern) {
        case ColorPattern::noise:
        case ColorPattern::streaks:
          weight = smoothstep(o.threshold - o.softness, o.threshold + o.softness, height_at(relief, uv));
          break;
        case ColorPattern::checker:
          weight = double((int(std::floor(uv.x * o.checks)) + int(std::floor(uv.y * o.checks))) & 1);
          break;
        case ColorPattern::spot: {
          const double r = glm::length(uv - glm::dvec2(0.5)) / o.radius;
          weight = std::exp(-r * r);
          break;
        }
      }
      const glm::dvec3 c = glm::mix(o.color0, o.color1, weight);
      for (int k = 0; k < 3; ++k) t.store(x, y, 0, k, c[k]);
      t.store(x, y, 0, 3, o.gloss0 + (o.gloss1 - o.gloss0) * weight);
    }
  return t;
}

int gloss_angle_code(double angle_rad) {
  double deg = std::fmod(angle_rad * 180.0 / kPi, 180.0);
  if (!(deg > 0)) deg += 180.0;  // (-180, 0] -> (0, 180]; NaN stays NaN and is caught below
  long whole = std::isfinite(deg) ? std::lround(deg) : 180;
  if (whole < 1) whole = 180;  // 0.4 degrees is next to 180 for a signless strand
  return int(std::min(whole, 180L)) + 2;
}

std::string validate(const GlossMapOptions& o) {
  if (auto e = check_size(o.width, o.height); !e.empty()) return e;
  if (auto e = check_direction(o.direction); !e.empty()) return e;
  if (auto e = check_relief(o.fibres); !e.empty()) return e;
  if (auto e = check_range("Brightness", o.brightness, 0, 1); !e.empty()) return e;
  if (auto e = check_range("Variation", o.brightness_variation, 0, 1); !e.empty()) return e;
  // The seed decodes g * g * 128.
  return check_range("Exponent", o.exponent, 0, 128);
}

Table bake_gloss_map(const GlossMapOptions& o) {
  if (!validate(o).empty()) return {};
  Table t = Table::make(o.width, o.height, 1, 4, o.format);
  const double g = std::sqrt(o.exponent / 128.0);
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      const glm::dvec2 uv = texel_uv(t, x, y);
      double fibre = o.brightness_variation > 0 ? height_at(o.fibres, uv) : 1.0;
      t.store(x, y, 0, 0, o.brightness * (1.0 - o.brightness_variation * (1.0 - fibre)));
      t.store(x, y, 0, 1, g);
      t.store(x, y, 0, 2, o.isotropic ? 0.0 : gloss_angle_code(strand_angle(o.direction, uv)) / 255.0);
      t.store(x, y, 0, 3, 1.0);
    }
  return t;
}

// ---- annotation readers ---------------------------------------------------------------

namespace detail {

namespace {

uint32_t read_seed(ParamReader& in) {
  double seed = in.number("Seed", 1.0);
  if (seed < 0 || seed > 4294967295.0 || seed != std::floor(seed)) {
    in.fail("Seed must be an integer in [0, 2^32)");
    return 1;
  }
  return uint32_t(seed);
}

void read_size(ParamReader& in, int& width, int& height) {
  width = in.integer("Width", width);
  height = in.integer("Height", width);
}

// Reads DirectionSpec fields; `pattern` is read by the caller (gloss_map adds isotropic).
void read_direction(ParamReader& in, DirectionSpec& d) {
  d.angle_deg = in.number("Angle", d.pattern == DirectionPattern::swirl ? 30.0 : 0.0);
  d.jitter = in.number("Amount", d.jitter);
  d.frequency = in.integer("Frequency", d.frequency);
  d.seed = read_seed(in);
}

void read_relief(ParamReader& in, HeightSpec& h, bool read_pattern) {
  if (read_pattern) h.pattern = HeightPattern(in.choice("Pattern", {"noise", "streaks"}, int(h.pattern)));
  h.frequency = in.integer("Frequency", h.frequency);
  h.octaves = in.integer("Octaves", h.octaves);
  h.stretch = in.integer("Stretch", h.stretch);
  h.kind = in.choice("Kind", {"gradient", "value"}, 0) == 0 ? NoiseKind::gradient : NoiseKind::value;
  h.seed = read_seed(in);
}

// "r g b" or "r, g, b" (numbers in [0, 1]).
glm::dvec3 read_color(ParamReader& in, std::string_view name, glm::dvec3 fallback) {
  std::string text = in.text(name, "");
  if (text.empty()) return fallback;
  std::replace(text.begin(), text.end(), ',', ' ');
  std::istringstream s(text);
  glm::dvec3 c;
  std::string rest;
  if (!(s >> c.r >> c.g >> c.b) || (s >> rest)) {
    in.fail(std::string(name) + " must be three numbers \"r g b\", got \"" + in.text(name, "") + "\"");
    return fallback;
  }
  return c;
}

}  // namespace

BakeResult bake_direction_field_asset(ParamReader& in) {
  DirectionFieldOptions o;
  read_size(in, o.width, o.height);
  o.direction.pattern = DirectionPattern(in.choice("Pattern", {"linear", "radial", "circular", "swirl"}, 0));
  read_direction(in, o.direction);
  o.format = in.format(o.format);
  return finish(in, o, bake_direction_field);
}

BakeResult bake_normal_map_asset(ParamReader& in) {
  NormalMapOptions o;
  read_size(in, o.width, o.height);
  read_relief(in, o.relief, true);
  o.strength = in.number("Strength", o.strength);
  o.alpha = NormalMapAlpha(in.choice("Alpha", {"height", "occlusion", "one"}, int(o.alpha)));
  o.format = in.format(o.format);
  return finish(in, o, bake_normal_map);
}

BakeResult bake_height_map_asset(ParamReader& in) {
  HeightMapOptions o;
  read_size(in, o.width, o.height);
  read_relief(in, o.relief, true);
  o.format = in.format(o.format);
  return finish(in, o, bake_height_map);
}

BakeResult bake_color_map_asset(ParamReader& in) {
  ColorMapOptions o;
  read_size(in, o.width, o.height);
  o.pattern = ColorPattern(in.choice("Pattern", {"noise", "streaks", "checker", "spot"}, int(o.pattern)));
  read_relief(in, o.relief, false);
  o.color0 = read_color(in, "Color0", o.color0);
  o.color1 = read_color(in, "Color1", o.color1);
  o.gloss0 = in.number("Gloss0", o.gloss0);
  o.gloss1 = in.number("Gloss1", o.gloss1);
  o.threshold = in.number("Threshold", o.threshold);
  o.softness = in.number("Softness", o.softness);
  o.checks = in.integer("Checks", o.checks);
  o.radius = in.number("Radius", o.radius);
  o.format = in.format(o.format);
  return finish(in, o, bake_color_map);
}

BakeResult bake_gloss_map_asset(ParamReader& in) {
  GlossMapOptions o;
  read_size(in, o.width, o.height);
  int pattern = in.choice("Pattern", {"isotropic", "linear", "radial", "circular", "swirl"}, 1);
  o.isotropic = pattern == 0;
  o.direction.pattern = DirectionPattern(std::max(0, pattern - 1));
  read_direction(in, o.direction);
  o.fibres.frequency = o.direction.frequency;
  o.fibres.seed = o.direction.seed;
  o.fibres.stretch = in.integer("Stretch", o.fibres.stretch);
  o.brightness = in.number("Brightness", o.brightness);
  o.brightness_variation = in.number("Variation", o.brightness_variation);
  o.exponent = in.number("Exponent", o.exponent);
  o.format = in.format(o.format);
  return finish(in, o, bake_gloss_map);
}

}  // namespace detail

}  // namespace fx::shading
