// Error measurement for shading approximations: a reusable sample set of shading
// configurations (uniform plus log-spaced near-degenerate and exact degenerate cases)
// and the statistics the numerics reports use (max-abs, RMSE, 8-bit LSB).
#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fx::shading {

enum class SampleKind { uniform, near_degenerate, exact_degenerate, non_finite };

// Which configuration a non-uniform sample approaches.
enum class Degeneracy { none, l_equals_t, l_equals_minus_t, l_equals_minus_v, t_parallel_n, v_equals_t, ridge };

// One shading configuration: unit vectors (except non_finite samples) in a random frame.
struct ShadingSample {
  glm::dvec3 l{0, 0, 1}, v{0, 0, 1}, t{1, 0, 0}, n{0, 0, 1};
  SampleKind kind = SampleKind::uniform;
  Degeneracy degeneracy = Degeneracy::none;
  double angle = 0;  // distance from the degeneracy in radians (near_degenerate only)
};

struct SampleSetOptions {
  int uniform = 4096;                         // uniform random configurations (all directions)
  double min_angle = 1e-8, max_angle = 1e-1;  // log-spaced near-degenerate range
  int angles_per_decade = 2;
  int frames_per_angle = 4;         // random orientations per (degeneracy, angle)
  bool include_non_finite = false;  // NaN / Inf components (reference must define them)
  uint32_t seed = 1;
};

// The sample set: deterministic for a given options struct.
std::vector<ShadingSample> shading_samples(const SampleSetOptions& options = {});

// A scalar shading term evaluated for a sample (the reference in double, or an
// approximation that converts to float internally).
using ShadingTerm = std::function<double(const ShadingSample&)>;

struct ErrorStats {
  size_t count = 0;       // samples compared
  size_t non_finite = 0;  // approximation returned NaN/Inf (counted, excluded from max/RMSE)
  double max_abs = 0;
  double rmse = 0;
  double max_lsb8 = 0;  // max_abs in units of 1/255
  ShadingSample worst;  // where max_abs occurred
};

// Statistics overall and per sample kind.
struct ErrorReport {
  ErrorStats all, uniform, near_degenerate, exact_degenerate, non_finite_inputs;
};

// Compares approximation against reference on every sample. Samples where the reference
// itself is non-finite are skipped (the reference defines the answer or nothing does).
ErrorReport measure_error(const ShadingTerm& reference, const ShadingTerm& approximation,
                          std::span<const ShadingSample> samples);

// Max-abs/RMSE/LSB over paired value arrays (for tables and 1D sweeps).
ErrorStats compare_values(std::span<const double> reference, std::span<const double> approximation);

// One-line summary: "max 1.2e-07 (0.03 LSB8), rmse 3.1e-08, n=4096, non-finite 0".
std::string describe(const ErrorStats& s);

}  // namespace fx::shading
