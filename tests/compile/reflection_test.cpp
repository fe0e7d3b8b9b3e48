// Reflected block layouts against the HLSL cbuffer packing rules and std140.
#include <gtest/gtest.h>

#include "compile_test_util.h"

namespace fx {
namespace {

const BlockMember& member(const UniformBlock& b, const std::string& name) {
  for (const BlockMember& m : b.members)
    if (m.name == name) return m;
  static BlockMember missing;
  ADD_FAILURE() << "no member " << name;
  return missing;
}

TEST(Reflection, HlslCbufferLayoutIsWhatTheSpirvSays) {
  // glslang lays out HLSL cbuffers by std140 rules (vec3 + float share 16 bytes; arrays have
  // a 16-byte stride and the next member starts after a whole register; matrices take one
  // register per column). fxc differs in two places, marked "fxc:", because it also packs
  // into the tail of an array's last register and places vectors anywhere that does not
  // cross a register. fxkit writes parameters through this reflection, so the SPIR-V layout
  // is the one that matters; docs/shader-compilation.md lists the difference.
  const char* src = R"(cbuffer Params {
  float3 Dir;       // 0
  float Gloss;      // 12: packs with Dir
  float2 Offsets[3];// 16, stride 16, last element ends at 56
  float Tail;       // 64 (fxc: 56, inside the array's last register)
  float3 Color;     // 80 (fxc: 68)
  float4x4 World;   // 96: 4 registers
  float3x3 Normal;  // 160: 3 registers
  float After;      // 208
};
float4 PS() : SV_Target { return float4(Dir * Gloss + Color + Offsets[2].xyx + Tail + After, 1) + World[0] + Normal[0].xyzx; }
)";
  ShaderCompiler compiler;
  CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_5_0"));
  ASSERT_TRUE(ps.ok) << ps.info_log;
  ASSERT_EQ(ps.reflection.uniform_blocks.size(), 1u);
  const UniformBlock& b = ps.reflection.uniform_blocks[0];
  EXPECT_EQ(b.name, "Params");
  EXPECT_EQ(member(b, "Dir").offset, 0u);
  EXPECT_EQ(member(b, "Gloss").offset, 12u);
  EXPECT_EQ(member(b, "Offsets").offset, 16u);
  EXPECT_EQ(member(b, "Offsets").array_stride, 16u);
  EXPECT_EQ(member(b, "Offsets").type.array_size, 3u);
  EXPECT_EQ(member(b, "Offsets").size, 40u);  // two strides plus one float2
  EXPECT_EQ(member(b, "Tail").offset, 64u);
  EXPECT_EQ(member(b, "Color").offset, 80u);
  EXPECT_EQ(member(b, "World").offset, 96u);
  EXPECT_EQ(member(b, "World").matrix_stride, 16u);
  EXPECT_EQ(member(b, "Normal").offset, 160u);
  EXPECT_EQ(member(b, "After").offset, 208u);
  EXPECT_EQ(b.size, 212u);
  // D3D's default column_major packing; glslang expresses it on the transposed type as
  // SPIR-V RowMajor (see docs/shader-compilation.md).
  EXPECT_EQ(member(b, "World").matrix_layout, MatrixLayout::row_major);
  for (size_t i = 1; i < b.members.size(); ++i) EXPECT_LE(b.members[i - 1].offset, b.members[i].offset);
}

TEST(Reflection, RowMajorPragmaChangesTheLayout) {
  const char* src = R"(row_major float4x4 A;
float4x4 B;
float4 PS() : SV_Target { return A[0] + B[0]; }
)";
  ShaderCompiler compiler;
  CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_3_0"));
  ASSERT_TRUE(ps.ok) << ps.info_log;
  const UniformBlock& g = ps.reflection.uniform_blocks.at(0);
  EXPECT_EQ(g.name, "$Global");
  EXPECT_NE(member(g, "A").matrix_layout, member(g, "B").matrix_layout);
  EXPECT_EQ(member(g, "B").offset, 64u);
}

// An array of HLSL float4x3 (a skinning palette): three 16-byte registers per element, as the
// SPIR-V's ArrayStride says; glslang's own reflection reported the column-major 64.
TEST(Reflection, RowMajorMatrixArrayStrideIsTheModules) {
  const char* src = R"(float4x3 Bones[4];
float4 After;
float4 VS(float4 p : POSITION, uint4 i : BLENDINDICES) : POSITION { return float4(mul(p, Bones[i.x]), 1) + After; }
)";
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", "vs_3_0"));
  ASSERT_TRUE(vs.ok) << vs.info_log;
  const UniformBlock& g = vs.reflection.uniform_blocks.at(0);
  EXPECT_EQ(member(g, "Bones").array_stride, 48u);
  EXPECT_EQ(member(g, "Bones").size, 4u * 48u);
  EXPECT_EQ(member(g, "After").offset, 4u * 48u);
  EXPECT_LE(member(g, "Bones").offset + member(g, "Bones").size, member(g, "After").offset);
}

TEST(Reflection, GlslStd140Layout) {
  const char* src = R"(#version 450
layout(set = 0, binding = 0, std140) uniform Block {
  vec3 a;      // 0
  float b;     // 12
  float c[2];  // 16, stride 16 in std140
  vec2 d;      // 48
  mat3 m;      // 64, 3 columns of 16
  float e;     // 112
} u;
layout(push_constant) uniform Push { vec4 tint; } pc;
layout(location = 0) out vec4 o;
void main() { o = vec4(u.a * u.b + u.c[1] + u.m[0] + u.e, u.d.x) * pc.tint; }
)";
  ShaderCompiler compiler;
  CompiledShader fs = compiler.compile(test::unit(src, ShaderStage::fragment, "main", "450", ShaderLanguage::glsl));
  ASSERT_TRUE(fs.ok) << fs.info_log;
  ASSERT_EQ(fs.reflection.uniform_blocks.size(), 1u);
  const UniformBlock& b = fs.reflection.uniform_blocks[0];
  EXPECT_EQ(member(b, "Block.a").offset, 0u);
  EXPECT_EQ(member(b, "Block.b").offset, 12u);
  EXPECT_EQ(member(b, "Block.c").offset, 16u);
  EXPECT_EQ(member(b, "Block.c").array_stride, 16u);
  EXPECT_EQ(member(b, "Block.d").offset, 48u);
  EXPECT_EQ(member(b, "Block.m").offset, 64u);
  EXPECT_EQ(member(b, "Block.m").matrix_stride, 16u);
  EXPECT_EQ(member(b, "Block.m").matrix_layout, MatrixLayout::column_major);
  EXPECT_EQ(member(b, "Block.e").offset, 112u);
  ASSERT_EQ(fs.reflection.push_constants.size(), 1u);
  EXPECT_EQ(fs.reflection.push_constants[0].size, 16u);
}

}  // namespace
}  // namespace fx
