// Compiling D3D9-style, D3D10-style HLSL and GLSL 450 to valid Vulkan SPIR-V.
#include <gtest/gtest.h>

#include <regex>
#include <thread>

#include "compile_test_util.h"
#include "fx/compile/shader_compiler.h"

namespace fx {
namespace {

using test::unit;

TEST(ShaderProfile, ParsesHlslAndGlslProfiles) {
  auto vs = parse_profile("vs_1_1");
  ASSERT_TRUE(vs);
  EXPECT_EQ(vs->stage, ShaderStage::vertex);
  EXPECT_TRUE(vs->dx9());
  auto ps4 = parse_profile("ps_4_0_level_9_1");
  ASSERT_TRUE(ps4);
  EXPECT_EQ(ps4->stage, ShaderStage::fragment);
  EXPECT_FALSE(ps4->dx9());
  EXPECT_EQ(parse_profile("cs_5_0")->stage, ShaderStage::compute);
  EXPECT_EQ(parse_profile("450")->language, ShaderLanguage::glsl);
  EXPECT_EQ(parse_profile("glsl")->language, ShaderLanguage::glsl);
  EXPECT_FALSE(parse_profile("gs_3_0"));  // no geometry shaders before SM4
  EXPECT_FALSE(parse_profile("xs_2_0"));
  EXPECT_FALSE(parse_profile("vs_2"));
}

TEST(ShaderCompiler, D3D9PairCompilesToValidSpirv) {
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(unit(test::kD3D9Effect, ShaderStage::vertex, "VS", "vs_2_0"));
  ASSERT_TRUE(vs.ok) << vs.info_log;
  EXPECT_EQ(vs.entry_point, "VS");
  EXPECT_EQ(test::spirv_val(vs.spirv), "");
  CompiledShader ps = compiler.compile(unit(test::kD3D9Effect, ShaderStage::fragment, "PS", "ps_2_0"));
  ASSERT_TRUE(ps.ok) << ps.info_log;
  EXPECT_EQ(test::spirv_val(ps.spirv), "");
  // Vertex attributes keep their D3D semantics; the POSITION output became the clip position.
  ASSERT_EQ(vs.reflection.inputs.size(), 3u);
  EXPECT_EQ(vs.reflection.inputs[0].semantic, "POSITION");
  EXPECT_EQ(vs.reflection.inputs[1].semantic, "NORMAL");
  EXPECT_EQ(vs.reflection.inputs[2].semantic, "TEXCOORD0");
  EXPECT_EQ(vs.reflection.inputs[2].type.columns, 2);
  for (const InterfaceVariable& out : vs.reflection.outputs) EXPECT_NE(out.semantic, "POSITION");
  EXPECT_EQ(vs.reflection.outputs.size(), 2u);
  // sampler2D + tex2D is a combined image sampler.
  ASSERT_EQ(ps.reflection.images.size(), 1u);
  EXPECT_EQ(ps.reflection.images[0].name, "DiffuseSampler");
  EXPECT_EQ(ps.reflection.images[0].kind, ImageBinding::Kind::combined_image_sampler);
  EXPECT_EQ(ps.reflection.images[0].dim, ImageDim::dim_2d);
  ASSERT_EQ(ps.reflection.outputs.size(), 1u);
  EXPECT_EQ(ps.reflection.outputs[0].location, 0u);
}

TEST(ShaderCompiler, D3D10PairCompilesWithSeparateTextureAndSampler) {
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(unit(test::kD3D10Effect, ShaderStage::vertex, "VS", "vs_4_0"));
  ASSERT_TRUE(vs.ok) << vs.info_log;
  EXPECT_EQ(test::spirv_val(vs.spirv), "");
  CompiledShader ps = compiler.compile(unit(test::kD3D10Effect, ShaderStage::fragment, "PS", "ps_4_0"));
  ASSERT_TRUE(ps.ok) << ps.info_log;
  EXPECT_EQ(test::spirv_val(ps.spirv), "");
  ASSERT_EQ(ps.reflection.images.size(), 2u);
  const ImageBinding* texture = nullptr;
  const ImageBinding* sampler = nullptr;
  for (const ImageBinding& i : ps.reflection.images) (i.name == "Albedo" ? texture : sampler) = &i;
  ASSERT_TRUE(texture && sampler);
  EXPECT_EQ(texture->kind, ImageBinding::Kind::sampled_image);
  EXPECT_EQ(sampler->kind, ImageBinding::Kind::sampler);
  EXPECT_NE(texture->binding, sampler->binding);
  // Two cbuffers in the vertex stage are two blocks with distinct bindings.
  ASSERT_EQ(vs.reflection.uniform_blocks.size(), 2u);
  EXPECT_NE(vs.reflection.uniform_blocks[0].binding, vs.reflection.uniform_blocks[1].binding);
}

TEST(ShaderCompiler, Glsl450CompilesForVulkan10And11) {
  const char* src = R"(#version 450
#extension GL_GOOGLE_cpp_style_line_directive : require
#line 1 "aniso.fx"
layout(set = 0, binding = 0) uniform Globals { mat4 mvp; vec3 light; float gloss; } g;
layout(set = 0, binding = 1) uniform sampler2D lut;
layout(location = 0) in vec3 t;
layout(location = 0) out vec4 color;
void main() { color = texture(lut, vec2(dot(t, g.light), g.gloss)); }
)";
  for (VulkanTarget target : {VulkanTarget::vulkan_1_0, VulkanTarget::vulkan_1_1}) {
    ShaderCompiler compiler({.target = target});
    CompiledShader fs = compiler.compile(unit(src, ShaderStage::fragment, "main", "450", ShaderLanguage::glsl));
    ASSERT_TRUE(fs.ok) << fs.info_log;
    EXPECT_EQ(test::spirv_val(fs.spirv, target == VulkanTarget::vulkan_1_0 ? "vulkan1.0" : "vulkan1.1"), "");
    // SPIR-V version word: 1.0 for Vulkan 1.0, 1.3 for Vulkan 1.1.
    EXPECT_EQ(fs.spirv[1], target == VulkanTarget::vulkan_1_0 ? 0x00010000u : 0x00010300u);
    ASSERT_EQ(fs.reflection.uniform_blocks.size(), 1u);
    EXPECT_EQ(fs.reflection.uniform_blocks[0].binding, 0u);
    ASSERT_EQ(fs.reflection.images.size(), 1u);
    EXPECT_EQ(fs.reflection.images[0].binding, 1u);
    EXPECT_TRUE(fs.reflection.inputs[0].semantic.empty());
  }
}

TEST(ShaderCompiler, ComputeShaderReportsWorkgroupSize) {
  const char* src = R"(RWStructuredBuffer<float> Data;
[numthreads(64, 2, 1)]
void CS(uint3 id : SV_DispatchThreadID) { Data[id.x] = Data[id.x] * 2.0; }
)";
  ShaderCompiler compiler;
  CompiledShader cs = compiler.compile(unit(src, ShaderStage::compute, "CS", "cs_5_0"));
  ASSERT_TRUE(cs.ok) << cs.info_log;
  EXPECT_EQ(test::spirv_val(cs.spirv), "");
  EXPECT_EQ(cs.reflection.local_size[0], 64u);
  EXPECT_EQ(cs.reflection.local_size[1], 2u);
  ASSERT_EQ(cs.reflection.storage_blocks.size(), 1u);
}

