#include "fx/shading/brdf_factorization.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fx/shading/noise.h"

namespace fx::shading {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Deterministic uniform [0, 1) stream (hash of a counter): no global RNG state.
struct UniformStream {
  uint32_t seed, n = 0;
  double next() { return double(hash32(seed ^ hash32(n++))) / 4294967296.0; }
};

// A direction uniform in parabolic coordinates (the tables' own texel density).
glm::dvec3 random_direction(UniformStream& rng) {
  for (;;) {
    double x = 2.0 * rng.next() - 1.0, y = 2.0 * rng.next() - 1.0;
    double r2 = x * x + y * y;
    if (r2 >= 1.0) continue;
    // Inverse of (x, y) = (wx, wy) / (1 + wz).
    double d = 1.0 + r2;
    return glm::dvec3(2.0 * x / d, 2.0 * y / d, (1.0 - r2) / d);
  }
}

// Bilinear taps (texel index, weight) for coordinate s in [0, 1] on n texels, clamped:
// the same convention as sample_linear, in double.
std::array<std::pair<int, double>, 2> taps(double s, int n) {
  double x = std::clamp(s * n - 0.5, 0.0, double(n - 1));
  int i0 = int(std::floor(x));
  int i1 = std::min(i0 + 1, n - 1);
  double w = x - i0;
  return {{{i0, 1.0 - w}, {i1, w}}};
}

// One sparse least-squares row: up to 12 (column, weight) entries and a right-hand side.
struct Row {
  std::array<int, 12> col{};
  std::array<double, 12> w{};
  int count = 0;
  double rhs = 0;
  void add(int c, double v) {
    col[count] = c;
    w[count] = v;
    ++count;
  }
};

void add_factor_taps(Row& row, int offset, int n, const glm::dvec3& dir) {
  glm::dvec2 st = parabolic_coords(dir);
  for (auto [ix, wx] : taps(st.x, n))
    for (auto [iy, wy] : taps(st.y, n)) row.add(offset + iy * n + ix, wx * wy);
}

void multiply(const std::vector<Row>& rows, const std::vector<double>& x, std::vector<double>& out) {
  out.assign(rows.size(), 0.0);
  for (size_t r = 0; r < rows.size(); ++r) {
    double s = 0.0;
    for (int k = 0; k < rows[r].count; ++k) s += rows[r].w[k] * x[rows[r].col[k]];
    out[r] = s;
  }
}

void multiply_transposed(const std::vector<Row>& rows, const std::vector<double>& y, std::vector<double>& out) {
  std::fill(out.begin(), out.end(), 0.0);
  for (size_t r = 0; r < rows.size(); ++r)
    for (int k = 0; k < rows[r].count; ++k) out[rows[r].col[k]] += rows[r].w[k] * y[r];
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

Table factor_table(const std::vector<double>& x, int offset, int n) {
  Table t = Table::make(n, n, 1, 1, TableFormat::float32);
  for (int y = 0; y < n; ++y)
    for (int i = 0; i < n; ++i) t.store(i, y, 0, 0, std::exp(x[offset + y * n + i]));
  return t;
}

}  // namespace

double AnalyticBrdf::evaluate(const glm::dvec3& wi, const glm::dvec3& wo) const {
  if (!(wi.z > 0.0) || !(wo.z > 0.0)) return 0.0;
  double lobe_value = 0.0;
  switch (lobe) {
    case BrdfLobe::phong: {
      glm::dvec3 r(-wi.x, -wi.y, wi.z);  // mirror of wi about N
      double c = std::max(0.0, glm::dot(r, wo));
      lobe_value = (exponent + 2.0) / (2.0 * kPi) * std::pow(c, exponent);
      break;
    }
    case BrdfLobe::blinn_phong: {
      glm::dvec3 h = glm::normalize(wi + wo);
      lobe_value = (exponent + 8.0) / (8.0 * kPi) * std::pow(std::max(0.0, h.z), exponent);
      break;
    }
    case BrdfLobe::ward: {
      glm::dvec3 h = wi + wo;  // only ratios of its components matter
      double e = (h.x * h.x / (alpha_x * alpha_x) + h.y * h.y / (alpha_y * alpha_y)) / (h.z * h.z);
      lobe_value = std::exp(-e) / (4.0 * kPi * alpha_x * alpha_y * std::sqrt(wi.z * wo.z));
      break;
    }
  }
  return (diffuse / kPi + specular * lobe_value) * wi.z;
}

glm::dvec2 parabolic_coords(const glm::dvec3& w) {
  double d = 1.0 + std::max(w.z, 0.0);
  return glm::dvec2(0.5 + 0.5 * w.x / d, 0.5 + 0.5 * w.y / d);
}

Table parabolic_to_cube(const Table& parabolic, int size) {
  Table cube = Table::make(size, size, 6, parabolic.channels, parabolic.format);
  cube.cube = true;
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const glm::dvec3 w = glm::normalize(cube_direction(face, (x + 0.5) / size, (y + 0.5) / size));
        const glm::dvec2 st = parabolic_coords(w);
        const glm::vec4 v = sample_linear(parabolic, glm::vec3(float(st.x), float(st.y), 0.0f), AddressMode::clamp);
        for (int c = 0; c < cube.channels; ++c) cube.store(x, y, face, c, v[c]);
      }
  return cube;
}

