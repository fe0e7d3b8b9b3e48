// uniform_layouts: a linked program's uniform blocks laid out over the effect's parameters
// with real glslang reflection: each member's parameter slice, offset, strides and matrix
// order, aliases packed once, members no parameter holds listed.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "fx/compile/effect_file.h"
#include "fx/compile/uniform_layout.h"

namespace fx {
namespace {

std::unique_ptr<EffectFile> load(std::string text) {
  DiagnosticSink sink;
  auto file = EffectFile::load_text("layout.fx", std::move(text), FrontEndOptions{}, sink);
  EXPECT_TRUE(file) << (sink.diagnostics().empty() ? "" : sink.diagnostics().front().message);
  return file;
}

const BlockMemberLayout* member(const EffectFile& file, const UniformBlockLayout& block, std::string_view parameter,
                                uint32_t first_word = 0) {
  const uint32_t p = file.model->find_parameter(parameter);
  for (const BlockMemberLayout& m : block.members)
    if (m.slice.parameter == p && m.slice.first_word == first_word) return &m;
  return nullptr;
}

// The uniform blocks of pass P of technique T, laid out.
std::vector<UniformBlockLayout> layouts(const EffectFile& file) {
  const PassProgram* program = file.programs->program("T", "P");
  EXPECT_TRUE(program && program->ok());
  return program && program->ok() ? uniform_layouts(*file.model, *program) : std::vector<UniformBlockLayout>{};
}

TEST(UniformLayout, HlslMembersHoldTheirParametersWordsInTheirDeclaredOrder) {
  auto file = load(R"(
    float4 g_Color = {1, 0, 0, 1};
    row_major float4x4 Rows;
    float4x4 Columns;
    struct Light { float3 dir; float4 color; };
    Light lights[2];
    float4 PS(float4 p : TEXCOORD0) : COLOR {
      return g_Color + mul(p, Rows) + mul(p, Columns) + lights[1].color + float4(lights[0].dir, 0);
    }
    float4 VS(float4 p : POSITION) : POSITION { return p; }
    technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } })");
  ASSERT_TRUE(file);
  const std::vector<UniformBlockLayout> blocks = layouts(*file);
  ASSERT_EQ(blocks.size(), 1u);
  const UniformBlockLayout& global = blocks[0];
  EXPECT_EQ(global.name, "$Global");
  EXPECT_TRUE(global.unplaced.empty());
  const BlockMemberLayout* color = member(*file, global, "g_Color");
  ASSERT_TRUE(color);
  EXPECT_EQ(color->size, 16u);
  EXPECT_EQ(color->slice.type.to_string(), "float4");
  const BlockMemberLayout* rows = member(*file, global, "Rows");
  const BlockMemberLayout* columns = member(*file, global, "Columns");
  ASSERT_TRUE(rows && columns);
  EXPECT_EQ(rows->order, MatrixPacking::row_major);
  EXPECT_EQ(columns->order, MatrixPacking::column_major);
  EXPECT_EQ(columns->matrix_stride, 16u);
  // lights[1].color: element 1 starts 7 words in (float3 + float4), its color 3 further.
  const BlockMemberLayout* light = member(*file, global, "lights", 10);
  ASSERT_TRUE(light) << "lights[1].color";
  EXPECT_EQ(light->slice.type.to_string(), "float4");
  // Every slice is packed once: no two members hold the same words.
  for (size_t a = 0; a < global.members.size(); ++a)
    for (size_t b = a + 1; b < global.members.size(); ++b)
      EXPECT_FALSE(global.members[a].slice.parameter == global.members[b].slice.parameter &&
                   global.members[a].slice.first_word == global.members[b].slice.first_word &&
                   global.members[a].slice.type.same_as(global.members[b].slice.type));
}

TEST(UniformLayout, GlslMatricesArePackedRowByRow) {
  auto file = load(R"(
    float4x4 M;
    float4 Tint;
    GLSLShader Header { #version 450 }
    GLSLShader Block { layout(set = 0, binding = 0, std140) uniform Parameters { mat4 M; vec4 Tint; }; }
    GLSLShader VS { layout(location = 0) in vec3 pos; void main() { gl_Position = M * vec4(pos, 1.0); } }
    GLSLShader FS { layout(location = 0) out vec4 color; void main() { color = Tint; } }
    technique T { pass P { VertexShader = { Header, Block, VS }; PixelShader = { Header, Block, FS }; } })");
  ASSERT_TRUE(file);
  const std::vector<UniformBlockLayout> blocks = layouts(*file);
  ASSERT_EQ(blocks.size(), 1u);
  const BlockMemberLayout* m = member(*file, blocks[0], "M");
  const BlockMemberLayout* tint = member(*file, blocks[0], "Tint");
  ASSERT_TRUE(m && tint);
  EXPECT_EQ(m->order, MatrixPacking::row_major) << "GLSL's M * v is HLSL's mul(v, M) transposed";
  EXPECT_EQ(m->offset, 0u);
  EXPECT_EQ(tint->offset, 64u);
}

TEST(UniformLayout, MembersNoParameterHoldsAreListed) {
  auto file = load(R"(
    float4 Tint;
    GLSLShader Header { #version 450 }
    GLSLShader Block { layout(set = 0, binding = 0, std140) uniform Parameters { vec4 Tint; vec4 Undeclared; }; }
    GLSLShader VS { layout(location = 0) in vec3 pos; void main() { gl_Position = vec4(pos, 1.0); } }
    GLSLShader FS { layout(location = 0) out vec4 color; void main() { color = Tint + Undeclared; } }
    technique T { pass P { VertexShader = { Header, Block, VS }; PixelShader = { Header, Block, FS }; } })");
  ASSERT_TRUE(file);
  const std::vector<UniformBlockLayout> blocks = layouts(*file);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].unplaced, std::vector<std::string>{"Undeclared"});
  ASSERT_EQ(blocks[0].members.size(), 1u);
  EXPECT_EQ(blocks[0].members[0].slice.parameter, file->model->find_parameter("Tint"));
}

}  // namespace
}  // namespace fx
