// Per-pixel lighting seed (Taylor, "Per-Pixel Lighting"): diffuse N.L and the specular
// power computed three ways: multiply-based x^16 (optionally with the 8-bit register
// rounding the seed blames for banding), a lookup table (LightEval), and native pow.
#pragma once
#include <cmath>

#include "fx/shading/guarded.h"

namespace fx::shading {

// dp3_sat: saturate(N.L).
template <class T>
T lambert(const Vec3<T>& n, const Vec3<T>& l) {
  return saturate(glm::dot(n, l));
}

// ps.1.1 "pow2 by multiplies": four squarings of saturate(x) give x^16. With
// `register_8bit`, the input and every product are rounded to 8-bit unorm as the ps.1.1
// registers do; that rounding is where the highlight banding comes from.
template <class T>
T pow16_by_squaring(T x, bool register_8bit) {
  T r = saturate(x);
  if (register_8bit) r = quantize_unorm8(r);
  for (int i = 0; i < 4; ++i) {
    r = r * r;
    if (register_8bit) r = quantize_unorm8(r);
  }
  return r;
}

// Native pow(saturate(x), n) with pow(0,0) = 1 (see guarded_pow).
template <class T>
T specular_power(T x, T n) {
  return guarded_pow(saturate(x), n);
}

// Double reference for specular_power.
inline double specular_power_reference(double x, double n) { return guarded_pow(saturate(x), n); }

}  // namespace fx::shading
