#include "fx/shading/approximations.h"

#include <cmath>
#include <cstdio>

#include "fx/shading/bakers.h"
#include "fx/shading/brdf_factorization.h"
#include "fx/shading/hemisphere.h"
#include "fx/shading/lut.h"
#include "fx/shading/specular_power.h"
#include "fx/shading/strand.h"
#include "fx/shading/ward.h"

namespace fx::shading {

namespace {

constexpr double kPi = 3.14159265358979323846;

glm::vec3 to_float(const glm::dvec3& v) { return glm::vec3(v); }

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

const char* name_of(LutIndex i) { return i == LutIndex::cosine ? "dot" : "angle"; }
const char* name_of(TableFormat f) { return f == TableFormat::unorm8 ? "unorm8" : "float32"; }
const char* name_of(LutMapping m) {
  switch (m) {
    case LutMapping::naive: return "naive";
    case LutMapping::seed_wrap: return "seed_wrap";
    case LutMapping::texel_centre: return "texel_centre";
    case LutMapping::texel_centre_wrap: return "texel_centre_wrap";
  }
  return "?";
}

// Runs measure_error and files the result.
ApproximationError measured(std::string id, std::string family, std::string description,
                            std::vector<std::pair<std::string, std::string>> params, const ShadingTerm& reference,
                            const ShadingTerm& approximation, std::span<const ShadingSample> samples) {
  ErrorReport r = measure_error(reference, approximation, samples);
  return {std::move(id), std::move(family), std::move(description), std::move(params), r.all, r.near_degenerate};
}

float n_dot_h_float(const ShadingSample& s) {
  glm::vec3 h = to_float(s.l) + to_float(s.v);
  float len = glm::length(h);
  return len > 0.f ? glm::dot(to_float(s.n), h / len) : 0.f;
}

void strand_tables(const ApproximationOptions& o, std::span<const ShadingSample> samples,
                   std::vector<ApproximationError>& out) {
  for (double exponent : o.strand_exponents) {
    ShadingTerm reference = [exponent](const ShadingSample& s) {
      return strand_reference(s.l, s.v, s.t, exponent).specular;
    };
    for (LutIndex index : {LutIndex::cosine, LutIndex::angle}) {
      for (TableFormat format : {TableFormat::unorm8, TableFormat::float32}) {
        for (int size : o.lut_sizes) {
          StrandTableOptions t{size, exponent, LutMapping::texel_centre, index, format};
          Table table = bake_strand_table(t);
          if (table.width == 0) continue;
          ShadingTerm approx = [&](const ShadingSample& s) {
            glm::vec3 l = to_float(s.l), v = to_float(s.v), tt = to_float(s.t);
            return double(
                lookup_strand_table(table, t, lut_u_from_vectors(index, l, tt), lut_u_from_vectors(index, v, tt))
                    .specular);
          };
          out.push_back(measured(std::string("strand_lut/") + name_of(index) + "/" + name_of(format) + "/n" +
                                     number(exponent) + "/s" + std::to_string(size),
                                 "strand_lut",
                                 "strand table specular, " + std::string(name_of(index)) + " index, " +
                                     name_of(format) + ", " + std::to_string(size) + "^2, exponent " + number(exponent),
                                 {{"index", name_of(index)},
                                  {"format", name_of(format)},
                                  {"exponent", number(exponent)},
                                  {"size", std::to_string(size)},
                                  {"mapping", "texel_centre"}},
                                 reference, approx, samples));
        }
      }
    }
  }
  // Texel mappings at the seed's sizes: the corner error of naive and wrap addressing.
  for (int size : {64, 256}) {
    for (LutMapping m :
         {LutMapping::naive, LutMapping::seed_wrap, LutMapping::texel_centre, LutMapping::texel_centre_wrap}) {
      for (bool diffuse : {false, true}) {
        StrandTableOptions t{size, 32, m, LutIndex::cosine, TableFormat::unorm8};
        Table table = bake_strand_table(t);
        ShadingTerm reference = [diffuse](const ShadingSample& s) {
          StrandTerms<double> r = strand_reference(s.l, s.v, s.t, 32);
          return diffuse ? r.diffuse : r.specular;
        };
        ShadingTerm approx = [&](const ShadingSample& s) {
          glm::vec3 l = to_float(s.l), v = to_float(s.v), tt = to_float(s.t);
          StrandTerms<float> f = lookup_strand_table(table, t, lut_u_from_vectors(LutIndex::cosine, l, tt),
                                                     lut_u_from_vectors(LutIndex::cosine, v, tt));
          return double(diffuse ? f.diffuse : f.specular);
        };
        const char* term = diffuse ? "diffuse" : "specular";
        out.push_back(measured(
            std::string("strand_mapping/") + name_of(m) + "/" + term + "/s" + std::to_string(size), "strand_mapping",
            std::string("strand table ") + term + ", " + name_of(m) + " mapping, unorm8 " + std::to_string(size) +
                "^2, exponent 32",
            {{"mapping", name_of(m)}, {"term", term}, {"size", std::to_string(size)}, {"exponent", "32"}}, reference,
            approx, samples));
      }
    }
  }
}

void strand_arithmetic(std::span<const ShadingSample> samples, std::vector<ApproximationError>& out) {
  for (bool diffuse : {true, false}) {
    const char* term = diffuse ? "diffuse" : "specular";
    ShadingTerm reference = [diffuse](const ShadingSample& s) {
      StrandTerms<double> r = strand_reference(s.l, s.v, s.t, 32);
      return diffuse ? r.diffuse : r.specular;
    };
    ShadingTerm stable = [diffuse](const ShadingSample& s) {
      StrandTerms<float> f = strand_from_vectors(to_float(s.l), to_float(s.v), to_float(s.t), 32.f);
      return double(diffuse ? f.diffuse : f.specular);
    };
    ShadingTerm naive = [diffuse](const ShadingSample& s) {
      glm::vec3 t = to_float(s.t);
      StrandTerms<float> f = strand_naive(glm::dot(to_float(s.l), t), glm::dot(to_float(s.v), t), 32.f);
      return double(diffuse ? f.diffuse : f.specular);
    };
    out.push_back(measured(std::string("strand_analytic/stable/") + term, "strand_analytic",
                           std::string("analytic strand ") + term + ", float, |L x T| sines, exponent 32",
                           {{"form", "stable"}, {"term", term}, {"exponent", "32"}}, reference, stable, samples));
    out.push_back(measured(std::string("strand_analytic/seed_sqrt/") + term, "strand_analytic",
                           std::string("analytic strand ") + term + ", float, the seed's sqrt(1-(L.T)^2), exponent 32",
                           {{"form", "seed_sqrt"}, {"term", term}, {"exponent", "32"}}, reference, naive, samples));
  }
}

// The seed's ps.1.4 bump shader: T' = T - (N'.T)N' against the bump normal N', not
// renormalized ("almost no visual impact"), so the table is indexed by L.T' and V.T' of a
// shorter vector. Each uniform sample's normal is tilted by a fixed angle (in a direction
// that turns with the sample) to make N'; the reference is the analytic strand with the
// renormalized T'. The renormalized float path is the control.
void bump_gram_schmidt(const ApproximationOptions& o, std::span<const ShadingSample> samples,
                       std::vector<ApproximationError>& out) {
  for (double degrees : o.bump_tilts_degrees) {
    const double tilt = degrees * kPi / 180.0;
    std::vector<ShadingSample> bumped;
    for (const ShadingSample& s : samples) {
      if (s.kind != SampleKind::uniform) continue;
      const double phi = 2.399963 * double(bumped.size());  // golden angle: directions spread evenly
      const glm::dvec3 b = glm::cross(s.n, s.t);
      ShadingSample t = s;
      t.n = std::cos(tilt) * s.n + std::sin(tilt) * (std::cos(phi) * s.t + std::sin(phi) * b);
      bumped.push_back(t);
    }
    for (bool diffuse : {true, false}) {
      const char* term = diffuse ? "diffuse" : "specular";
      ShadingTerm reference = [diffuse](const ShadingSample& s) {
        StrandTerms<double> r = strand_reference(s.l, s.v, gram_schmidt_tangent(s.t, s.n), 32);
        return diffuse ? r.diffuse : r.specular;
      };
      ShadingTerm unnormalized = [diffuse](const ShadingSample& s) {
        glm::vec3 t = gram_schmidt_unnormalized(to_float(s.t), to_float(s.n));
        StrandTerms<float> f = strand_from_cosines(glm::dot(to_float(s.l), t), glm::dot(to_float(s.v), t), 32.f);
        return double(diffuse ? f.diffuse : f.specular);
      };
      ShadingTerm renormalized = [diffuse](const ShadingSample& s) {
        glm::vec3 t = gram_schmidt_tangent(to_float(s.t), to_float(s.n));
        StrandTerms<float> f = strand_from_vectors(to_float(s.l), to_float(s.v), t, 32.f);
        return double(diffuse ? f.diffuse : f.specular);
      };
      const std::string tilt_name = number(degrees);
      for (bool renorm : {false, true}) {
        const char* form = renorm ? "renormalized" : "unnormalized";
        out.push_back(measured(std::string("bump/") + form + "/" + term + "/tilt" + tilt_name, "bump_gram_schmidt",
                               std::string("strand ") + term + " on T' = T - (N'.T)N', " + form + ", bump normal " +
                                   tilt_name + " deg off the surface normal, float",
                               {{"form", form}, {"term", term}, {"tilt_degrees", tilt_name}}, reference,
                               renorm ? renormalized : unnormalized, bumped));
      }
    }
  }
}

void specular_powers(const ApproximationOptions& o, std::span<const ShadingSample> samples,
                     std::vector<ApproximationError>& out) {
  // The cosine is computed once in float and fed to both sides: this isolates the power's
  // approximation from the half vector's own ill-conditioning at L = -V.
  ShadingTerm reference = [](const ShadingSample& s) { return specular_power_reference(n_dot_h_float(s), 16); };
  out.push_back(measured(
      "specular/pow_native", "specular_power", "(N.H)^16, native pow in float", {{"method", "pow"}, {"exponent", "16"}},
      reference, [](const ShadingSample& s) { return double(specular_power(n_dot_h_float(s), 16.f)); }, samples));
  out.push_back(measured(
      "specular/squaring_float", "specular_power", "(N.H)^16 by four float squarings",
      {{"method", "squaring"}, {"register", "float"}, {"exponent", "16"}}, reference,
      [](const ShadingSample& s) { return double(pow16_by_squaring(n_dot_h_float(s), false)); }, samples));
  out.push_back(measured(
      "specular/squaring_8bit", "specular_power", "(N.H)^16 by four squarings in 8-bit registers (ps.1.1)",
      {{"method", "squaring"}, {"register", "unorm8"}, {"exponent", "16"}}, reference,
      [](const ShadingSample& s) { return double(pow16_by_squaring(n_dot_h_float(s), true)); }, samples));
  for (TableFormat format : {TableFormat::unorm8, TableFormat::float32}) {
    for (int size : o.lut_sizes) {
      PowTableOptions t{2, size, 16, LutMapping::texel_centre, format};
      Table table = bake_pow_table(t);
      if (table.width == 0) continue;
      out.push_back(measured(
          std::string("specular/table/") + name_of(format) + "/s" + std::to_string(size), "specular_power",
          "(N.H)^16 from the LightEval table, " + std::string(name_of(format)) + ", " + std::to_string(size) +
              " entries",
          {{"method", "table"}, {"format", name_of(format)}, {"size", std::to_string(size)}, {"exponent", "16"}},
          reference,
          [&](const ShadingSample& s) { return double(lookup_pow_table(table, t, saturate(n_dot_h_float(s)))); },
          samples));
    }
  }
}

// Strand specular (exponent 32) on a UV sphere: evaluated per vertex and interpolated
// across each triangle, against the analytic value at each interior point.
void per_vertex(const ApproximationOptions& o, std::vector<ApproximationError>& out) {
  const glm::dvec3 lights[] = {glm::normalize(glm::dvec3(1, 1, 1)), glm::normalize(glm::dvec3(-0.3, 0.8, 0.5))};
  const glm::dvec3 view = glm::normalize(glm::dvec3(0.2, -0.4, 1));
  constexpr int k = 4;  // barycentric subdivisions per edge
  for (int rings : o.sphere_rings) {
    int segments = 2 * rings;
    auto vertex = [&](int i, int j) {
      double th = kPi * i / rings, ph = 2 * kPi * j / segments;
      glm::dvec3 p(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      glm::dvec3 t(-std::sin(ph), std::cos(ph), 0);
      return std::pair{p, t};
    };
    std::vector<double> ref, approx;
    for (const glm::dvec3& l : lights) {
      for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < segments; ++j) {
          std::pair<glm::dvec3, glm::dvec3> quad[4] = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1),
                                                       vertex(i, j + 1)};
          for (int tri = 0; tri < 2; ++tri) {
            int idx[3] = {0, 1, 2};
            if (tri == 1) idx[1] = 2, idx[2] = 3;
            double vals[3];
            for (int c = 0; c < 3; ++c) {
              const auto& [p, t] = quad[idx[c]];
              vals[c] = strand_from_vectors(to_float(l), to_float(view), to_float(t), 32.f).specular;
            }
            for (int a = 0; a <= k; ++a) {
              for (int b = 0; a + b <= k; ++b) {
                double w0 = double(a) / k, w1 = double(b) / k, w2 = 1.0 - w0 - w1;
                glm::dvec3 n =
                    glm::normalize(w0 * quad[idx[0]].first + w1 * quad[idx[1]].first + w2 * quad[idx[2]].first);
                glm::dvec3 t = w0 * quad[idx[0]].second + w1 * quad[idx[1]].second + w2 * quad[idx[2]].second;
                t = gram_schmidt_tangent(t, n);
                ref.push_back(strand_reference(l, view, t, 32).specular);
                approx.push_back(w0 * vals[0] + w1 * vals[1] + w2 * vals[2]);
              }
            }
          }
        }
      }
    }
    double edge_deg = 180.0 / rings;
    out.push_back({"per_vertex/rings" + std::to_string(rings),
                   "per_vertex",
                   "strand specular n=32 per vertex, interpolated, sphere " + std::to_string(rings) + "x" +
                       std::to_string(segments) + " (edge " + number(edge_deg) + " deg)",
                   {{"rings", std::to_string(rings)}, {"edge_deg", number(edge_deg)}},
                   compare_values(ref, approx),
                   {}});
  }
}

