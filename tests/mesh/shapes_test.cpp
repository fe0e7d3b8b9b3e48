// Sphere, torus and quad against their analytic frames; the vertex layout; the tangent
// solver on degenerate input.
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "fx/mesh.h"
#include "mesh_checks.h"

namespace fx {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

TEST(MeshVertexLayout, DescribesVertexBySemantic) {
  const MeshVertexLayout& layout = mesh_vertex_layout();
  EXPECT_EQ(layout.stride, sizeof(Vertex));
  ASSERT_EQ(layout.attributes.size(), 5u);
  const MeshVertexAttribute* uv = layout.find("TEXCOORD0");
  ASSERT_NE(uv, nullptr);
  EXPECT_EQ(uv->offset, offsetof(Vertex, uv));
  EXPECT_EQ(uv->format, VertexFormat::float2);
  EXPECT_EQ(layout.find("texcoord"), uv);  // no index means 0, case-insensitive
  const MeshVertexAttribute* t = layout.find("Tangent");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->offset, offsetof(Vertex, tangent));
  EXPECT_EQ(t->format, VertexFormat::float4);
  EXPECT_EQ(layout.find("POSITION0")->offset, offsetof(Vertex, position));
  EXPECT_EQ(layout.find("NORMAL")->offset, offsetof(Vertex, normal));
  EXPECT_EQ(layout.find("BINORMAL")->offset, offsetof(Vertex, binormal));
  EXPECT_EQ(layout.find("TEXCOORD1"), nullptr);
  EXPECT_EQ(layout.find("COLOR"), nullptr);
  EXPECT_EQ(layout.find("TEXCOORD99999999999999999999"), nullptr);
  EXPECT_EQ(layout.find(""), nullptr);
  // Attributes lie inside the stride and do not overlap.
  uint32_t end = 0;
  for (const MeshVertexAttribute& a : layout.attributes) {
    EXPECT_GE(a.offset, end) << a.semantic;
    end = a.offset + format_size(a.format);
  }
  EXPECT_LE(end, layout.stride);
}

TEST(Quad, UnitSquareFacingPlusZ) {
  Mesh q = quad();
  test::expect_valid_frames(q, "quad");
  ASSERT_EQ(q.vertices.size(), 4u);
  EXPECT_EQ(q.triangle_count(), 2u);
  MeshBounds b = bounds(q);
  EXPECT_EQ(b.min, glm::vec3(-0.5f, -0.5f, 0.0f));
  EXPECT_EQ(b.max, glm::vec3(0.5f, 0.5f, 0.0f));
  for (const Vertex& v : q.vertices) {
    EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
    EXPECT_EQ(v.uv, glm::vec2(v.position.x + 0.5f, 0.5f - v.position.y));  // (0,0) top-left
    EXPECT_EQ(glm::vec3(v.tangent), glm::vec3(1, 0, 0));
    EXPECT_EQ(v.binormal, glm::vec3(0, -1, 0));  // +v runs down the image
    EXPECT_EQ(v.tangent.w, -1.0f);
  }
}

TEST(Sphere, NormalsArePositionsAndTangentsFollowLatitude) {
  const uint32_t rings = 24, segments = 48;
  Mesh s = sphere(rings, segments);
  test::expect_valid_frames(s, "sphere");
  EXPECT_EQ(s.vertices.size(), size_t(rings + 1) * (segments + 1));
  // Two triangles per cell, minus the one collapsed triangle per cell at each pole.
  EXPECT_EQ(s.triangle_count(), size_t(2) * rings * segments - 2 * segments);
  float worst_normal = 0, worst_tangent = 0, worst_equator = 0, worst_radius = 0;
  for (const Vertex& v : s.vertices) {
    worst_radius = std::max(worst_radius, std::abs(glm::length(v.position) - 1.0f));
    worst_normal = std::max(worst_normal, glm::length(v.normal - glm::normalize(v.position)));
    if (std::abs(v.position.y) > 0.999f) continue;  // the poles have no latitude direction
    float phi = 2.0f * kPi * v.uv.x;
    glm::vec3 analytic(std::cos(phi), 0.0f, -std::sin(phi));  // d/du of (sin phi, ., cos phi)
    float error = glm::length(glm::vec3(v.tangent) - analytic);
    worst_tangent = std::max(worst_tangent, error);
    if (std::abs(v.position.y) < 0.5f) worst_equator = std::max(worst_equator, error);
    EXPECT_EQ(v.tangent.w, -1.0f);
  }
  EXPECT_LT(worst_radius, 1e-6f);
  EXPECT_LT(worst_normal, 1e-6f);
  // Averaged triangle tangents carry the grid diagonals' asymmetry: zero on the equator,
  // growing like cot(theta) / rings towards the poles (measured 0.022 rad on the first ring
  // at 24 rings). The u = 0/1 seam is no worse: its copies share their sums.
  EXPECT_LT(worst_tangent, 0.03f);
  EXPECT_LT(worst_equator, 3e-3f);
  std::printf(
      "[ measured ] sphere %ux%u: max |n - p/|p|| %.2g; tangent vs analytic: max %.2g "
      "(first ring), %.2g within 30 degrees of the equator\n",
      rings, segments, worst_normal, worst_tangent, worst_equator);
}

