// The Utah teapot: the typed control data (counts, symmetries, shared patch boundaries)
// and the tessellated mesh (bounds, counts, orientation, closed-ish surface).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "fx/mesh.h"
#include "mesh_checks.h"

namespace fx {
namespace {

using Key = std::tuple<float, float, float>;
Key key(const glm::vec3& p) { return {p.x + 0.0f, p.y + 0.0f, p.z + 0.0f}; }

TEST(TeapotData, CountsAndIndexRange) {
  auto points = teapot_control_points();
  auto patches = teapot_patches();
  EXPECT_EQ(points.size(), 306u);
  EXPECT_EQ(patches.size(), 32u);
  std::set<uint16_t> used;
  for (const auto& p : patches)
    for (uint16_t i : p) {
      EXPECT_LT(i, 306u);
      used.insert(i);
    }
  // Everything but the lid apex's nudged copies (204, 205) and two unused lid points.
  EXPECT_EQ(used.size(), 302u);
  for (uint16_t unused : {204, 205, 215, 222}) EXPECT_EQ(used.count(unused), 0u) << unused;
}

TEST(TeapotData, ControlHullBounds) {
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& p : teapot_control_points()) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  EXPECT_EQ(lo, glm::vec3(-3.0f, -2.0f, 0.0f));
  EXPECT_EQ(hi, glm::vec3(3.525f, 2.0f, 3.15f));
}

TEST(TeapotData, MirrorSymmetricAcrossXZ) {
  // Newell's teapot is symmetric under y -> -y: a typo in one point breaks this.
  std::set<Key> all;
  for (const glm::vec3& p : teapot_control_points()) all.insert(key(p));
  for (const glm::vec3& p : teapot_control_points())
    EXPECT_TRUE(all.count(key({p.x, -p.y, p.z}))) << p.x << " " << p.y << " " << p.z;
}

TEST(TeapotData, BodyLidAndBottomHaveFourFoldSymmetry) {
  // Rim, body, lid and bottom (patches 0-11, 20-31) are surfaces of revolution built from
  // quarter patches: each control point turned by 90 degrees about Z is a control point.
  auto points = teapot_control_points();
  std::set<Key> all;
  for (const glm::vec3& p : points) all.insert(key(p));
  auto patches = teapot_patches();
  for (size_t i = 0; i < 32; ++i) {
    if (i >= 12 && i < 20) continue;  // handle and spout
    for (uint16_t k : patches[i]) {
      const glm::vec3& p = points[k];
      EXPECT_TRUE(all.count(key({-p.y, p.x, p.z}))) << "patch " << i << " point " << k;
    }
    // ...and the next patch of its group of four is this one turned by 90 degrees (the
    // bottom turns the other way round from the rest).
    size_t first = i - i % 4;
    const glm::vec3& a = points[patches[i][5]];
    const glm::vec3& b = points[patches[first + (i - first + 1) % 4][5]];
    float sign = i >= 28 ? 1.0f : -1.0f;
    EXPECT_NEAR(b.x, -sign * a.y, 1e-6f) << i;
    EXPECT_NEAR(b.y, sign * a.x, 1e-6f) << i;
  }
}

TEST(TeapotData, PatchBoundariesAreSharedExceptTheKnownOpenings) {
  // A boundary curve is 4 control points; curves shared by two patches (either direction)
  // make the surface watertight there. The openings are the body's rim (4 curves), the
  // lid's rim (4), the spout's two ends (2 + 2) and the handle's two ends (2 + 2).
  auto points = teapot_control_points();
  auto patches = teapot_patches();
  using Curve = std::array<Key, 4>;
  std::map<Curve, int> uses;
  std::vector<std::pair<size_t, Curve>> curves;
  for (size_t i = 0; i < patches.size(); ++i) {
    const auto& p = patches[i];
    const int edges[4][4] = {{0, 1, 2, 3}, {12, 13, 14, 15}, {0, 4, 8, 12}, {3, 7, 11, 15}};
    for (const auto& e : edges) {
      Curve c, r;
      for (int k = 0; k < 4; ++k) {
        c[size_t(k)] = key(points[p[size_t(e[k])]]);
        r[size_t(3 - k)] = c[size_t(k)];
      }
      if (c[0] == c[1] && c[1] == c[2] && c[2] == c[3]) continue;  // collapsed: apex, centre
      Curve canonical = std::min(c, r);
      ++uses[canonical];
      curves.push_back({i, canonical});
    }
  }
  std::map<size_t, int> open_per_patch;
  for (const auto& [patch, curve] : curves) {
    EXPECT_LE(uses[curve], 2) << "patch " << patch;
    if (uses[curve] == 1) ++open_per_patch[patch];
  }
  std::map<size_t, int> expected;
  for (size_t i : {0, 1, 2, 3, 24, 25, 26, 27, 12, 13, 14, 15, 16, 17, 18, 19}) expected[i] = 1;
  EXPECT_EQ(open_per_patch, expected);
}

TEST(Teapot, TessellatedCountsBoundsAndFrames) {
  const uint32_t n = 8;
  Mesh t = teapot(n);
  EXPECT_EQ(t.vertices.size(), size_t(32) * (n + 1) * (n + 1));
  // Collapsed rows (lid apex: 4 patches, bottom centre: 4 patches) drop one triangle per cell.
  EXPECT_EQ(t.triangle_count(), size_t(32) * 2 * n * n - size_t(8) * n);
  test::expect_valid_frames(t, "teapot", 2e-5f);
  MeshBounds b = bounds(t);
  // Patch corners lie on the surface: bottom (y = 0), knob top (3.15), body at radius 2,
  // handle's outer corner at x = -3; the spout's tip lies inside its control hull (3.525).
  EXPECT_NEAR(b.min.y, 0.0f, 1e-6f);
  EXPECT_NEAR(b.max.y, 3.15f, 1e-6f);
  EXPECT_NEAR(b.min.z, -2.0f, 1e-6f);
  EXPECT_NEAR(b.max.z, 2.0f, 1e-6f);
  EXPECT_NEAR(b.min.x, -3.0f, 1e-6f);
  EXPECT_GT(b.max.x, 3.3f);
  EXPECT_LT(b.max.x, 3.525f);
}

TEST(Teapot, NormalsPointOutOfTheBody) {
  Mesh t = teapot(6);
  const size_t per_patch = 7 * 7;
  // Rim top and lid face up, body and the knob's underside face away from the axis, the
  // bottom faces down.
  for (size_t patch = 0; patch < 32; ++patch) {
    const Vertex& mid = t.vertices[patch * per_patch + 3 * 7 + 3];
    glm::vec3 radial(mid.position.x, 0.0f, mid.position.z);
    if ((patch >= 4 && patch < 12) || (patch >= 20 && patch < 24)) {
      EXPECT_GT(glm::dot(mid.normal, glm::normalize(radial)), 0.6f) << patch;
    }
    if (patch < 4 || (patch >= 24 && patch < 28)) {
      EXPECT_GT(mid.normal.y, 0.9f) << patch;
    }
    if (patch >= 28) {
      EXPECT_LT(mid.normal.y, -0.9f) << patch;
    }
  }
  // The apex and bottom centre: the collapsed edge's limit normal.
  for (const Vertex& v : t.vertices) {
    if (glm::length(v.position - glm::vec3(0, 3.15f, 0)) < 1e-6f) {
      EXPECT_GT(v.normal.y, 0.999f);
    }
    if (glm::length(v.position) < 1e-6f) {
      EXPECT_LT(v.normal.y, -0.999f);
    }
  }
}

TEST(Teapot, SharedBoundariesMeetWithAgreeingNormals) {
  // Closed-ish: every vertex on a shared patch boundary has a twin from the neighbouring
  // patch at the same point, and (G1 where the model is smooth) nearly the same normal.
  Mesh t = teapot(8);
  std::map<Key, std::vector<const Vertex*>> at;
  for (const Vertex& v : t.vertices) {
    glm::vec3 q = glm::round(v.position * 1e4f) / 1e4f;  // patches evaluate shared edges independently
    at[key(q)].push_back(&v);
  }
  size_t shared = 0, creased = 0, opposed = 0;
  for (const auto& [k, vs] : at) {
    if (vs.size() < 2) continue;
    // The handle's lower end touches the body in one point without sharing an edge.
    if (k == key(glm::vec3(-2.0f, 0.9f, 0.0f))) continue;
    ++shared;
    for (const Vertex* a : vs)
      for (const Vertex* b : vs) {
        float d = glm::dot(a->normal, b->normal);
        if (d < 0.0f) ++opposed;
        else if (d < 0.95f) ++creased;
      }
  }
  EXPECT_GT(shared, 300u);  // 400 at tessellation 8
  EXPECT_EQ(opposed, 0u);   // every patch oriented outwards consistently
  std::printf("[ measured ] teapot(8): %zu shared boundary points, %zu pairs differ by > 18 degrees\n", shared,
              creased);
}

TEST(Teapot, TessellationIsClamped) {
  Mesh t = teapot(0);
  EXPECT_EQ(t.vertices.size(), 32u * 16u);
  test::expect_valid_frames(t, "teapot(0)", 2e-5f);
}

}  // namespace
}  // namespace fx
