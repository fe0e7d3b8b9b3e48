// The Renderman Companion wood shader as the D3DX effects seed writes it (fx.2.0 HLSL):
// noise-perturbed radial distance -> ring position -> light/dark wood blend + specular.
#pragma once
#include <cmath>

#include "fx/shading/guarded.h"
#include "fx/shading/highlight.h"

namespace fx::shading {

// HLSL frc: x - floor(x), in [0, 1) for finite x. Non-finite -> 0.
template <class T>
T frc(T x) {
  if (!finite(x)) return T(0);
  T f = x - std::floor(x);
  return f < T(1) ? f : T(0);  // x = -tiny rounds x - floor(x) up to exactly 1
}

// HLSL lerp(a, b, s) = a + s (b - a).
template <class T, class S>
T lerp(const T& a, const T& b, S s) {
  return a + s * (b - a);
}

// The seed's smoothstep, verbatim: a cubic Hermite curve from value a (s = 0) to value b
// (s = 1) with unit end tangents; constant a / b outside [0, 1]. Not RenderMan's
// smoothstep(edge0, edge1, x), which this seed's call sites assume.
template <class T>
T seed_smoothstep(T a, T b, T s) {
  T s2 = s * s;
  T s3 = s * s2;
  T v1 = T(2) * s3 - T(3) * s2 + T(1);
  T t1 = s3 - T(2) * s2 + s;
  T v2 = T(-2) * s3 + T(3) * s2;
  T t2 = s3 - s2;
  return s < T(0) ? a : s > T(1) ? b : v1 * a + t1 + v2 * b + t2;
}

// RenderMan smoothstep(e0, e1, x): 0 below e0, 1 above e1, 3t^2 - 2t^3 between.
template <class T>
T renderman_smoothstep(T e0, T e1, T x) {
  T t = saturate((x - e0) / (e1 - e0));
  return t * t * (T(3) - T(2) * t);
}

// Ring profile of the seed: r = frc(r); smoothstep(0, .8, r) - smoothstep(.83, 1, r),
// with the seed's smoothstep.
template <class T>
T wood_ring_seed(T r) {
  r = frc(r);
  return seed_smoothstep(T(0), T(0.8), r) - seed_smoothstep(T(0.83), T(1), r);
}

// The same ring profile with RenderMan's smoothstep (the Companion's intent): rises over
// [0, .8], falls over [.83, 1].
template <class T>
T wood_ring_renderman(T r) {
  r = frc(r);
  return renderman_smoothstep(T(0), T(0.8), r) - renderman_smoothstep(T(0.83), T(1), r);
}

// The seed's effect parameters.
template <class T>
struct WoodParams {
  T ringscale = 10, point_scale = 1, turbulence = 1;
  Vec3<T> lightwood{0.3, 0.12, 0.03}, darkwood{0.05, 0.01, 0.005};
  T ka = 0.2, kd = 0.4, ks = 0.6, roughness = 0.1;
  Vec3<T> ambient_color{1, 1, 1}, diffuse_color{1, 1, 1}, specular_color{1, 1, 1};
  Vec3<T> l{0, 0, 1};   // to the light
  Vec3<T> i{0, 0, -1};  // incident (view) direction; the seed passes -I as the eye vector
};

// The seed's Wood() pixel shader. `noise3(p)` stands for sample3d(noise, p) (a Vec3<T>)
// and `noise1(x)` for sample1d(noise, x) (a T); `alpha` is v.Color.a. The specular half
// vector and pow are guarded (half_vector, guarded_pow); the rest is verbatim.
template <class T, class Noise3, class Noise1>
Vec3<T> wood_shade(const WoodParams<T>& w, const Vec3<T>& position, const Vec3<T>& normal, T alpha, Noise3&& noise3,
                   Noise1&& noise1) {
  Vec3<T> pp = position * w.point_scale;
  pp += noise3(pp) * w.turbulence;
  T r = std::sqrt(pp.y * pp.y + pp.z * pp.z);
  r *= w.ringscale;
  r += std::abs(noise1(r) * w.turbulence);
  r = frc(r);
  r = seed_smoothstep(T(0), T(0.8), r) - seed_smoothstep(T(0.83), T(1), r);
  Vec3<T> diffuse = w.diffuse_color * glm::dot(normal, w.l);
  Vec3<T> h = half_vector(w.l, -w.i);
  Vec3<T> specular = w.specular_color * guarded_pow(glm::dot(h, normal), T(1) / w.roughness);
  return (w.ambient_color * w.ka + diffuse * w.kd) * lerp(w.lightwood, w.darkwood, r) * alpha +
         specular * (w.ks * (T(0.3) * r + T(0.7)));
}

}  // namespace fx::shading
