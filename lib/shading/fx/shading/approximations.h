// The catalogue of approximations the seed effects make (table sizes, indexing, formats,
// texel mappings, pow by multiplies / table / native, per-vertex vs per-pixel, hemisphere
// forms, (L.N, H.N) table, Gaussian, BRDF factorization) and their measured error
// against the double-precision reference. `fxkit bench accuracy` adds GPU cost.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "fx/shading/error_measure.h"

namespace fx::shading {

// One measured approximation.
struct ApproximationError {
  std::string id;           // stable, e.g. "strand_lut/dot/unorm8/texel_centre/n32/s256"
  std::string family;       // strand_lut, strand_mapping, strand_arith, specular_power,
                            // per_vertex, hemisphere, ln_hn, gaussian, brdf
  std::string description;  // one line for the report
  std::vector<std::pair<std::string, std::string>> params;  // size, exponent, index, ...
  ErrorStats all;                                           // every sample
  ErrorStats near_degenerate;                               // log-spaced 1e-1 .. 1e-8 rad samples (count 0 if none)
};

struct ApproximationOptions {
  SampleSetOptions samples;  // the shading configurations (uniform + near-degenerate)
  std::vector<int> lut_sizes = {16, 32, 64, 128, 256, 512, 1024};
  std::vector<double> strand_exponents = {8, 32, 128};
  std::vector<int> sphere_rings = {6, 12, 24, 48, 96};  // per-vertex: latitude rings
  std::vector<int> brdf_sizes = {8, 16, 32};
  std::vector<double> bump_tilts_degrees = {5, 15, 30, 45};  // bump normal vs surface normal
  int hemisphere_quadrature_steps = 400;
};

// Measures every approximation of the catalogue. Deterministic for given options.
std::vector<ApproximationError> measure_approximations(const ApproximationOptions& options);

// The value of a named parameter of a result ("" when absent).
std::string param(const ApproximationError& e, const std::string& name);

}  // namespace fx::shading
