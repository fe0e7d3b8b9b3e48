// OBJ loading: normals present or computed, quads and polygons triangulated, uv flip,
// broken and missing files reported as diagnostics.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "fx/mesh.h"
#include "mesh_checks.h"

namespace fx {
namespace {

std::filesystem::path data(const char* name) { return std::filesystem::path(FXKIT_MESH_DATA_DIR) / name; }

bool has_id(const DiagnosticSink& sink, const std::string& id) {
  for (const Diagnostic& d : sink.diagnostics())
    if (d.id == id) return true;
  return false;
}

TEST(Obj, QuadsWithoutNormalsGetSmoothComputedNormals) {
  DiagnosticSink sink;
  auto cube = load_obj(data("cube_quads.obj"), sink);
  ASSERT_TRUE(cube.has_value());
  EXPECT_EQ(sink.error_count(), 0u);
  EXPECT_EQ(cube->triangle_count(), 12u);  // 6 quads
  test::expect_valid_frames(*cube, "cube");
  // Smooth normals per position: each corner sees three equal-area faces.
  for (const Vertex& v : cube->vertices) EXPECT_LT(glm::length(v.normal - glm::normalize(v.position)), 1e-6f);
  // v flipped to top-down: the +Z face's bottom-left (vt 0 0) has uv (0, 1).
  bool found = false;
  for (const Vertex& v : cube->vertices)
    if (v.position == glm::vec3(-1, -1, 1) && v.uv == glm::vec2(0, 1)) found = true;
  EXPECT_TRUE(found);
}

TEST(Obj, ExplicitNormalsAreKeptNormalised) {
  DiagnosticSink sink;
  auto tri = load_obj(data("triangle_normals.obj"), sink);
  ASSERT_TRUE(tri.has_value());
  EXPECT_EQ(sink.error_count(), 0u);
  ASSERT_EQ(tri->vertices.size(), 3u);
  EXPECT_EQ(tri->triangle_count(), 1u);
  test::expect_valid_frames(*tri, "triangle");
  for (const Vertex& v : tri->vertices) {
    EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
    // OBJ v grows up the image, fxkit v down it: +v is -y here, so like the built-ins w = -1.
    EXPECT_EQ(v.tangent.w, -1.0f);
  }
}

TEST(Obj, PolygonWithoutUvsOrNormalsGetsAFiniteFrame) {
  DiagnosticSink sink;
  auto pentagon = load_obj(data("pentagon_no_uv.obj"), sink);
  ASSERT_TRUE(pentagon.has_value());
  EXPECT_EQ(pentagon->triangle_count(), 3u);
  test::expect_valid_frames(*pentagon, "pentagon");
  for (const Vertex& v : pentagon->vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
}

TEST(Obj, MissingMaterialLibraryIsAWarningOnly) {
  DiagnosticSink sink;
  auto tri = load_obj(data("missing_material.obj"), sink);
  ASSERT_TRUE(tri.has_value());
  EXPECT_EQ(tri->triangle_count(), 1u);
  EXPECT_EQ(sink.error_count(), 0u);
  EXPECT_GE(sink.warning_count(), 1u);
  EXPECT_TRUE(has_id(sink, "obj-warning"));
  bool names_file = false;
  for (const Diagnostic& d : sink.diagnostics())
    if (d.message.find("nothing_here.mtl") != std::string::npos) names_file = true;
  EXPECT_TRUE(names_file);
}

TEST(Obj, OutOfRangeIndexIsAnError) {
  DiagnosticSink sink;
  EXPECT_FALSE(load_obj(data("broken_index.obj"), sink).has_value());
  EXPECT_TRUE(has_id(sink, "obj-index-out-of-range"));
}

TEST(Obj, ZeroIndexIsAParseError) {
  DiagnosticSink sink;
  EXPECT_FALSE(load_obj(data("broken_zero_index.obj"), sink).has_value());
  EXPECT_TRUE(has_id(sink, "obj-parse-failed")) << sink.diagnostics().size();
}

TEST(Obj, FileWithoutFacesIsAnError) {
  DiagnosticSink sink;
  EXPECT_FALSE(load_obj(data("no_faces.obj"), sink).has_value());
  EXPECT_TRUE(has_id(sink, "obj-no-faces"));
}

TEST(Obj, MissingFileAndDirectoryAreErrors) {
  DiagnosticSink sink;
  EXPECT_FALSE(load_obj(data("does_not_exist.obj"), sink).has_value());
  ASSERT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "mesh-open-failed");
  EXPECT_NE(sink.diagnostics()[0].message.find("does_not_exist.obj"), std::string::npos);
  sink.clear();
  EXPECT_FALSE(load_obj(FXKIT_MESH_DATA_DIR, sink).has_value());
  EXPECT_TRUE(has_id(sink, "mesh-open-failed"));
}

TEST(Obj, MakeMeshLoadsPaths) {
  DiagnosticSink sink;
  auto cube = make_mesh(data("cube_quads.obj").string(), sink);
  ASSERT_TRUE(cube.has_value());
  EXPECT_EQ(cube->triangle_count(), 12u);
  EXPECT_FALSE(make_mesh("missing.obj", sink).has_value());
  EXPECT_TRUE(has_id(sink, "mesh-open-failed"));
}

}  // namespace
}  // namespace fx
