#include "fx/shading/error_measure.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "fx/shading/noise.h"

namespace fx::shading {

namespace {

struct UniformStream {
  uint32_t seed, n = 0;
  double next() { return double(hash32(seed ^ hash32(n++))) / 4294967296.0; }
};

glm::dvec3 random_unit(UniformStream& rng) {
  double z = 2.0 * rng.next() - 1.0, phi = 2.0 * 3.14159265358979323846 * rng.next();
  double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
}

// A unit vector perpendicular to unit a.
glm::dvec3 perpendicular(const glm::dvec3& a, UniformStream& rng) {
  for (;;) {
    glm::dvec3 c = glm::cross(a, random_unit(rng));
    double len = glm::length(c);
    if (len > 1e-3) return c / len;
  }
}

// Unit vector at exactly `angle` from unit a (rotated toward a random perpendicular).
glm::dvec3 at_angle(const glm::dvec3& a, double angle, UniformStream& rng) {
  return std::cos(angle) * a + std::sin(angle) * perpendicular(a, rng);
}

// Builds the configuration for degeneracy d at distance `angle` (0 = exact).
ShadingSample degenerate_sample(Degeneracy d, double angle, UniformStream& rng) {
  ShadingSample s;
  s.degeneracy = d;
  s.angle = angle;
  s.n = random_unit(rng);
  s.t = perpendicular(s.n, rng);
  s.v = random_unit(rng);
  s.l = random_unit(rng);
  switch (d) {
    case Degeneracy::l_equals_t: s.l = at_angle(s.t, angle, rng); break;
    case Degeneracy::l_equals_minus_t: s.l = at_angle(-s.t, angle, rng); break;
    case Degeneracy::l_equals_minus_v: s.l = at_angle(-s.v, angle, rng); break;
    case Degeneracy::t_parallel_n: s.t = at_angle(s.n, angle, rng); break;
    case Degeneracy::v_equals_t: s.v = at_angle(s.t, angle, rng); break;
    case Degeneracy::ridge: {
      // V.T = -L.T: the strand highlight's maximum; V is L mirrored through T's normal plane.
      s.v = s.l - 2.0 * glm::dot(s.l, s.t) * s.t;
      s.v = at_angle(s.v, angle, rng);
      break;
    }
    case Degeneracy::none: break;
  }
  return s;
}

void accumulate(ErrorStats& st, double& sum_sq, const ShadingSample& s, double ref, double approx) {
  ++st.count;
  if (!std::isfinite(approx)) {
    ++st.non_finite;
    return;
  }
  double d = std::abs(approx - ref);
  sum_sq += d * d;
  if (d > st.max_abs || st.count == 1) {
    st.max_abs = std::max(st.max_abs, d);
    st.worst = s;
  }
}

void finish(ErrorStats& st, double sum_sq) {
  size_t finite = st.count - st.non_finite;
  st.rmse = finite ? std::sqrt(sum_sq / double(finite)) : 0.0;
  st.max_lsb8 = st.max_abs * 255.0;
}

}  // namespace

std::vector<ShadingSample> shading_samples(const SampleSetOptions& o) {
  std::vector<ShadingSample> out;
  UniformStream rng{o.seed};
  for (int i = 0; i < o.uniform; ++i) {
    ShadingSample s;
    s.n = random_unit(rng);
    s.t = perpendicular(s.n, rng);
    s.l = random_unit(rng);
    s.v = random_unit(rng);
    out.push_back(s);
  }
  const Degeneracy kinds[] = {Degeneracy::l_equals_t,   Degeneracy::l_equals_minus_t, Degeneracy::l_equals_minus_v,
                              Degeneracy::t_parallel_n, Degeneracy::v_equals_t,       Degeneracy::ridge};
  if (o.min_angle > 0.0 && o.max_angle >= o.min_angle && o.angles_per_decade > 0) {
    int steps = int(std::ceil(std::log10(o.max_angle / o.min_angle) * o.angles_per_decade));
    for (int k = 0; k <= steps; ++k) {
      double angle = o.max_angle * std::pow(10.0, -double(k) / o.angles_per_decade);
      if (angle < o.min_angle * 0.999) break;
      for (Degeneracy d : kinds)
        for (int f = 0; f < o.frames_per_angle; ++f) {
          ShadingSample s = degenerate_sample(d, angle, rng);
          s.kind = SampleKind::near_degenerate;
          out.push_back(s);
        }
    }
  }
  for (Degeneracy d : kinds)
    for (int f = 0; f < o.frames_per_angle; ++f) {
      ShadingSample s = degenerate_sample(d, 0.0, rng);
      s.kind = SampleKind::exact_degenerate;
      out.push_back(s);
    }
  if (o.include_non_finite) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const double bad[] = {nan, inf, -inf};
    for (double b : bad)
      for (int which = 0; which < 4; ++which) {
        ShadingSample s = degenerate_sample(Degeneracy::none, 0.0, rng);
        s.kind = SampleKind::non_finite;
        glm::dvec3* vecs[] = {&s.l, &s.v, &s.t, &s.n};
        vecs[which]->y = b;
        out.push_back(s);
      }
  }
  return out;
}

ErrorReport measure_error(const ShadingTerm& reference, const ShadingTerm& approximation,
                          std::span<const ShadingSample> samples) {
  ErrorReport r;
  double sq_all = 0, sq_u = 0, sq_n = 0, sq_e = 0, sq_f = 0;
  for (const ShadingSample& s : samples) {
    double ref = reference(s);
    if (!std::isfinite(ref)) continue;
    double approx = approximation(s);
    accumulate(r.all, sq_all, s, ref, approx);
    switch (s.kind) {
      case SampleKind::uniform: accumulate(r.uniform, sq_u, s, ref, approx); break;
      case SampleKind::near_degenerate: accumulate(r.near_degenerate, sq_n, s, ref, approx); break;
      case SampleKind::exact_degenerate: accumulate(r.exact_degenerate, sq_e, s, ref, approx); break;
      case SampleKind::non_finite: accumulate(r.non_finite_inputs, sq_f, s, ref, approx); break;
    }
  }
  finish(r.all, sq_all);
  finish(r.uniform, sq_u);
  finish(r.near_degenerate, sq_n);
  finish(r.exact_degenerate, sq_e);
  finish(r.non_finite_inputs, sq_f);
  return r;
}

ErrorStats compare_values(std::span<const double> reference, std::span<const double> approximation) {
  ErrorStats st;
  double sq = 0;
  size_t n = std::min(reference.size(), approximation.size());
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(reference[i])) continue;
    ShadingSample s;
    s.angle = double(i);  // the index, for locating the worst entry
    accumulate(st, sq, s, reference[i], approximation[i]);
  }
  finish(st, sq);
  return st;
}

std::string describe(const ErrorStats& s) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "max %.3g (%.3g LSB8), rmse %.3g, n=%zu, non-finite %zu", s.max_abs, s.max_lsb8,
                s.rmse, s.count, s.non_finite);
  return buf;
}

}  // namespace fx::shading
