// Per-vertex normals and tangent frames from triangles.
//
// Tangents follow the per-pixel lighting seed ("Tangents need to be averaged - and be
// careful about texture wrapping"): each triangle's dP/du and dP/dv (the 2x2 solve of its
// edges against its uv deltas, which unlike the seed's |DeltaU2*Vec1 - DeltaU1*Vec2| form
// keeps its sign whatever the winding) is averaged per vertex, weighted by triangle area;
// vertices duplicated along a uv seam (same position and normal, tangents within ~25
// degrees) share their sums, so the wrap does not bend the frame; then Gram-Schmidt
// against the normal. Degenerate cases (zero-area triangles, equal uvs, tangent parallel
// to the normal, zero normals) are skipped or replaced, never divided by.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "detail.h"

namespace fx {
namespace {

// Below this squared length a vector has no direction (near FLT_MIN: scale-free for any
// real geometry, yet 1/sqrt stays finite).
constexpr float kTinySquared = 1e-30f;
// A Gram-Schmidt residue shorter than this fraction (squared) of the input is rounding
// noise of a vector parallel to the normal (float cancellation leaves ~1e-7 relative).
constexpr float kResidueSquared = 1e-10f;

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Unit vector or `fallback` when `v` has no usable direction.
glm::vec3 normalize_or(const glm::vec3& v, const glm::vec3& fallback) {
  float len2 = glm::dot(v, v);
  if (!(len2 > kTinySquared) || !std::isfinite(len2)) return fallback;
  return v / std::sqrt(len2);
}

// Some unit vector perpendicular to unit `n`: crosses n with the axis it is least aligned
// with, so the cross product is never shorter than sqrt(2/3).
glm::vec3 any_perpendicular(const glm::vec3& n) {
  glm::vec3 a = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
                    ? glm::vec3(1, 0, 0)
                    : (std::abs(n.y) <= std::abs(n.z) ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
  return glm::normalize(glm::cross(n, a));
}

// Gram-Schmidt: the unit part of `v` orthogonal to unit `n`, or zero when v is absent or
// (to rounding) parallel to n.
glm::vec3 orthogonal_unit(const glm::vec3& v, const glm::vec3& n) {
  glm::vec3 r = v - n * glm::dot(n, v);
  float len2 = glm::dot(r, r);
  if (!(len2 > kTinySquared) || !(len2 > kResidueSquared * glm::dot(v, v)) || !std::isfinite(len2))
    return glm::vec3(0.0f);
  return r / std::sqrt(len2);
}

struct SeamKey {
  uint32_t bits[6];
  friend bool operator==(const SeamKey&, const SeamKey&) = default;
};
// Vertices sorted by key, so equal keys form runs (sorting beat a node-based hash map of
// vectors by ~3x on a 130k-vertex sphere).
std::vector<std::pair<SeamKey, uint32_t>> sorted_by_key(std::vector<std::pair<SeamKey, uint32_t>> keyed) {
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
    return std::memcmp(a.first.bits, b.first.bits, sizeof a.first.bits) < 0;
  });
  return keyed;
}

SeamKey seam_key(const Vertex& v) {
  SeamKey k{};
  // Positions compare exactly (seam duplicates are copies); normals are rounded to ~1e-4
  // so analytic normals computed twice still meet. +0.0f folds -0.0f.
  float p[3] = {v.position.x + 0.0f, v.position.y + 0.0f, v.position.z + 0.0f};
  std::memcpy(k.bits, p, sizeof p);
  for (int i = 0; i < 3; ++i) k.bits[3 + i] = uint32_t(int32_t(std::lround(v.normal[i] * 8192.0f)));
  return k;
}

}  // namespace

namespace mesh_detail {

bool usable_normal(const glm::vec3& n) {
  float len2 = glm::dot(n, n);
  return std::isfinite(len2) && len2 > kTinySquared;
}

void smooth_normals(Mesh& mesh, bool only_unusable) {
  // Pool vertices by exact position: copies along a uv seam are one surface point.
  std::vector<std::pair<SeamKey, uint32_t>> keyed(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    Vertex probe;
    probe.position = mesh.vertices[i].position;
    probe.normal = glm::vec3(0.0f);
    keyed[i] = {seam_key(probe), uint32_t(i)};
  }
  keyed = sorted_by_key(std::move(keyed));
  std::vector<uint32_t> slot(mesh.vertices.size());
  uint32_t slots = 0;
  for (size_t k = 0; k < keyed.size(); ++k) {
    if (k > 0 && !(keyed[k].first == keyed[k - 1].first)) ++slots;
    slot[keyed[k].second] = slots;
  }
  std::vector<glm::vec3> sum(keyed.empty() ? 0 : slots + 1, glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t idx[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    if (idx[0] >= slot.size() || idx[1] >= slot.size() || idx[2] >= slot.size()) continue;
    glm::vec3 p[3] = {mesh.vertices[idx[0]].position, mesh.vertices[idx[1]].position, mesh.vertices[idx[2]].position};
    glm::vec3 face = normalize_or(glm::cross(p[1] - p[0], p[2] - p[0]), glm::vec3(0.0f));
    if (glm::dot(face, face) == 0.0f) continue;
    // Weight by the corner angle (Thurmer and Wuthrich): unlike area weighting, the result
    // does not depend on how a polygon was split into triangles.
    for (int k = 0; k < 3; ++k) {
      glm::vec3 e1 = normalize_or(p[(k + 1) % 3] - p[k], glm::vec3(0.0f));
      glm::vec3 e2 = normalize_or(p[(k + 2) % 3] - p[k], glm::vec3(0.0f));
      float angle = std::acos(std::clamp(glm::dot(e1, e2), -1.0f, 1.0f));
      sum[slot[idx[k]]] += face * angle;
    }
  }
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    Vertex& v = mesh.vertices[i];
    if (only_unusable && usable_normal(v.normal)) {
      v.normal = glm::normalize(v.normal);
      continue;
    }
    v.normal = normalize_or(sum[slot[i]], glm::vec3(0.0f, 0.0f, 1.0f));
  }
}

}  // namespace mesh_detail

