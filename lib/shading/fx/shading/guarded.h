// Guarded scalar and vector operations shared by every shading model: the places where
// GLSL/SPIR-V leave results undefined (normalize(0), pow(0,0), pow(x<0,y), clamp(NaN))
// get one documented answer here, so the double references and the float mirrors agree.
#pragma once
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace fx::shading {

template <class T>
using Vec3 = glm::vec<3, T, glm::defaultp>;

// A vector shorter than this (relative to unit inputs) is rounding noise: its direction
// carries no information, so guarded operations fall back instead of normalizing it.
template <class T>
constexpr T degenerate_length() {
  return T(4) * std::numeric_limits<T>::epsilon();
}

// True when x is neither NaN nor infinite.
template <class T>
bool finite(T x) {
  return std::isfinite(x);
}
// True when all components are finite.
template <class T>
bool finite(const Vec3<T>& v) {
  return finite(v.x) && finite(v.y) && finite(v.z);
}

// clamp(x, 0, 1) with NaN -> 0 (GLSL leaves clamp(NaN) undefined; 0 means "unlit").
template <class T>
T saturate(T x) {
  return x > T(0) ? (x < T(1) ? x : T(1)) : T(0);
}

// clamp(x, -1, 1) with NaN -> 0: a cosine that went NaN is treated as perpendicular.
template <class T>
T clamp_cosine(T x) {
  if (!(x == x)) return T(0);
  return x > T(-1) ? (x < T(1) ? x : T(1)) : T(-1);
}

// pow(x, y) defined everywhere: x is clamped to [0, inf) (pow(x<0, y) is undefined in
// SPIR-V; a negative cosine means "facing away"), pow(0, 0) = 1 (the C and IEEE-754
// pown convention, and the limit along x = y -> 0), NaN in either argument -> 0.
template <class T>
T guarded_pow(T x, T y) {
  if (!(x == x) || !(y == y)) return T(0);
  if (x <= T(0)) return y == T(0) ? T(1) : (y > T(0) ? T(0) : std::numeric_limits<T>::infinity());
  return std::pow(x, y);
}

// normalize(v), or `fallback` when v is non-finite or shorter than degenerate_length().
template <class T>
Vec3<T> normalize_or(const Vec3<T>& v, const Vec3<T>& fallback) {
  if (!finite(v)) return fallback;
  T len = std::sqrt(glm::dot(v, v));
  if (!(len > degenerate_length<T>()) || !finite(len)) return fallback;
  return v / len;
}

// A unit vector perpendicular to unit n, continuous except across n.z = 0 (Duff et al.,
// "Building an Orthonormal Basis, Revisited", JCGT 2017). Used as the documented fallback
// when a tangent collapses onto the normal.
template <class T>
Vec3<T> any_perpendicular(const Vec3<T>& n) {
  T sign = std::copysign(T(1), n.z);
  T a = T(-1) / (sign + n.z);
  T b = n.x * n.y * a;
  return Vec3<T>(T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

// Rounds x in [0,1] to the nearest 8-bit unorm level and back (the ps.1.x register
// precision the per-pixel lighting seed blames for banding). NaN -> 0.
template <class T>
T quantize_unorm8(T x) {
  return std::round(saturate(x) * T(255)) / T(255);
}

}  // namespace fx::shading