TEST(Sphere, SeamAndPoleCopiesAgree) {
  Mesh s = sphere(8, 16);
  // Row j, column 0 and column 16 are the same point on the u = 0/1 seam.
  for (uint32_t j = 1; j < 8; ++j) {
    const Vertex& a = s.vertices[j * 17];
    const Vertex& b = s.vertices[j * 17 + 16];
    EXPECT_EQ(a.position, b.position);
    EXPECT_LT(glm::length(glm::vec3(a.tangent) - glm::vec3(b.tangent)), 1e-6f) << "row " << j;
  }
}

TEST(Sphere, TinyParametersAreRaised) {
  Mesh s = sphere(0, 0);
  EXPECT_EQ(s.vertices.size(), size_t(3) * 4);
  test::expect_valid_frames(s, "sphere(0,0)");
}

TEST(Torus, NormalsAndTangentsMatchAnalyticFrame) {
  const float R = 1.0f, r = 0.25f;
  Mesh t = torus(R, r, 64, 32);
  test::expect_valid_frames(t, "torus");
  EXPECT_EQ(t.vertices.size(), size_t(65) * 33);
  EXPECT_EQ(t.triangle_count(), size_t(2) * 64 * 32);
  float worst_normal = 0, worst_tangent = 0, worst_binormal = 0;
  for (const Vertex& v : t.vertices) {
    glm::vec3 ring_center = R * glm::normalize(glm::vec3(v.position.x, 0.0f, v.position.z));
    EXPECT_NEAR(glm::length(v.position - ring_center), r, 1e-6f);
    worst_normal = std::max(worst_normal, glm::length(v.normal - (v.position - ring_center) / r));
    float alpha = 2.0f * kPi * v.uv.x, beta = 2.0f * kPi * v.uv.y;
    glm::vec3 tangent(std::cos(alpha), 0.0f, -std::sin(alpha));
    glm::vec3 binormal(-std::sin(beta) * std::sin(alpha), -std::cos(beta), -std::sin(beta) * std::cos(alpha));
    worst_tangent = std::max(worst_tangent, glm::length(glm::vec3(v.tangent) - tangent));
    worst_binormal = std::max(worst_binormal, glm::length(v.binormal - binormal));
  }
  EXPECT_LT(worst_normal, 2e-6f);
  // The grid's diagonals make each vertex's triangle fan slightly asymmetric: measured
  // 8.1e-4 at 64x32, shrinking with the step.
  EXPECT_LT(worst_tangent, 2e-3f);
  EXPECT_LT(worst_binormal, 2e-3f);
  std::printf("[ measured ] torus 64x32: max normal err %.2g, tangent err %.2g, binormal err %.2g\n", worst_normal,
              worst_tangent, worst_binormal);
}

TEST(Tangents, AllEqualUvsGiveAFiniteFrame) {
  Mesh q = quad();
  for (Vertex& v : q.vertices) v.uv = glm::vec2(0.25f);
  compute_tangents(q);
  test::expect_valid_frames(q, "quad with equal uvs");
}