void hemisphere(const ApproximationOptions& o, std::vector<ApproximationError>& out) {
  std::vector<double> uniform_q, near_q;
  for (int i = 0; i <= 180; ++i) uniform_q.push_back(kPi * i / 180);
  for (double d = 1e-1; d > 0.5e-8; d /= std::sqrt(10.0)) {
    for (double centre : {0.0, kPi / 2, kPi}) {
      if (centre > 0) near_q.push_back(centre - d);
      if (centre < kPi) near_q.push_back(centre + d);
    }
  }
  auto forms = [&](const std::vector<double>& qs, int form) {
    std::vector<double> ref, approx;
    for (double q : qs) {
      ref.push_back(hemisphere_sky_fraction_quadrature(q, o.hemisphere_quadrature_steps));
      double c = std::cos(q);
      if (form == 0) approx.push_back(hemisphere_sky_fraction(float(c)));
      else if (form == 1) approx.push_back(hemisphere_sky_fraction_seed(float(c)));
      else approx.push_back(0.5 + 0.5 * c);
    }
    return compare_values(ref, approx);
  };
  const char* names[] = {"cosine_float", "seed_float", "cosine_double"};
  const char* what[] = {"0.5 + 0.5 cos q in float", "the seed's 'actual integral' 1 - 0.5 sin q in float",
                        "0.5 + 0.5 cos q in double (quadrature's own error)"};
  for (int form = 0; form < 3; ++form) {
    out.push_back({std::string("hemisphere/") + names[form],
                   "hemisphere",
                   std::string("sky fraction, ") + what[form] + " vs quadrature (" +
                       std::to_string(o.hemisphere_quadrature_steps) + " steps)",
                   {{"form", names[form]}},
                   forms(uniform_q, form),
                   forms(near_q, form)});
    ErrorStats all = out.back().all;  // fold near-degenerate into `all` as measure_error does
    const ErrorStats& nd = out.back().near_degenerate;
    double sq = all.rmse * all.rmse * all.count + nd.rmse * nd.rmse * nd.count;
    all.count += nd.count;
    all.rmse = std::sqrt(sq / all.count);
    if (nd.max_abs > all.max_abs) all.max_abs = nd.max_abs, all.max_lsb8 = nd.max_lsb8, all.worst = nd.worst;
    out.back().all = all;
  }
}

