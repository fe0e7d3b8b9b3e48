#include "fx/shading/hemisphere.h"

namespace fx::shading {

double hemisphere_sky_fraction_quadrature(double q, int steps) {
  if (steps < 1 || !std::isfinite(q)) return 0.0;
  const double pi = 3.14159265358979323846;
  // Frame: N = z; the sky axis A is tilted by q in the x-z plane.
  const glm::dvec3 axis(std::sin(q), 0.0, std::cos(q));
  const int n_theta = steps, n_phi = 2 * steps;
  const double d_theta = 0.5 * pi / n_theta, d_phi = 2.0 * pi / n_phi;
  double sum = 0.0;
  for (int i = 0; i < n_theta; ++i) {
    double theta = (i + 0.5) * d_theta;
    double st = std::sin(theta), ct = std::cos(theta);
    double ring = 0.0;
    for (int j = 0; j < n_phi; ++j) {
      double phi = (j + 0.5) * d_phi;
      glm::dvec3 w(st * std::cos(phi), st * std::sin(phi), ct);
      if (glm::dot(w, axis) > 0.0) ring += 1.0;
    }
    sum += ring * ct * st;  // (w.N) times the solid-angle Jacobian sin(theta)
  }
  return sum * d_theta * d_phi / pi;
}

}  // namespace fx::shading
