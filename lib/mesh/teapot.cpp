// Tessellation of the Utah teapot's Bezier patches.
#include <algorithm>
#include <cmath>

#include "detail.h"

namespace fx {
namespace {

// Bernstein cubic weights and their derivatives at t.
void bernstein(float t, float w[4], float dw[4]) {
  float s = 1.0f - t;
  w[0] = s * s * s;
  w[1] = 3.0f * t * s * s;
  w[2] = 3.0f * t * t * s;
  w[3] = t * t * t;
  dw[0] = -3.0f * s * s;
  dw[1] = 3.0f * s * s - 6.0f * t * s;
  dw[2] = 6.0f * t * s - 3.0f * t * t;
  dw[3] = 3.0f * t * t;
}

struct PatchPoint {
  glm::vec3 position, d_row, d_col;  // P and its derivatives along row and column params
};

// De Casteljau with std::lerp, which is exact at t = 0 and 1 and for equal end points:
// a collapsed patch edge (4 equal control points) then yields one exact point, so the
// grid can drop its zero-area triangles, and patch corners land exactly on their points.
glm::vec3 de_casteljau(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, float t) {
  auto lerp = [t](const glm::vec3& x, const glm::vec3& y) {
    return glm::vec3(std::lerp(x.x, y.x, t), std::lerp(x.y, y.y, t), std::lerp(x.z, y.z, t));
  };
  a = lerp(a, b);
  b = lerp(b, c);
  c = lerp(c, d);
  a = lerp(a, b);
  b = lerp(b, c);
  return lerp(a, b);
}

PatchPoint evaluate(const std::array<glm::vec3, 16>& cp, float row_t, float col_t) {
  float wr[4], dwr[4], wc[4], dwc[4];
  bernstein(row_t, wr, dwr);
  bernstein(col_t, wc, dwc);
  PatchPoint p{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
  glm::vec3 rows[4];
  for (int r = 0; r < 4; ++r) {
    const glm::vec3* q = &cp[size_t(r * 4)];
    rows[r] = de_casteljau(q[0], q[1], q[2], q[3], col_t);
    for (int c = 0; c < 4; ++c) {
      p.d_row += dwr[r] * wc[c] * q[c];
      p.d_col += wr[r] * dwc[c] * q[c];
    }
  }
  p.position = de_casteljau(rows[0], rows[1], rows[2], rows[3], row_t);
  return p;
}

// Newell's frame is Z up; fxkit's meshes are Y up. A rotation (det +1), so windings hold.
glm::vec3 z_up_to_y_up(const glm::vec3& p) { return {p.x, p.z, -p.y}; }

}  // namespace

Mesh teapot(uint32_t tessellation) {
  // Below 3 steps a flat triangle can face away from its corners' normals (the spout's lip).
  tessellation = std::clamp(tessellation, 3u, 256u);
  Mesh mesh;
  const std::span<const glm::vec3> points = teapot_control_points();
  for (const std::array<uint16_t, 16>& patch : teapot_patches()) {
    std::array<glm::vec3, 16> cp;
    glm::vec3 lo = z_up_to_y_up(points[patch[0]]), hi = lo;
    for (size_t k = 0; k < 16; ++k) {
      cp[k] = z_up_to_y_up(points[patch[k]]);
      lo = glm::min(lo, cp[k]);
      hi = glm::max(hi, cp[k]);
    }
    // |dP/du x dP/dv| is ~9 size^2 on a regular patch; 1e-5 of that is a collapsed edge
    // (where one derivative is rounding noise), not geometry.
    const float size2 = glm::dot(hi - lo, hi - lo);
    const float degenerate = 1e-5f * size2;
    // In Newell's data cross(dP/dcolumn, dP/drow) points out of every patch; the grid wants
    // cross(dP/dv, dP/du) outwards, so u runs against the columns and v along the rows.
    mesh_detail::append_grid(mesh, tessellation, tessellation, [&](float u, float v, Vertex& out) {
      PatchPoint p = evaluate(cp, v, 1.0f - u);
      glm::vec3 n = glm::cross(p.d_col, p.d_row);
      if (!(glm::length(n) > degenerate)) {
        // A collapsed edge (the lid's apex, the bottom's centre): one derivative vanishes.
        // The normal there is the limit from inside the patch; step towards the centre.
        constexpr float kStep = 1e-3f;
        PatchPoint q = evaluate(cp, v + (0.5f - v) * kStep * 2.0f, (1.0f - u) + (u - 0.5f) * kStep * 2.0f);
        n = glm::cross(q.d_col, q.d_row);
      }
      float len = glm::length(n);
      out.position = p.position;
      out.normal = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
      out.uv = {u, v};
    });
  }
  compute_tangents(mesh);
  return mesh;
}

}  // namespace fx