void half_angle(const ApproximationOptions& o, std::span<const ShadingSample> samples,
                std::vector<ApproximationError>& out) {
  for (HalfAngleLobe lobe : {HalfAngleLobe::blinn_phong, HalfAngleLobe::gaussian}) {
    double shape = lobe == HalfAngleLobe::blinn_phong ? 32 : 0.3;
    const char* lobe_name = lobe == HalfAngleLobe::blinn_phong ? "blinn_phong" : "gaussian";
    ShadingTerm reference = [=](const ShadingSample& s) {
      return ln_hn_terms(double(glm::dot(to_float(s.n), to_float(s.l))), double(n_dot_h_float(s)), lobe, shape)
          .specular;
    };
    for (int size : o.lut_sizes) {
      HalfAngleTableOptions t{size, lobe, shape, LutMapping::texel_centre, TableFormat::unorm8};
      Table table = bake_ln_hn_table(t);
      if (table.width == 0) continue;
      out.push_back(measured(
          std::string("ln_hn/") + lobe_name + "/s" + std::to_string(size), "ln_hn",
          std::string("(L.N, H.N) table, ") + lobe_name + " lobe, unorm8 " + std::to_string(size) + "^2",
          {{"lobe", lobe_name}, {"size", std::to_string(size)}, {"format", "unorm8"}}, reference,
          [&](const ShadingSample& s) {
            return double(
                lookup_ln_hn_table(table, t, glm::dot(to_float(s.n), to_float(s.l)), n_dot_h_float(s)).specular);
          },
          samples));
    }
  }
  // The seed's Gaussian exp(-e*e) in float against the same formula in double.
  ShadingTerm gauss_ref = [](const ShadingSample& s) {
    glm::vec3 h = to_float(s.l) + to_float(s.v);  // same half vector as the float side
    float len = glm::length(h);
    return ward_gaussian(s.n, s.t, len > 0 ? glm::dvec3(h / len) : glm::dvec3(0), 4.0);
  };
  ShadingTerm gauss_float = [](const ShadingSample& s) {
    glm::vec3 h = to_float(s.l) + to_float(s.v);
    float len = glm::length(h);
    return double(ward_gaussian(to_float(s.n), to_float(s.t), len > 0 ? h / len : glm::vec3(0), 4.f));
  };
  out.push_back(measured("gaussian/float", "gaussian", "the seed's exp(-e*e), e = k 0.3 (T.H)/(N.H), k = 4, float",
                         {{"k", "4"}}, gauss_ref, gauss_float, samples));
}

