// Parametric built-in meshes: sphere, torus, quad, and the shared grid triangulation.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "detail.h"

namespace fx {
namespace mesh_detail {

void append_grid(Mesh& mesh, uint32_t columns, uint32_t rows,
                 const std::function<void(float u, float v, Vertex& vertex)>& surface) {
  const uint32_t base = uint32_t(mesh.vertices.size());
  const uint32_t stride = columns + 1;
  mesh.vertices.reserve(mesh.vertices.size() + size_t(stride) * (rows + 1));
  for (uint32_t j = 0; j <= rows; ++j) {
    for (uint32_t i = 0; i <= columns; ++i) {
      Vertex v;
      surface(float(i) / float(columns), float(j) / float(rows), v);
      mesh.vertices.push_back(v);
    }
  }
  auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
    const glm::vec3 &pa = mesh.vertices[a].position, &pb = mesh.vertices[b].position, &pc = mesh.vertices[c].position;
    if (pa == pb || pb == pc || pa == pc) return;
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  };
  for (uint32_t j = 0; j < rows; ++j) {
    for (uint32_t i = 0; i < columns; ++i) {
      uint32_t a = base + j * stride + i, c = a + 1;  // top-left, top-right
      uint32_t b = a + stride, d = b + 1;             // bottom-left, bottom-right
      add(a, b, c);
      add(c, b, d);
    }
  }
}

}  // namespace mesh_detail

namespace {
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
}

Mesh sphere(uint32_t rings, uint32_t segments) {
  rings = std::max(rings, 2u);
  segments = std::max(segments, 3u);
  Mesh mesh;
  mesh_detail::append_grid(mesh, segments, rings, [](float u, float v, Vertex& out) {
    float phi = u >= 1.0f ? 0.0f : kTwoPi * u, theta = std::numbers::pi_v<float> * v;
    // Exact poles: sin(pi) in float is -8.7e-8, which would split the south pole's copies.
    float st = v <= 0.0f || v >= 1.0f ? 0.0f : std::sin(theta);
    float ct = v <= 0.0f ? 1.0f : (v >= 1.0f ? -1.0f : std::cos(theta));
    glm::vec3 p(st * std::sin(phi), ct, st * std::cos(phi));
    out.position = p;
    out.normal = p;
    out.uv = {u, v};
  });
  compute_tangents(mesh);
  return mesh;
}

Mesh torus(float major_radius, float minor_radius, uint32_t rings, uint32_t segments) {
  rings = std::max(rings, 3u);
  segments = std::max(segments, 3u);
  Mesh mesh;
  mesh_detail::append_grid(mesh, rings, segments, [&](float u, float v, Vertex& out) {
    // u = 1 and v = 1 must land exactly on u = 0 and v = 0 so seam copies coincide.
    float alpha = u >= 1.0f ? 0.0f : kTwoPi * u, beta = v >= 1.0f ? 0.0f : kTwoPi * v;
    glm::vec3 center(major_radius * std::sin(alpha), 0.0f, major_radius * std::cos(alpha));
    // v grows downwards over the outer equator, as on the sphere: same uv handedness.
    glm::vec3 n(std::cos(beta) * std::sin(alpha), -std::sin(beta), std::cos(beta) * std::cos(alpha));
    out.position = center + minor_radius * n;
    out.normal = n;
    out.uv = {u, v};
  });
  compute_tangents(mesh);
  return mesh;
}

Mesh quad() {
  Mesh mesh;
  mesh_detail::append_grid(mesh, 1, 1, [](float u, float v, Vertex& out) {
    out.position = {u - 0.5f, 0.5f - v, 0.0f};
    out.normal = {0.0f, 0.0f, 1.0f};
    out.uv = {u, v};
  });
  compute_tangents(mesh);
  return mesh;
}

}  // namespace fx
