// Homomorphic BRDF factorization (McCool, Ang, Ahmad, SIGGRAPH 2001), as used by the
// D3DX effects seed's "BRDF Shader": f(wi, wo) cos(theta_i) ~= p_i(wi) q(wh) p_o(wo),
// three textures multiplied in the pixel shader. The factors are found by linear least
// squares on log f over sampled direction pairs, each factor a parabolic-map table.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "fx/shading/table.h"

namespace fx::shading {

enum class BrdfLobe {
  phong,        // (R.V)^n: does not factor exactly (the test case for the method)
  blinn_phong,  // (N.H)^n: factors exactly into q(wh), up to table interpolation
  ward,         // anisotropic Ward: factors exactly, p = 1/sqrt(cos), q = the Gaussian
};

// An analytic BRDF in the tangent frame (N = z, tangent = x), times cos(theta_i).
struct AnalyticBrdf {
  BrdfLobe lobe = BrdfLobe::phong;
  double exponent = 16;                   // Phong, Blinn-Phong
  double alpha_x = 0.15, alpha_y = 0.35;  // Ward roughness along x and y
  double diffuse = 0;                     // Lambert albedo (a sum never factors exactly)
  double specular = 1;                    // lobe weight
  // f(wi, wo) * cos(theta_i) for unit wi, wo; 0 when either is below the horizon.
  double evaluate(const glm::dvec3& wi, const glm::dvec3& wo) const;
};

// Parabolic-map texture coordinate of a unit upper-hemisphere direction, in [0, 1]^2.
glm::dvec2 parabolic_coords(const glm::dvec3& w);

// A parabolic factor table resampled as a size x size cube map (Table::cube): each texel
// holds the parabolic map's linearly filtered value at parabolic_coords of its direction,
// so a cube lookup with any (unnormalised) direction reads what the parabolic lookup of the
// normalised direction does, up to the second filtering. What the DirectX 8 listings
// (texture stages sampling at the raw direction) need.
Table parabolic_to_cube(const Table& parabolic, int size);

struct BrdfFactorizationOptions {
  int size = 32;               // each factor is size x size
  int samples = 16384;         // direction pairs (uniform in parabolic coordinates)
  int iterations = 300;        // CGLS iterations
  double smoothness = 0.05;    // weight of the Laplacian regularizer (fills unseen texels)
  double log_floor = 1e-4;     // f below floor * max(f) is clamped before the log
  double floor_weight = 0.05;  // least row weight (rows are weighted by sqrt(f / max f))
  uint32_t seed = 1;
};

// The three factor tables (float32, 1 channel, parabolic map, clamp addressing).
struct BrdfFactors {
  Table in, half, out;          // p_i(wi), q(wh), p_o(wo)
  double log_residual_rms = 0;  // RMS of the weighted log-space residual over the samples
};

// Fits the factors. Invalid options (size < 2 or > 256, samples < 16, iterations < 1)
// return empty tables.
BrdfFactors factorize_brdf(const AnalyticBrdf& brdf, const BrdfFactorizationOptions& options);

// p_i(wi) q(wh) p_o(wo), fetched as the shader does (linear filtering, float).
double evaluate_factored(const BrdfFactors& f, const glm::dvec3& wi, const glm::dvec3& wo);

// Reconstruction error against the analytic BRDF over independent random pairs.
struct FactorizationError {
  double max_abs = 0;        // max |approx - exact|
  double rmse = 0;           // root mean square of approx - exact
  double relative_rmse = 0;  // rmse / RMS(exact)
};
FactorizationError measure_factorization(const BrdfFactors& f, const AnalyticBrdf& brdf, int samples, uint32_t seed);

}  // namespace fx::shading
