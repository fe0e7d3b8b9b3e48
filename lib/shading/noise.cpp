#include "fx/shading/noise.h"

#include <cmath>

namespace fx::shading {

uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

namespace {

// Hash of a lattice point, wrapped to the period so the noise tiles.
uint32_t lattice_hash(const NoiseSpec& s, int period, int x, int y, int z, int channel, int octave) {
  auto wrap = [period](int i) {
    int m = i % period;
    return uint32_t(m < 0 ? m + period : m);
  };
  uint32_t h = hash32(s.seed ^ 0x9e3779b9U);
  h = hash32(h ^ wrap(x));
  h = hash32(h ^ (wrap(y) * 0x85ebca6bU));
  h = hash32(h ^ (wrap(z) * 0xc2b2ae35U));
  h = hash32(h ^ (uint32_t(channel) * 0x27d4eb2fU) ^ (uint32_t(octave) << 24));
  return h;
}

double unit(uint32_t h) { return double(h) / 4294967295.0 * 2.0 - 1.0; }  // [-1, 1]

// Quintic fade (Perlin 2002): C2 continuous, so the noise has no visible lattice creases.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

double lattice_value(const NoiseSpec& s, int period, int x, int y, int z, int ch, int oct, double fx, double fy,
                     double fz) {
  uint32_t h = lattice_hash(s, period, x, y, z, ch, oct);
  if (s.kind == NoiseKind::value) return unit(h);
  // Gradient: one of the 12 cube-edge directions (Perlin's improved-noise set).
  static const int g[12][3] = {{1, 1, 0},  {-1, 1, 0},  {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},  {-1, 0, 1},
                               {1, 0, -1}, {-1, 0, -1}, {0, 1, 1},  {0, -1, 1},  {0, 1, -1}, {0, -1, -1}};
  const int* d = g[h % 12];
  return d[0] * fx + d[1] * fy + d[2] * fz;
}

double octave_noise(const NoiseSpec& s, int period, const glm::dvec3& p, int ch, int oct) {
  double bx = std::floor(p.x), by = std::floor(p.y), bz = std::floor(p.z);
  double fx = p.x - bx, fy = p.y - by, fz = p.z - bz;
  // Reduce the cell index modulo the period before converting, so large p cannot overflow.
  auto cell = [period](double b) {
    double m = std::fmod(b, double(period));
    return int(m < 0 ? m + period : m);
  };
  int x = cell(bx), y = cell(by), z = cell(bz);
  double u = fade(fx), v = fade(fy), w = fade(fz);
  double acc = 0.0;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        double wt = (i ? u : 1 - u) * (j ? v : 1 - v) * (k ? w : 1 - w);
        acc += wt * lattice_value(s, period, x + i, y + j, z + k, ch, oct, fx - i, fy - j, fz - k);
      }
  // Gradient noise with this gradient set stays within about [-1, 1]; value noise does.
  return acc;
}

}  // namespace

double lattice_noise(const NoiseSpec& spec, const glm::dvec3& p, int channel) {
  if (spec.period < 1 || spec.octaves < 1 || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    return 0.0;
  double sum = 0.0, amp = 1.0, norm = 0.0;
  int period = spec.period;
  glm::dvec3 q = p;
  for (int o = 0; o < spec.octaves && o < 16; ++o) {
    sum += amp * octave_noise(spec, period, q, channel, o);
    norm += amp;
    amp *= 0.5;
    q *= 2.0;
    period *= 2;
  }
  return sum / norm;
}

}  // namespace fx::shading