BrdfFactors factorize_brdf(const AnalyticBrdf& brdf, const BrdfFactorizationOptions& o) {
  BrdfFactors out;
  if (o.size < 2 || o.size > 256 || o.samples < 16 || o.samples > (1 << 22) || o.iterations < 1 ||
      !(o.log_floor > 0.0) || !(o.smoothness >= 0.0))
    return out;
  const int n = o.size, texels = n * n;
  const int off_in = 0, off_half = texels, off_out = 2 * texels;
  UniformStream rng{o.seed};

  std::vector<glm::dvec3> wis, wos;
  std::vector<double> values;
  double peak = 0.0;
  for (int k = 0; k < o.samples; ++k) {
    glm::dvec3 wi = random_direction(rng), wo = random_direction(rng);
    double v = brdf.evaluate(wi, wo);
    wis.push_back(wi);
    wos.push_back(wo);
    values.push_back(v);
    if (std::isfinite(v)) peak = std::max(peak, v);
  }
  if (!(peak > 0.0)) return out;
  const double floor = o.log_floor * peak;

  std::vector<Row> rows;
  rows.reserve(values.size() + 6 * texels);
  for (size_t k = 0; k < values.size(); ++k) {
    Row r;
    add_factor_taps(r, off_in, n, wis[k]);
    add_factor_taps(r, off_half, n, glm::normalize(wis[k] + wos[k]));
    add_factor_taps(r, off_out, n, wos[k]);
    double v = std::isfinite(values[k]) ? values[k] : peak;
    r.rhs = std::log(std::max(v, floor));
    // Relative (log) error matters most where the BRDF is large: weight rows by
    // sqrt(f / peak), kept above `floor_weight` so the dark region still constrains texels.
    double weight = std::max(std::sqrt(std::max(v, 0.0) / peak), o.floor_weight);
    for (int i = 0; i < r.count; ++i) r.w[i] *= weight;
    r.rhs *= weight;
    rows.push_back(r);
  }
  // Smoothness rows: lambda (x_a - x_b) = 0 for neighbouring texels of each factor,
  // scaled with the samples-per-texel ratio so the balance does not depend on counts.
  const double lambda = o.smoothness * std::sqrt(double(o.samples) / texels);
  for (int f = 0; f < 3; ++f)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        int a = f * texels + y * n + x;
        if (x + 1 < n) {
          Row r;
          r.add(a, lambda);
          r.add(a + 1, -lambda);
          rows.push_back(r);
        }
        if (y + 1 < n) {
          Row r;
          r.add(a, lambda);
          r.add(a + n, -lambda);
          rows.push_back(r);
        }
      }

  // CGLS on min |A x - b|^2, from x = 0 (converges toward the minimum-norm solution,
  // which also fixes the factors' gauge freedom: constants moved between factors).
  const size_t m = size_t(3) * texels;
  std::vector<double> x(m, 0.0), r(rows.size()), s(m), p, q(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) r[i] = rows[i].rhs;
  multiply_transposed(rows, r, s);
  p = s;
  double gamma = dot(s, s);
  // Stop once |A^T r| has fallen 12 orders of magnitude: past that, rounding breaks the
  // search directions' conjugacy and a near-zero q.q sends alpha to Inf (NaN factors).
  const double converged = gamma * 1e-24;
  for (int it = 0; it < o.iterations && gamma > converged; ++it) {
    multiply(rows, p, q);
    double qq = dot(q, q);
    double alpha = gamma / qq;
    if (!(qq > 0.0) || !std::isfinite(alpha)) break;
    for (size_t i = 0; i < m; ++i) x[i] += alpha * p[i];
    for (size_t i = 0; i < r.size(); ++i) r[i] -= alpha * q[i];
    multiply_transposed(rows, r, s);
    double gamma_next = dot(s, s);
    double beta = gamma_next / gamma;
    gamma = gamma_next;
    for (size_t i = 0; i < m; ++i) p[i] = s[i] + beta * p[i];
  }

  double sq = 0.0;
  for (size_t k = 0; k < values.size(); ++k) sq += r[k] * r[k];
  out.log_residual_rms = std::sqrt(sq / values.size());
  out.in = factor_table(x, off_in, n);
  out.half = factor_table(x, off_half, n);
  out.out = factor_table(x, off_out, n);
  return out;
}

double evaluate_factored(const BrdfFactors& f, const glm::dvec3& wi, const glm::dvec3& wo) {
  if (f.in.value_count() == 0 || !(wi.z > 0.0) || !(wo.z > 0.0)) return 0.0;
  auto fetch = [](const Table& t, const glm::dvec3& w) {
    glm::dvec2 st = parabolic_coords(w);
    return double(sample_linear(t, glm::vec3(float(st.x), float(st.y), 0.0f), AddressMode::clamp).x);
  };
  return fetch(f.in, wi) * fetch(f.half, glm::normalize(wi + wo)) * fetch(f.out, wo);
}

FactorizationError measure_factorization(const BrdfFactors& f, const AnalyticBrdf& brdf, int samples, uint32_t seed) {
  FactorizationError e;
  if (samples < 1) return e;
  UniformStream rng{seed ^ 0xa5a5a5a5U};
  double sq = 0.0, ref_sq = 0.0;
  for (int k = 0; k < samples; ++k) {
    glm::dvec3 wi = random_direction(rng), wo = random_direction(rng);
    double exact = brdf.evaluate(wi, wo), approx = evaluate_factored(f, wi, wo);
    double d = approx - exact;
    e.max_abs = std::max(e.max_abs, std::abs(d));
    sq += d * d;
    ref_sq += exact * exact;
  }
  e.rmse = std::sqrt(sq / samples);
  e.relative_rmse = ref_sq > 0.0 ? e.rmse / std::sqrt(ref_sq / samples) : 0.0;
  return e;
}

}  // namespace fx::shading