void compute_normals(Mesh& mesh) { mesh_detail::smooth_normals(mesh, false); }

void compute_tangents(Mesh& mesh) {
  const size_t n = mesh.vertices.size();
  std::vector<glm::vec3> t_sum(n, glm::vec3(0.0f)), b_sum(n, glm::vec3(0.0f));

  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t idx[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    if (idx[0] >= n || idx[1] >= n || idx[2] >= n) continue;
    const Vertex &v0 = mesh.vertices[idx[0]], &v1 = mesh.vertices[idx[1]], &v2 = mesh.vertices[idx[2]];
    glm::vec3 e1 = v1.position - v0.position, e2 = v2.position - v0.position;
    glm::vec2 d1 = v1.uv - v0.uv, d2 = v2.uv - v0.uv;
    float area2 = glm::length(glm::cross(e1, e2));
    float det = d1.x * d2.y - d2.x * d1.y;
    // Relative test: a uv triangle whose area is ~1e-7 of its edge lengths' product is a
    // rounding artefact of equal uvs, not a parametrisation.
    float uv_scale = glm::length(d1) * glm::length(d2);
    if (!(area2 > 0.0f) || !std::isfinite(area2) || !(std::abs(det) > 1e-7f * uv_scale) || !std::isfinite(det))
      continue;
    // Solve [e1 e2] = [dPdu dPdv] [d1 d2]: dP/du and dP/dv of the triangle's plane.
    glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
    glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
    // Direction per triangle, weight by area: a sliver with a tiny uv footprint must not
    // dominate its neighbours through a huge 1/det.
    glm::vec3 tu = normalize_or(dpdu, glm::vec3(0.0f)) * area2;
    glm::vec3 tv = normalize_or(dpdv, glm::vec3(0.0f)) * area2;
    if (!finite(tu) || !finite(tv)) continue;
    for (uint32_t i : idx) {
      t_sum[i] += tu;
      b_sum[i] += tv;
    }
  }

  // Share sums across uv seams: copies of one surface point with the same normal whose
  // tangents agree. Mirrored uv islands (opposite tangents) and hard edges (different
  // normals) stay apart.
  std::vector<std::pair<SeamKey, uint32_t>> keyed;
  keyed.reserve(n);
  for (uint32_t i = 0; i < n; ++i)
    if (glm::dot(t_sum[i], t_sum[i]) > kTinySquared) keyed.push_back({seam_key(mesh.vertices[i]), i});
  keyed = sorted_by_key(std::move(keyed));
  std::vector<glm::vec3> t_merged = t_sum, b_merged = b_sum;
  constexpr float kSameDirection = 0.9f;  // cos 25.8 degrees
  for (size_t run = 0; run < keyed.size();) {
    size_t end = run + 1;
    while (end < keyed.size() && keyed[end].first == keyed[run].first) ++end;
    for (size_t a = run; a < end; ++a) {
      uint32_t i = keyed[a].second;
      glm::vec3 ti = glm::normalize(t_sum[i]);
      for (size_t b = run; b < end; ++b) {
        uint32_t j = keyed[b].second;
        if (j == i) continue;
        if (glm::dot(ti, glm::normalize(t_sum[j])) > kSameDirection && glm::dot(b_sum[i], b_sum[j]) >= 0.0f) {
          t_merged[i] += t_sum[j];
          b_merged[i] += b_sum[j];
        }
      }
    }
    run = end;
  }

  for (size_t i = 0; i < n; ++i) {
    Vertex& v = mesh.vertices[i];
    glm::vec3 nrm = normalize_or(v.normal, glm::vec3(0.0f, 0.0f, 1.0f));
    v.normal = nrm;
    glm::vec3 b_avg = b_merged[i];
    glm::vec3 tangent = orthogonal_unit(t_merged[i], nrm);
    if (glm::dot(tangent, tangent) == 0.0f) {
      // dP/du parallel to the normal or absent: derive from dP/dv if that is usable.
      glm::vec3 b = orthogonal_unit(b_avg, nrm);
      tangent = normalize_or(glm::cross(b, nrm), any_perpendicular(nrm));
    }
    glm::vec3 cross_nt = glm::cross(nrm, tangent);
    // Handedness: does dP/dv point along N x T? With no usable dP/dv, default +1.
    float w = glm::dot(cross_nt, b_avg) < 0.0f ? -1.0f : 1.0f;
    v.tangent = glm::vec4(tangent, w);
    v.binormal = cross_nt * w;
  }
}

}  // namespace fx