TEST(Tangents, UvCollinearOrNaNOrZeroNormalNeverGiveNaN) {
  Mesh q = quad();
  // uvs on a line: det == 0 but non-zero deltas.
  for (Vertex& v : q.vertices) v.uv = glm::vec2(v.position.x, 2.0f * v.position.x);
  compute_tangents(q);
  test::expect_valid_frames(q, "collinear uvs");

  Mesh z = quad();
  for (Vertex& v : z.vertices) v.normal = glm::vec3(0.0f);
  compute_tangents(z);
  test::expect_valid_frames(z, "zero normals");

  Mesh nan_uv = quad();
  nan_uv.vertices[0].uv = glm::vec2(std::numeric_limits<float>::quiet_NaN());
  nan_uv.vertices[3].normal = glm::vec3(std::numeric_limits<float>::infinity());
  compute_tangents(nan_uv);
  for (Vertex& v : nan_uv.vertices) v.uv = glm::vec2(0.0f);  // the input NaN stays; frames must not
  test::expect_valid_frames(nan_uv, "NaN uv, infinite normal");

  // Normal along dP/du: Gram-Schmidt leaves nothing; dP/dv or any perpendicular steps in.
  Mesh p = quad();
  for (Vertex& v : p.vertices) v.normal = glm::vec3(1, 0, 0);
  compute_tangents(p);
  test::FrameReport r = test::check_frames(p);
  EXPECT_EQ(r.non_finite, 0u);
  EXPECT_LT(r.tangent_normal_dot, 1e-6f);
  EXPECT_LT(r.tangent_length_error, 1e-6f);

  // Degenerate triangle (all corners equal) and an index past the end: skipped.
  Mesh d = quad();
  for (Vertex& v : d.vertices) v.position = glm::vec3(1.0f);
  d.indices.push_back(99);
  d.indices.push_back(0);
  d.indices.push_back(1);
  compute_tangents(d);
  for (const Vertex& v : d.vertices) EXPECT_TRUE(test::finite3(glm::vec3(v.tangent)));
}

TEST(Tangents, MirroredUvsFlipHandedness) {
  Mesh q = quad();
  for (Vertex& v : q.vertices) v.uv.x = 1.0f - v.uv.x;
  compute_tangents(q);
  test::expect_valid_frames(q, "mirrored quad");
  for (const Vertex& v : q.vertices) {
    EXPECT_EQ(glm::vec3(v.tangent), glm::vec3(-1, 0, 0));
    EXPECT_EQ(v.tangent.w, 1.0f);
    EXPECT_EQ(v.binormal, glm::vec3(0, -1, 0));
  }
}

TEST(Tangents, SkewedUvsGiveDpDuNotTheUGradient) {
  // u = x + y, v = y: dP/du (v held) is +x, while grad u points along (1,1): the frame
  // must follow the texture's u axis as the shader samples it.
  Mesh q = quad();
  for (Vertex& v : q.vertices) v.uv = {v.position.x + v.position.y, v.position.y};
  compute_tangents(q);
  for (const Vertex& v : q.vertices) {
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
    EXPECT_NEAR(v.tangent.y, 0.0f, 1e-6f);
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
}

TEST(Normals, ComputeNormalsMatchesWinding) {
  Mesh s = sphere(16, 32);
  for (Vertex& v : s.vertices) v.normal = glm::vec3(0.0f);
  compute_normals(s);
  float worst = 0, worst_equator = 0;
  for (const Vertex& v : s.vertices) {
    // Pole copies see one triangle each (or none: the grid's unused corner copies).
    if (std::abs(v.position.y) > 0.999f) continue;
    float error = glm::length(v.normal - glm::normalize(v.position));
    worst = std::max(worst, error);
    if (std::abs(v.position.y) < 0.5f) worst_equator = std::max(worst_equator, error);
    EXPECT_GT(glm::dot(v.normal, v.position), 0.99f);
  }
  // Faceting error of a 16x32 sphere (measured 0.006 max, 0.0023 near the equator); the
  // u = 0/1 seam is not creased (area weighting per vertex index gave 0.10 there).
  EXPECT_LT(worst, 0.01f);
  EXPECT_LT(worst_equator, 0.005f);
  std::printf(
      "[ measured ] compute_normals on sphere(16, 32): max error %.3g, %.3g within 30 "
      "degrees of the equator\n",
      worst, worst_equator);
}

TEST(MakeMesh, BuiltInsAndUnknownNames) {
  DiagnosticSink sink;
  for (const char* name : {"sphere", "torus", "quad", "teapot", "Teapot"}) {
    auto m = make_mesh(name, sink);
    ASSERT_TRUE(m.has_value()) << name;
    EXPECT_FALSE(m->indices.empty()) << name;
  }
  EXPECT_FALSE(sink.has_errors());
  EXPECT_FALSE(make_mesh("sphre", sink).has_value());
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "unknown-mesh");
  EXPECT_NE(sink.diagnostics()[0].message.find("did you mean 'sphere'"), std::string::npos)
      << sink.diagnostics()[0].message;
}

TEST(Bounds, CenterAndRadius) {
  MeshBounds b = bounds(torus(2.0f, 0.5f, 32, 16));
  EXPECT_NEAR(b.max.x, 2.5f, 1e-5f);
  EXPECT_NEAR(b.min.y, -0.5f, 1e-5f);
  EXPECT_NEAR(glm::length(b.center()), 0.0f, 1e-5f);
  EXPECT_NEAR(b.radius, 2.5f, 1e-5f);
  EXPECT_EQ(bounds(Mesh{}).radius, 0.0f);
}

}  // namespace
}  // namespace fx
