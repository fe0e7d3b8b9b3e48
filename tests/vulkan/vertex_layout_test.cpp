// Matching the application's vertex layout to a vertex shader's inputs by semantic: no
// device needed, only the descriptions Vulkan gets.
#include <gtest/gtest.h>

#include "fx/vulkan/vertex_layout.h"

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
  auto matched = match_vertex_layout(layout, {input("pos", "POSITION", 0, 1, 3), input("World", "TEXCOORD4", 1, 4, 4)}, sink);
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

}  // namespace
}  // namespace fx::vk
