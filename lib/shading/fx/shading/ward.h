// The "anisotropic lighting LUT and Ward" seed: (1) NVIDIA's table indexed by (H.N, L.N),
// (2) the Gems-style per-vertex Gaussian c = exp(-e*e), e = k * 0.3 (T.H) / (N.H).
#pragma once
#include <cmath>

#include "fx/shading/guarded.h"

namespace fx::shading {

// Which specular lobe the (H.N, L.N) table stores.
enum class HalfAngleLobe {
  blinn_phong,  // (H.N)^n
  gaussian,     // exp(-(tan(theta_h) / m)^2): Ward's isotropic exponent
};

// The (L.N, H.N) table function: rgb = saturate(L.N), a = lobe(H.N). The NVIDIA texture's
// own formula is unpublished (the seed says so); this is the documented stand-in.
template <class T>
struct HalfAngleTerms {
  T diffuse = 0;
  T specular = 0;
};

// Table contents for cosines (L.N, H.N); `shape` is n for Blinn-Phong, m for Gaussian.
template <class T>
HalfAngleTerms<T> ln_hn_terms(T ln, T hn, HalfAngleLobe lobe, T shape) {
  ln = clamp_cosine(ln);
  hn = clamp_cosine(hn);
  HalfAngleTerms<T> out{saturate(ln), T(0)};
  if (hn <= T(0)) return out;  // half vector at or below the horizon: no highlight
  if (lobe == HalfAngleLobe::blinn_phong) {
    out.specular = guarded_pow(hn, shape);
  } else {
    T tan2 = (T(1) - hn) * (T(1) + hn) / (hn * hn);
    out.specular = std::exp(-tan2 / (shape * shape));
  }
  return out;
}

// The seed's Gaussian: u = (T.H) * 0.3, w = N.H, e = k u / w, c = exp(-e*e). Guarded:
// w <= 0 (half vector at or below the surface, where e is +-inf or 0/0) -> 0;
// non-finite input -> 0. The seed's 0.3 is a wavelength it folds into k.
template <class T>
T ward_gaussian(const Vec3<T>& n, const Vec3<T>& t, const Vec3<T>& h, T k) {
  if (!finite(n) || !finite(t) || !finite(h) || !finite(k)) return T(0);
  T u = glm::dot(t, h) * T(0.3);
  T w = glm::dot(n, h);
  if (!(w > T(0))) return T(0);
  T e = k * u / w;
  return std::exp(-e * e);
}

}  // namespace fx::shading