void brdf(const ApproximationOptions& o, std::vector<ApproximationError>& out) {
  for (BrdfLobe lobe : {BrdfLobe::blinn_phong, BrdfLobe::phong}) {
    AnalyticBrdf analytic;
    analytic.lobe = lobe;
    analytic.exponent = 8;
    const char* lobe_name = lobe == BrdfLobe::phong ? "phong" : "blinn_phong";
    for (int size : o.brdf_sizes) {
      BrdfFactorizationOptions fo;
      fo.size = size;
      BrdfFactors f = factorize_brdf(analytic, fo);
      FactorizationError e = measure_factorization(f, analytic, 4096, 7);
      ErrorStats s;
      s.count = 4096;
      s.max_abs = e.max_abs;
      s.rmse = e.rmse;
      s.max_lsb8 = e.max_abs * 255;
      out.push_back({std::string("brdf/") + lobe_name + "/s" + std::to_string(size),
                     "brdf",
                     std::string("homomorphic factorization of ") + lobe_name + " n=8, 3 x " + std::to_string(size) +
                         "^2 float (relative RMSE " + number(e.relative_rmse) + ")",
                     {{"lobe", lobe_name}, {"size", std::to_string(size)}, {"relative_rmse", number(e.relative_rmse)}},
                     s,
                     {}});
    }
  }
}

}  // namespace

std::vector<ApproximationError> measure_approximations(const ApproximationOptions& options) {
  std::vector<ShadingSample> samples = shading_samples(options.samples);
  std::vector<ApproximationError> out;
  strand_arithmetic(samples, out);
  strand_tables(options, samples, out);
  bump_gram_schmidt(options, samples, out);
  specular_powers(options, samples, out);
  per_vertex(options, out);
  hemisphere(options, out);
  half_angle(options, samples, out);
  brdf(options, out);
  return out;
}

std::string param(const ApproximationError& e, const std::string& name) {
  for (const auto& [k, v] : e.params)
    if (k == name) return v;
  return {};
}

}  // namespace fx::shading
