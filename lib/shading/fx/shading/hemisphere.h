// Hemisphere ("2-hemisphere", sky + ground) lighting from the per-pixel lighting seed,
// with the occlusion term and an optional directional (sun) light.
//
// Model note: a = 0.5 + 0.5 cos q, the seed's "simplification", IS the exact
// cosine-weighted fraction of the sky hemisphere seen by a surface tilted q from the sky
// axis. The seed's "actual integral" a = 1 - 0.5 sin q (q < 90), 0.5 sin q (q > 90) is a
// different model; the two differ by up to 0.207 at q = 45 and 135 degrees.
#pragma once
#include <cmath>

#include "fx/shading/guarded.h"

namespace fx::shading {

// Sky fraction a = 0.5 + 0.5 cos q from cos q = N.A (the seed's dp3 + mad). NaN -> 0.5.
template <class T>
T hemisphere_sky_fraction(T cos_q) {
  return T(0.5) + T(0.5) * clamp_cosine(cos_q);
}

// The seed's "actual integral" from cos q: 1 - 0.5 sin q facing the sky, 0.5 sin q away.
template <class T>
T hemisphere_sky_fraction_seed(T cos_q) {
  T c = clamp_cosine(cos_q);
  T s = std::sqrt((T(1) - c) * (T(1) + c));
  return c >= T(0) ? T(1) - T(0.5) * s : T(0.5) * s;
}

// Cosine-weighted sky fraction by midpoint quadrature over the hemisphere around N, in
// double: (1/pi) * sum over directions w (w.N > 0) of [w.A > 0] (w.N) dw, with `steps`
// polar and 2*`steps` azimuthal cells. Independent of the closed form it checks.
double hemisphere_sky_fraction_quadrature(double q_radians, int steps);

// Inputs of the three-term hemisphere model plus one directional light.
template <class T>
struct HemisphereLight {
  Vec3<T> sky_axis{0, 0, 1};
  Vec3<T> sky_color{1, 1, 1};
  Vec3<T> ground_color{0, 0, 0};
  Vec3<T> material{1, 1, 1};       // c43 in the seed's vertex shader
  Vec3<T> sun_direction{0, 0, 1};  // to the sun, unit
  Vec3<T> sun_color{0, 0, 0};      // zero disables the directional light
};

// color = material * ((a sky + (1 - a) ground) (1 - occlusion) + sun saturate(N.S)).
// The occlusion term darkens only the hemisphere light (it is a sky-visibility ratio);
// the sun's own shadowing belongs to a shadow map. Non-finite normal -> a = 0.5.
template <class T>
Vec3<T> hemisphere_lighting(const HemisphereLight<T>& h, const Vec3<T>& n, T occlusion) {
  T a = hemisphere_sky_fraction(finite(n) ? glm::dot(n, h.sky_axis) : T(0));
  Vec3<T> ambient = (h.sky_color - h.ground_color) * a + h.ground_color;  // the seed's lerp
  Vec3<T> lit = ambient * (T(1) - saturate(occlusion));
  T ns = finite(n) ? saturate(glm::dot(n, h.sun_direction)) : T(0);
  return h.material * (lit + h.sun_color * ns);
}

}  // namespace fx::shading
