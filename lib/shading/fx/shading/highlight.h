// The GLSL "Anisotropic Specular Highlights" seed: eye and light (or the half vector) are
// projected onto the plane spanned by the strand direction T and the normal N, then lit
// with plain Phong (R.E) or Blinn-Phong (N.H). The isotropic switch skips the projection.
#pragma once
#include "fx/shading/guarded.h"

namespace fx::shading {

enum class HighlightModel { phong, blinn_phong };

// Inputs in tangent space, all expected unit length (E and L as the seed normalizes them).
template <class T>
struct HighlightInputs {
  Vec3<T> n{0, 0, 1};  // (bumped) normal
  Vec3<T> t{1, 0, 0};  // strand direction, nominally in the tangent plane
  Vec3<T> e{0, 0, 1};  // to the eye
  Vec3<T> l{0, 0, 1};  // to the light
  T exponent = 32;     // the seed uses gloss.g^2 * 128
};

// normalize(L + V), or the zero vector when L = -V (the half vector is undefined there;
// every dot product with the zero vector is 0, so Blinn-Phong gives no highlight, the same
// answer a hemisphere test gives for a light exactly behind the surface).
template <class T>
Vec3<T> half_vector(const Vec3<T>& l, const Vec3<T>& v) {
  return normalize_or(l + v, Vec3<T>(0));
}

// Removes the component along the unit plane normal b and renormalizes; the zero vector
// when x is (numerically) parallel to b, i.e. has no component in the plane.
template <class T>
Vec3<T> project_to_plane(const Vec3<T>& x, const Vec3<T>& b) {
  return normalize_or(x - glm::dot(x, b) * b, Vec3<T>(0));
}

// The seed's specular term, written in the shader's operation order. The strand plane's
// normal is cross(N, T), normalized here (the seed skips it because T lies in the
// unbumped tangent plane; with a bump map it does not). T parallel to N has no strand
// plane: shade isotropically. Non-finite input -> 0.
template <class T>
T anisotropic_highlight(const HighlightInputs<T>& in, HighlightModel model, bool anisotropic) {
  if (!finite(in.n) || !finite(in.t) || !finite(in.e) || !finite(in.l) || !finite(in.exponent)) return T(0);
  Vec3<T> e = in.e, l = in.l;
  Vec3<T> tplane = normalize_or(glm::cross(in.n, in.t), Vec3<T>(0));
  bool project = anisotropic && glm::dot(tplane, tplane) > T(0);
  if (model == HighlightModel::phong) {
    if (project) {
      e = project_to_plane(e, tplane);
      l = project_to_plane(l, tplane);
    }
    Vec3<T> r = T(2) * glm::dot(in.n, l) * in.n - l;  // reflect(-L, N)
    return guarded_pow(saturate(glm::dot(r, e)), in.exponent);
  }
  Vec3<T> h = half_vector(l, e);
  if (project) h = project_to_plane(h, tplane);
  // saturate, not max(0, .): a dot of unit floats can exceed 1 by an ulp, and x^n
  // amplifies that past 1 (pow(saturate(x), n) is also what the shader writes).
  return guarded_pow(saturate(glm::dot(in.n, h)), in.exponent);
}

}  // namespace fx::shading