TEST(ShaderCompiler, DefinesReachThePreprocessor) {
  const char* src = "float4 PS() : SV_Target { return float4(SCALE, 0, 0, 1); }\n";
  ShaderCompiler compiler;
  TranslationUnit u = unit(src, ShaderStage::fragment, "PS", "ps_4_0");
  EXPECT_FALSE(compiler.compile(u).ok);
  u.defines.push_back({"SCALE", "0.5"});
  CompiledShader ps = compiler.compile(u);
  EXPECT_TRUE(ps.ok) << ps.info_log;
}

TEST(ShaderCompiler, InvalidSpirvFromGlslangBecomesAnError) {
  // A derivative in a vertex shader: glslang accepts it but emits SPIR-V that is invalid there.
  const char* src = "float4 VS(float4 p : POSITION) : POSITION { return ddx(p); }\n";
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", "vs_3_0"));
  EXPECT_FALSE(vs.ok);
  EXPECT_TRUE(vs.spirv.empty());
  EXPECT_NE(test::messages_of(vs).find("SPIR-V"), std::string::npos) << vs.info_log;
}

TEST(ShaderCompiler, LegalizesOnlyShadersThatKeepSamplersInMemory) {
  // spirv-opt's legalization costs ten times the rest of a compile; SPIR-V valid without it
  // skips it. A sampler passed to a function or copied into a local is kept in Function
  // memory, which Vulkan forbids and the validator does not catch: those are legalized.
  const char* direct = "sampler2D S;\nfloat4 PS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(S, uv); }\n";
  const char* by_parameter =
      "sampler2D S;\nfloat4 look(sampler2D t, float2 uv) { return tex2D(t, uv); }\n"
      "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return look(S, uv * 2); }\n";
  const char* local_copy =
      "sampler2D S;\n"
      "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { sampler2D t = S; return tex2D(t, uv); }\n";
  ShaderCompiler compiler;
  for (auto [src, legalized] : {std::pair{direct, false}, {by_parameter, true}, {local_copy, true}}) {
    CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_3_0"));
    ASSERT_TRUE(ps.ok) << src << ps.info_log;
    EXPECT_EQ(ps.legalized, legalized) << src;
    EXPECT_EQ(test::spirv_val(ps.spirv), "") << src;
    // No sampler is left in Function memory, legalized or not: no Function pointer to the
    // sampled image type.
    std::string text = test::spirv_dis(ps.spirv);
    std::smatch type;
    ASSERT_TRUE(std::regex_search(text, type, std::regex("(%\\w+) = OpTypeSampledImage"))) << text;
    EXPECT_EQ(text.find("OpTypePointer Function " + type[1].str() + "\n"), std::string::npos) << src << text;
  }
}

