#include "fx/shading/bakers.h"

#include <cmath>
#include <string>

#include "fx/shading/hemisphere.h"

namespace fx::shading {

namespace {

// Largest table edge / volume the bakers accept: bounds memory and bake time for
// annotation-driven bakes (a typo like Width = 1e9 must not take the process down).
constexpr int kMaxEdge = 4096;
constexpr long kMaxTexels = 1L << 24;

std::string check_size(const char* what, int n, int min = 2) {
  if (n < min || n > kMaxEdge)
    return std::string(what) + " must be in [" + std::to_string(min) + ", " + std::to_string(kMaxEdge) + "], got " +
           std::to_string(n);
  return {};
}

std::string check_mapping(LutMapping m, int n) {
  if (!lut_size_valid(m, n)) return "wrap mappings need an even table size, got " + std::to_string(n);
  return {};
}

std::string check_finite(const char* what, double v, double lo, double hi) {
  if (!std::isfinite(v) || v < lo || v > hi)
    return std::string(what) + " must be a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return {};
}

}  // namespace

// ---- strand ---------------------------------------------------------------------------

std::string validate(const StrandTableOptions& o) {
  if (auto e = check_size("Width", o.size); !e.empty()) return e;
  if (auto e = check_mapping(o.mapping, o.size); !e.empty()) return e;
  return check_finite("Exponent", o.exponent, 0.0, 1.0e4);
}

Table bake_strand_table(const StrandTableOptions& o) {
  if (!validate(o).empty()) return {};
  Table t = Table::make(o.size, o.size, 1, 4, o.format);
  for (int j = 0; j < o.size; ++j) {
    double vt = lut_cosine_of_u(o.index, lut_texel_u(o.mapping, o.size, j));
    for (int i = 0; i < o.size; ++i) {
      double lt = lut_cosine_of_u(o.index, lut_texel_u(o.mapping, o.size, i));
      StrandTerms<double> s = strand_from_cosines(lt, vt, o.exponent);
      for (int c = 0; c < 3; ++c) t.store(i, j, 0, c, s.diffuse);
      t.store(i, j, 0, 3, s.specular);
    }
  }
  return t;
}

StrandTerms<float> lookup_strand_table(const Table& t, const StrandTableOptions& o, float lu, float vu) {
  glm::vec3 st(lut_texcoord(o.mapping, o.size, lu), lut_texcoord(o.mapping, o.size, vu), 0.0f);
  glm::vec4 r = sample_linear(t, st, lut_address_mode(o.mapping));
  return {r.x, r.w};
}

// ---- pow (LightEval) -------------------------------------------------------------------

std::string validate(const PowTableOptions& o) {
  if (auto e = check_size("Width", o.width, 1); !e.empty()) return e;
  if (auto e = check_size("Height", o.height); !e.empty()) return e;
  if (long(o.width) * o.height > kMaxTexels) return "Width * Height is too large";
  if (auto e = check_mapping(o.mapping, o.height); !e.empty()) return e;
  if (auto e = check_mapping(o.mapping, o.width < 2 ? 2 : o.width); !e.empty()) return e;
  return check_finite("Exponent", o.exponent, 0.0, 1.0e4);
}

Table bake_pow_table(const PowTableOptions& o) {
  if (!validate(o).empty()) return {};
  Table t = Table::make(o.width, o.height, 1, 4, o.format);
  for (int j = 0; j < o.height; ++j) {
    double y = lut_texel_u(o.mapping, o.height, j);
    double p = guarded_pow(y, o.exponent);
    for (int i = 0; i < o.width; ++i) {
      double x = o.width > 1 ? lut_texel_u(o.mapping, o.width, i) : 0.5;
      for (int c = 0; c < 3; ++c) t.store(i, j, 0, c, p);
      t.store(i, j, 0, 3, x);  // LightEval: col->w = input->x
    }
  }
  return t;
}

float lookup_pow_table(const Table& t, const PowTableOptions& o, float x) {
  float v = lut_texcoord(o.mapping, o.height, saturate(x));
  glm::vec4 r = sample_linear(t, glm::vec3(0.5f, v, 0.0f), lut_address_mode(o.mapping));
  return r.x;
}

// ---- (L.N, H.N) ---------------------------------------------------------------------------

std::string validate(const HalfAngleTableOptions& o) {
  if (auto e = check_size("Width", o.size); !e.empty()) return e;
  if (auto e = check_mapping(o.mapping, o.size); !e.empty()) return e;
  return o.lobe == HalfAngleLobe::blinn_phong ? check_finite("Exponent", o.shape, 0.0, 1.0e4)
                                              : check_finite("Roughness", o.shape, 1.0e-3, 10.0);
}

Table bake_ln_hn_table(const HalfAngleTableOptions& o) {
  if (!validate(o).empty()) return {};
  Table t = Table::make(o.size, o.size, 1, 4, o.format);
  for (int j = 0; j < o.size; ++j) {
    double ln = lut_cosine_of_u(LutIndex::cosine, lut_texel_u(o.mapping, o.size, j));
    for (int i = 0; i < o.size; ++i) {
      double hn = lut_cosine_of_u(LutIndex::cosine, lut_texel_u(o.mapping, o.size, i));
      HalfAngleTerms<double> h = ln_hn_terms(ln, hn, o.lobe, o.shape);
      for (int c = 0; c < 3; ++c) t.store(i, j, 0, c, h.diffuse);
      t.store(i, j, 0, 3, h.specular);
    }
  }
  return t;
}

HalfAngleTerms<float> lookup_ln_hn_table(const Table& t, const HalfAngleTableOptions& o, float ln, float hn) {
  float s = lut_texcoord(o.mapping, o.size, lut_u_from_cosine(LutIndex::cosine, hn));
  float r = lut_texcoord(o.mapping, o.size, lut_u_from_cosine(LutIndex::cosine, ln));
  glm::vec4 v = sample_linear(t, glm::vec3(s, r, 0.0f), lut_address_mode(o.mapping));
  return {v.x, v.w};
}

// ---- noise volume -----------------------------------------------------------------------

std::string validate(const NoiseTableOptions& o) {
  if (auto e = check_size("Width", o.width, 1); !e.empty()) return e;
  if (auto e = check_size("Height", o.height, 1); !e.empty()) return e;
  if (auto e = check_size("Depth", o.depth, 1); !e.empty()) return e;
  if (long(o.width) * o.height * o.depth > kMaxTexels) return "Width * Height * Depth is too large";
  if (o.channels < 1 || o.channels > 4) return "Channels must be 1, 2, 3 or 4";
  if (o.noise.period < 1 || o.noise.period > 1024) return "Period must be in [1, 1024]";
  if (o.noise.octaves < 1 || o.noise.octaves > 8) return "Octaves must be in [1, 8]";
  return {};
}

Table bake_noise_table(const NoiseTableOptions& o) {
  if (!validate(o).empty()) return {};
  Table t = Table::make(o.width, o.height, o.depth, o.channels, o.format);
  const double p = o.noise.period;
  for (int z = 0; z < o.depth; ++z)
    for (int y = 0; y < o.height; ++y)
      for (int x = 0; x < o.width; ++x) {
        // Texel centres spread one full period over the texture: wrap-addressing tiles.
        glm::dvec3 pos((x + 0.5) / o.width * p, (y + 0.5) / o.height * p, (z + 0.5) / o.depth * p);
        for (int c = 0; c < o.channels; ++c) {
          double n = lattice_noise(o.noise, pos, c);
          t.store(x, y, z, c, o.format == TableFormat::unorm8 ? 0.5 * n + 0.5 : n);
        }
      }
  return t;
}

// ---- hemisphere -------------------------------------------------------------------------

std::string validate(const HemisphereTableOptions& o) { return check_size("Width", o.width); }

Table bake_hemisphere_table(const HemisphereTableOptions& o) {
  if (!validate(o).empty()) return {};
  Table t = Table::make(o.width, 1, 1, 2, o.format);
  for (int i = 0; i < o.width; ++i) {
    double c = lut_cosine_of_u(LutIndex::cosine, lut_texel_u(LutMapping::texel_centre, o.width, i));
    t.store(i, 0, 0, 0, hemisphere_sky_fraction(c));
    t.store(i, 0, 0, 1, hemisphere_sky_fraction_seed(c));
  }
  return t;
}

}  // namespace fx::shading
