// docs/meshes.md: a built-in mesh, its vertex layout by semantic, in Vulkan terms, bounds.
// The examples are the docs' text, verbatim (examples_compiled_test.cpp): not reformatted.
// clang-format off
#include "example_fixture.h"
#include "fx/mesh.h"
#include "fx/binding/vertex_layout.h"

namespace fx::docs {
namespace {

TEST_F(ExampleTest, MeshesAndTheirLayout) {
  fx::DiagnosticSink sink;
  std::optional<fx::Mesh> mesh = fx::make_mesh("teapot", sink);   // or sphere|torus|quad|path.obj
  const fx::MeshVertexLayout& layout = fx::mesh_vertex_layout();
  const fx::MeshVertexAttribute* t = layout.find("TANGENT");       // offset 24, float4
  fx::vk::VertexLayout vk_layout = fx::vk::to_vertex_layout(layout); // EffectBinding::add_vertex_layout
  fx::MeshBounds b = fx::bounds(*mesh);                             // frame the camera: center(), radius

  ASSERT_TRUE(mesh);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->offset, 24u);
  EXPECT_EQ(t->format, fx::VertexFormat::float4);
  EXPECT_EQ(vk_layout.attributes.size(), layout.attributes.size());
  EXPECT_GT(b.radius, 0.f);
}

}  // namespace
}  // namespace fx::docs