TEST(ShaderCompiler, HlslPackingValidatesForVulkan10) {
  // HLSL packs `float2 b` right after `float a` (offset 4): relaxed block layout, which
  // SPIRV-Tools implies from Vulkan 1.1 on and fxkit's validation must allow for 1.0 too.
  const char* src =
      "cbuffer C { float a; float2 b; };\n"
      "float4 PS() : SV_Target { return float4(b, a, 1); }\n";
  CompileOptions options;
  options.target = VulkanTarget::vulkan_1_0;
  ShaderCompiler compiler(options);
  CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_4_0"));
  ASSERT_TRUE(ps.ok) << ps.info_log;
  EXPECT_EQ(test::spirv_val(ps.spirv, "vulkan1.0 --relax-block-layout"), "");
}

TEST(ShaderCompiler, InoutSvPositionIsTheClipPosition) {
  // XNA/FNA/MonoGame sprite shaders transform the position in place; glslang gives the
  // `inout ... : SV_Position` output a location, so nothing reached the rasterizer.
  const char* src =
      "float4x4 M;\n"
      "void VS(inout float4 color : COLOR0, inout float4 position : SV_Position) {\n"
      "  position = mul(position, M);\n}\n";
  ShaderCompiler compiler;
  for (const char* profile : {"vs_2_0", "vs_4_0_level_9_1", "vs_5_0"}) {
    CompiledShader vs = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", profile));
    ASSERT_TRUE(vs.ok) << profile << vs.info_log;
    EXPECT_NE(test::spirv_dis(vs.spirv).find("BuiltIn Position"), std::string::npos) << profile;
    ASSERT_EQ(vs.reflection.outputs.size(), 1u) << profile;
    EXPECT_EQ(vs.reflection.outputs[0].semantic, "COLOR0");
    EXPECT_EQ(vs.reflection.inputs.size(), 2u) << profile;  // the input side reads the mesh
    EXPECT_EQ(test::spirv_val(vs.spirv), "") << profile;
  }
}

TEST(ShaderCompiler, D3D9SamplersUnderAnSm4ProfileCompile) {
  // fxc's backwards-compatibility mode: D3D9 sampler syntax with ps_4_0_level_9_1 (the
  // MonoGame templates) or ps_4_0. glslang alone wrote SPIR-V sampling a bare image here.
  const char* d3d9 =
      "sampler2D S;\nsamplerCUBE C;\n"
      "float4 PS(float2 uv : TEXCOORD0) : SV_Target { return tex2D(S, uv) + texCUBElod(C, uv.xyxy); }\n";
  // D3D10 syntax with a plain `sampler` must stay separate image and sampler.
  const char* d3d10 =
      "Texture2D<float4> T : register(t0);\nsampler TS : register(s0);\n"
      "float4 PS(float2 uv : TEXCOORD0) : SV_Target { return T.Sample(TS, uv); }\n";
  ShaderCompiler compiler;
  for (const char* src : {d3d9, d3d10})
    for (const char* profile : {"ps_4_0_level_9_1", "ps_4_0", "ps_5_0"}) {
      CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", profile));
      ASSERT_TRUE(ps.ok) << profile << "\n" << src << ps.info_log;
      EXPECT_EQ(test::spirv_val(ps.spirv), "") << profile << "\n" << src;
    }
}

TEST(ShaderCompiler, RejectsMismatchedProfilesWithoutRunningGlslang) {
  ShaderCompiler compiler;
  CompiledShader r = compiler.compile(unit(test::kD3D9Effect, ShaderStage::fragment, "PS", "vs_2_0"));
  EXPECT_FALSE(r.ok);
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_NE(r.messages[0].text.find("vertex profile"), std::string::npos);
  r = compiler.compile(unit("void main() {}", ShaderStage::vertex, "VS", "ps_9_9"));
  EXPECT_FALSE(r.ok);
  r = compiler.compile(unit("void main() {}", ShaderStage::vertex, "VS", "450", ShaderLanguage::glsl));
  EXPECT_FALSE(r.ok);  // GLSL is entered through main
  EXPECT_EQ(compiler.glslang_runs(), 0u);
}

TEST(ShaderCompiler, CompilesFromSeveralThreadsAtOnce) {
  ShaderCompiler compiler;
  std::vector<CompiledShader> results(4);
  std::vector<std::thread> threads;
  for (size_t i = 0; i < results.size(); ++i)
    threads.emplace_back([&, i] {
      results[i] = compiler.compile(unit(i % 2 ? test::kD3D9Effect : test::kD3D10Effect, ShaderStage::fragment, "PS",
                                         i % 2 ? "ps_2_0" : "ps_4_0"));
    });
  for (std::thread& t : threads) t.join();
  for (const CompiledShader& r : results) EXPECT_TRUE(r.ok) << r.info_log;
  EXPECT_EQ(results[1].spirv, results[3].spirv);
  EXPECT_EQ(compiler.glslang_runs(), 4u);
}

}  // namespace
}  // namespace fx
