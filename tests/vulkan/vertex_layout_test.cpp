// Matching the application's vertex layout to a vertex shader's inputs by semantic: no
// device needed, only the descriptions Vulkan gets.
#include <gtest/gtest.h>

#include "fx/binding/vertex_layout.h"
#include "fx/mesh.h"

namespace fx::vk {
namespace {

InterfaceVariable input(std::string name, std::string semantic, uint32_t location, uint8_t rows, uint8_t columns) {
  InterfaceVariable v;
  v.name = std::move(name);
  v.semantic = std::move(semantic);
  v.location = location;
  v.type.rows = rows;
  v.type.columns = columns;
  return v;
}

// An instanced world matrix, `float4x4 World : TEXCOORD4`, takes four locations and, as in
// D3D, four semantic indices: TEXCOORD4..TEXCOORD7, one column each.
TEST(VertexLayoutMatch, AMatrixInputTakesALocationAndASemanticIndexPerColumn) {
  EXPECT_EQ(input_semantics(input("World", "TEXCOORD4", 1, 4, 4)),
            (std::vector<std::string>{"TEXCOORD4", "TEXCOORD5", "TEXCOORD6", "TEXCOORD7"}));
  EXPECT_EQ(input_semantics(input("World", "BLENDWEIGHT", 1, 4, 3)),
            (std::vector<std::string>{"BLENDWEIGHT", "BLENDWEIGHT1", "BLENDWEIGHT2"}));
  EXPECT_EQ(input_semantics(input("uv", "TEXCOORD0", 0, 1, 2)), (std::vector<std::string>{"TEXCOORD"}));

  VertexLayout layout;
  layout.bindings = {{0, 12, VK_VERTEX_INPUT_RATE_VERTEX}, {1, 64, VK_VERTEX_INPUT_RATE_INSTANCE}};
  layout.attributes = {{"POSITION", VK_FORMAT_R32G32B32_SFLOAT, 0, 0}};
  for (uint32_t k = 0; k < 4; ++k)
    layout.attributes.push_back({"TEXCOORD" + std::to_string(4 + k), VK_FORMAT_R32G32B32A32_SFLOAT, 16 * k, 1});
  DiagnosticSink sink;
  auto matched =
      match_vertex_layout(layout, {input("pos", "POSITION", 0, 1, 3), input("World", "TEXCOORD4", 1, 4, 4)}, sink);
  ASSERT_TRUE(matched) << (sink.diagnostics().empty() ? "" : sink.diagnostics()[0].message);
  ASSERT_EQ(matched->attributes.size(), 5u);
  for (uint32_t k = 0; k < 4; ++k) {
    EXPECT_EQ(matched->attributes[1 + k].location, 1 + k);
    EXPECT_EQ(matched->attributes[1 + k].binding, 1u);
    EXPECT_EQ(matched->attributes[1 + k].offset, 16 * k);
  }
  // A column the layout lacks is named with its location.
  layout.attributes.pop_back();
  DiagnosticSink missing;
  EXPECT_FALSE(match_vertex_layout(layout, {input("World", "TEXCOORD4", 1, 4, 4)}, missing));
  ASSERT_EQ(missing.diagnostics().size(), 1u);
  EXPECT_NE(missing.diagnostics()[0].message.find("TEXCOORD7 ('World', location 4)"), std::string::npos)
      << missing.diagnostics()[0].message;
}

// The mesh library's layout of fx::Vertex in Vulkan terms: one binding of sizeof(Vertex),
// the D3D semantics, float formats and offsets as they are.
TEST(VertexLayoutFromMesh, FxVertexBecomesOneBindingOfFloatAttributes) {
  const VertexLayout layout = to_vertex_layout(mesh_vertex_layout());
  ASSERT_EQ(layout.bindings.size(), 1u);
  EXPECT_EQ(layout.bindings[0].binding, 0u);
  EXPECT_EQ(layout.bindings[0].stride, uint32_t(sizeof(Vertex)));
  EXPECT_EQ(layout.bindings[0].rate, VK_VERTEX_INPUT_RATE_VERTEX);
  ASSERT_EQ(layout.attributes.size(), 5u);
  const std::pair<const char*, VkFormat> expected[] = {{"POSITION", VK_FORMAT_R32G32B32_SFLOAT},
                                                       {"NORMAL", VK_FORMAT_R32G32B32_SFLOAT},
                                                       {"TANGENT", VK_FORMAT_R32G32B32A32_SFLOAT},
                                                       {"BINORMAL", VK_FORMAT_R32G32B32_SFLOAT},
                                                       {"TEXCOORD", VK_FORMAT_R32G32_SFLOAT}};
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(layout.attributes[i].semantic, expected[i].first);
    EXPECT_EQ(layout.attributes[i].format, expected[i].second) << expected[i].first;
    EXPECT_EQ(layout.attributes[i].offset, mesh_vertex_layout().attributes[i].offset);
    EXPECT_EQ(layout.attributes[i].binding, 0u);
  }
  EXPECT_EQ(layout.attributes[2].offset, uint32_t(offsetof(Vertex, tangent)));
}

// A semantic index other than 0 is spelled out; the binding number goes to every attribute,
// and the result matches shader inputs by semantic.
TEST(VertexLayoutFromMesh, SemanticIndexAndBindingCarryOver) {
  MeshVertexLayout mesh{20, {{"POSITION", 0, VertexFormat::float3, 0}, {"TEXCOORD", 1, VertexFormat::float2, 12}}};
  const VertexLayout layout = to_vertex_layout(mesh, 2);
  ASSERT_EQ(layout.bindings.size(), 1u);
  EXPECT_EQ(layout.bindings[0].binding, 2u);
  EXPECT_EQ(layout.bindings[0].stride, 20u);
  ASSERT_EQ(layout.attributes.size(), 2u);
  EXPECT_EQ(layout.attributes[1].semantic, "TEXCOORD1");
  EXPECT_EQ(layout.attributes[1].binding, 2u);
  DiagnosticSink sink;
  auto matched = match_vertex_layout(layout, {input("uv", "TEXCOORD1", 0, 1, 2)}, sink);
  ASSERT_TRUE(matched);
  ASSERT_EQ(matched->attributes.size(), 1u);
  EXPECT_EQ(matched->attributes[0].format, VK_FORMAT_R32G32_SFLOAT);
  EXPECT_EQ(matched->attributes[0].offset, 12u);
  EXPECT_EQ(matched->attributes[0].binding, 2u);
}

}  // namespace
}  // namespace fx::vk
