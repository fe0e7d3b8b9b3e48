// Invariants every fxkit mesh must satisfy, measured (not asserted) so tests can state
// their own tolerances and print what they saw.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "fx/mesh.h"

namespace fx::test {

struct FrameReport {
  size_t non_finite = 0;          // vertices with any NaN/Inf component
  size_t bad_handedness = 0;      // tangent.w not exactly +-1
  size_t bad_indices = 0;         // indices >= vertex count
  size_t inverted_triangles = 0;  // winding normal against the corners' vertex normals
  size_t triangles = 0;
  float normal_length_error = 0;  // max | |n| - 1 |
  float tangent_length_error = 0;
  float binormal_length_error = 0;
  float tangent_normal_dot = 0;      // max |t . n|
  float binormal_formula_error = 0;  // max |b - cross(n, t) w|
};

inline bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline FrameReport check_frames(const Mesh& mesh) {
  FrameReport r;
  for (const Vertex& v : mesh.vertices) {
    glm::vec3 t(v.tangent);
    if (!finite3(v.position) || !finite3(v.normal) || !finite3(t) || !std::isfinite(v.tangent.w) ||
        !finite3(v.binormal) || !std::isfinite(v.uv.x) || !std::isfinite(v.uv.y)) {
      ++r.non_finite;
      continue;
    }
    if (v.tangent.w != 1.0f && v.tangent.w != -1.0f) ++r.bad_handedness;
    r.normal_length_error = std::max(r.normal_length_error, std::abs(glm::length(v.normal) - 1.0f));
    r.tangent_length_error = std::max(r.tangent_length_error, std::abs(glm::length(t) - 1.0f));
    r.binormal_length_error = std::max(r.binormal_length_error, std::abs(glm::length(v.binormal) - 1.0f));
    r.tangent_normal_dot = std::max(r.tangent_normal_dot, std::abs(glm::dot(t, v.normal)));
    r.binormal_formula_error =
        std::max(r.binormal_formula_error, glm::length(v.binormal - glm::cross(v.normal, t) * v.tangent.w));
  }
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    ++r.triangles;
    uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    if (a >= mesh.vertices.size() || b >= mesh.vertices.size() || c >= mesh.vertices.size()) {
      ++r.bad_indices;
      continue;
    }
    const Vertex &va = mesh.vertices[a], &vb = mesh.vertices[b], &vc = mesh.vertices[c];
    glm::vec3 face = glm::cross(vb.position - va.position, vc.position - va.position);
    if (glm::dot(face, va.normal + vb.normal + vc.normal) <= 0.0f) ++r.inverted_triangles;
  }
  return r;
}

// The checks every mesh passes: finite, unit, orthogonal, consistent, counter-clockwise.
inline void expect_valid_frames(const Mesh& mesh, const char* what, float tolerance = 1e-5f) {
  FrameReport r = check_frames(mesh);
  EXPECT_EQ(r.non_finite, 0u) << what;
  EXPECT_EQ(r.bad_handedness, 0u) << what;
  EXPECT_EQ(r.bad_indices, 0u) << what;
  EXPECT_EQ(r.inverted_triangles, 0u) << what << " of " << r.triangles;
  EXPECT_EQ(mesh.indices.size() % 3, 0u) << what;
  EXPECT_LT(r.normal_length_error, tolerance) << what;
  EXPECT_LT(r.tangent_length_error, tolerance) << what;
  EXPECT_LT(r.binormal_length_error, tolerance) << what;
  EXPECT_LT(r.tangent_normal_dot, tolerance) << what;
  EXPECT_LT(r.binormal_formula_error, tolerance) << what;
}

}  // namespace fx::test
