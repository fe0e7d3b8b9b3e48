// How a 2D lookup table over cosines is laid out and addressed: which domain value each
// texel stores, and which texture coordinate the shader computes for a domain value.
//
// The domain coordinate u in [0, 1] is 0.5 x + 0.5 for a cosine x (dot indexing), or
// 1 - angle / pi (angle indexing, u = 1 at angle 0 as for the cosine).
#pragma once
#include <cmath>

#include "fx/shading/guarded.h"
#include "fx/shading/table.h"

namespace fx::shading {

// Mapping from domain coordinate u to texture coordinate s (N texels along the axis).
enum class LutMapping {
  naive,              // s = u; texel i stores u = (i + 0.5) / N (D3DXFillTexture); clamp
  seed_wrap,          // the strand seed's "bias for free": naive table rotated by N/2,
                      // s = u - 0.5 (the shader's 0.5 scale only), wrap addressing
  texel_centre,       // s = (u (N - 1) + 0.5) / N; texel i stores u = i / (N - 1); clamp
  texel_centre_wrap,  // texel_centre rotated by N/2, s = (u - 0.5)(N - 1)/N, wrap: the
                      // half-texel fix folds into the vertex shader's scale, still free
};

// How the shader turns its vectors into u.
enum class LutIndex { cosine, angle };

// The address mode a mapping needs.
inline AddressMode lut_address_mode(LutMapping m) {
  return (m == LutMapping::seed_wrap || m == LutMapping::texel_centre_wrap) ? AddressMode::wrap : AddressMode::clamp;
}

// True when the mapping supports n texels (wrap mappings rotate by n/2: n must be even).
inline bool lut_size_valid(LutMapping m, int n) {
  if (n < 2) return false;
  return lut_address_mode(m) == AddressMode::clamp || n % 2 == 0;
}

// The domain coordinate u stored in texel i of n.
inline double lut_texel_u(LutMapping m, int n, int i) {
  switch (m) {
    case LutMapping::naive: return (i + 0.5) / n;
    case LutMapping::seed_wrap: return ((i + n / 2) % n + 0.5) / n;
    case LutMapping::texel_centre: return double(i) / (n - 1);
    case LutMapping::texel_centre_wrap: return double((i + n / 2) % n) / (n - 1);
  }
  return 0;
}

// The texture coordinate the shader computes for domain coordinate u (float, as on GPU).
inline float lut_texcoord(LutMapping m, int n, float u) {
  switch (m) {
    case LutMapping::naive: return u;
    case LutMapping::seed_wrap: return u - 0.5f;
    case LutMapping::texel_centre: return (u * float(n - 1) + 0.5f) / float(n);
    case LutMapping::texel_centre_wrap: return (u - 0.5f) * (float(n - 1) / float(n));
  }
  return 0;
}

// The cosine a domain coordinate stands for (double: used when baking).
inline double lut_cosine_of_u(LutIndex index, double u) {
  return index == LutIndex::cosine ? 2.0 * u - 1.0 : std::cos(3.14159265358979323846 * (1.0 - u));
}

// u from a cosine (float, shader side). Angle indexing via acos loses precision near
// |x| = 1 (~sqrt(eps) rad); prefer lut_u_from_vectors when the vectors are at hand.
inline float lut_u_from_cosine(LutIndex index, float x) {
  x = clamp_cosine(x);
  return index == LutIndex::cosine ? 0.5f * x + 0.5f : 1.0f - std::acos(x) / 3.14159265f;
}

// u from the two unit vectors: the angle comes from atan2(|a x b|, a.b), accurate at all
// angles. Non-finite input -> u of a perpendicular pair (0.5).
inline float lut_u_from_vectors(LutIndex index, const glm::vec3& a, const glm::vec3& b) {
  if (!finite(a) || !finite(b)) return 0.5f;
  float c = glm::dot(a, b);
  if (index == LutIndex::cosine) return 0.5f * clamp_cosine(c) + 0.5f;
  float s = glm::length(glm::cross(a, b));
  return 1.0f - std::atan2(s, c) / 3.14159265f;
}

}  // namespace fx::shading
