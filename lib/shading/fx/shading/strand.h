// Strand (Heidrich/Banks) anisotropic lighting, as in the ATI "Per-Pixel Strand Based
// Anisotropic Lighting" seed: diffuse L.N' = sqrt(1-(L.T)^2), specular
// (V.R')^n = (sqrt(1-(L.T)^2) sqrt(1-(V.T)^2) - (L.T)(V.T))^n.
// Every function is a template: instantiate with float to mirror the shader, with double
// to get the same formula without float rounding (arithmetic error); the *_reference
// functions are the analytic model in double (model error).
#pragma once
#include <cmath>

#include "fx/shading/guarded.h"

namespace fx::shading {

// The two strand terms for one light.
template <class T>
struct StrandTerms {
  T diffuse = 0;   // L.N'
  T specular = 0;  // (V.R')^n, clamped at 0 before the power
};

// The seed's formula verbatim, from the two cosines: goes NaN when rounding pushes |L.T|
// past 1 and loses all precision near |L.T| = 1 (kept to demonstrate exactly that).
template <class T>
StrandTerms<T> strand_naive(T lt, T vt, T exponent) {
  T sl = std::sqrt(T(1) - lt * lt);
  T sv = std::sqrt(T(1) - vt * vt);
  return {sl, std::pow(sl * sv - lt * vt, exponent)};
}

// The table function: the seed's formula from the cosines with the undefined cases
// defined. Cosines are clamped to [-1, 1] (NaN -> 0, i.e. perpendicular),
// 1-x^2 is evaluated as (1-x)(1+x) (exact factors for |x| >= 0.5), and the power is
// guarded_pow. Used by the table bakers, where the cosine is exact.
template <class T>
StrandTerms<T> strand_from_cosines(T lt, T vt, T exponent) {
  lt = clamp_cosine(lt);
  vt = clamp_cosine(vt);
  T sl = std::sqrt((T(1) - lt) * (T(1) + lt));
  T sv = std::sqrt((T(1) - vt) * (T(1) + vt));
  T r = sl * sv - lt * vt;
  return {sl, guarded_pow(r > T(0) ? r : T(0), exponent)};
}

// The stable per-pixel form from unit vectors: the sines come from |L x T| and |V x T|,
// which keep full relative precision at small angles where 1-(L.T)^2 cancels to 0 or
// below. Non-finite input -> {0, 0} (a NaN pixel renders unlit rather than flashing).
template <class T>
StrandTerms<T> strand_from_vectors(const Vec3<T>& l, const Vec3<T>& v, const Vec3<T>& t, T exponent) {
  if (!finite(l) || !finite(v) || !finite(t) || !finite(exponent)) return {};
  T sl = glm::length(glm::cross(l, t));
  T sv = glm::length(glm::cross(v, t));
  T lt = clamp_cosine(glm::dot(l, t));
  T vt = clamp_cosine(glm::dot(v, t));
  sl = sl < T(1) ? sl : T(1);
  sv = sv < T(1) ? sv : T(1);
  T r = sl * sv - lt * vt;
  return {sl, guarded_pow(r > T(0) ? r : T(0), exponent)};
}

// Analytic reference: normalizes the inputs in double and evaluates through the angles,
// V.R' = -cos(a + b) with a = angle(L,T), b = angle(V,T) from atan2(|x|, .).
// Degenerate (zero or non-finite) input vectors -> {0, 0}, as in strand_from_vectors.
StrandTerms<double> strand_reference(const glm::dvec3& l, const glm::dvec3& v, const glm::dvec3& t, double exponent);

// Gram-Schmidt tangent against a bump-map normal, as the seed's ps.1.4 shader does it:
// T - (N.T)N, without renormalization (the seed notes the missing normalize "has almost
// no visual impact"; the shorter T' brightens the lighting near steep bumps).
template <class T>
Vec3<T> gram_schmidt_unnormalized(const Vec3<T>& t, const Vec3<T>& n) {
  return t - glm::dot(n, t) * n;
}

// normalize(T - (N.T)N) with a documented fallback: when T is parallel to N (or either is
// non-finite) the projection is rounding noise, so the result is any_perpendicular(N)
// (or (1,0,0) when N itself is unusable). Always returns a finite unit vector.
// The projection is applied twice ("twice is enough", Kahan/Parlett): one pass leaves a
// component along N of ~eps / sin(angle(T, N)), the second brings it back to ~eps.
template <class T>
Vec3<T> gram_schmidt_tangent(const Vec3<T>& t, const Vec3<T>& n) {
  if (!finite(n)) return Vec3<T>(1, 0, 0);
  Vec3<T> nn = normalize_or(n, Vec3<T>(0, 0, 1));
  Vec3<T> fallback = any_perpendicular(nn);
  if (!finite(t)) return fallback;
  Vec3<T> p = t - glm::dot(nn, t) * nn;
  if (!(glm::length(p) > degenerate_length<T>())) return fallback;
  p = p - glm::dot(nn, p) * nn;
  return normalize_or(p, fallback);
}

}  // namespace fx::shading
