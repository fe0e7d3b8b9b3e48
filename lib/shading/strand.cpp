#include "fx/shading/strand.h"

namespace fx::shading {

StrandTerms<double> strand_reference(const glm::dvec3& l, const glm::dvec3& v, const glm::dvec3& t, double exponent) {
  const glm::dvec3 zero(0.0);
  glm::dvec3 ln = normalize_or(l, zero), vn = normalize_or(v, zero), tn = normalize_or(t, zero);
  if (ln == zero || vn == zero || tn == zero || !finite(exponent)) return {};
  double a = std::atan2(glm::length(glm::cross(ln, tn)), glm::dot(ln, tn));
  double b = std::atan2(glm::length(glm::cross(vn, tn)), glm::dot(vn, tn));
  double r = -std::cos(a + b);
  return {std::sin(a), guarded_pow(r > 0.0 ? r : 0.0, exponent)};
}

}  // namespace fx::shading
