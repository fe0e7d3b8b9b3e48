// Cross-stage linking: shared descriptor bindings and varyings matched by semantic.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "compile_test_util.h"
#include "fx/compile/program_link.h"

namespace fx {
namespace {

// VS and PS of a source compiled as shader model 4 and linked.
struct LinkedPair {
  CompiledShader vs, ps;
  DiagnosticSink sink;
  bool ok = false;  // both compiled
};
LinkedPair link_sm4(const char* src) {
  ShaderCompiler compiler;
  LinkedPair l;
  l.vs = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", "vs_4_0"));
  l.ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_4_0"));
  l.ok = l.vs.ok && l.ps.ok;
  if (l.ok) link_program({&l.vs, &l.ps}, l.sink);
  return l;
}

TEST(ProgramLink, SameNameGetsTheSameBindingInEveryStage) {
  // Both stages read $Global; only the pixel shader has textures.
  const char* src = R"(float4x4 M;
float4 Tint;
sampler2D A;
sampler2D B;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, M) * Tint; }
float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(B, uv) + tex2D(A, uv.yx) * Tint; }
)";
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", "vs_3_0"));
  CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_3_0"));
  ASSERT_TRUE(vs.ok && ps.ok) << vs.info_log << ps.info_log;
  DiagnosticSink sink;
  ProgramLayout layout = link_program({&ps, &vs}, sink);  // order of the list does not matter
  EXPECT_FALSE(sink.has_errors());
  ASSERT_EQ(layout.bindings.size(), 3u);
  const ProgramBinding* global = layout.find("$Global");
  ASSERT_TRUE(global);
  EXPECT_EQ(global->binding, 0u);
  EXPECT_EQ(global->stage_mask, (1u << unsigned(ShaderStage::vertex)) | (1u << unsigned(ShaderStage::fragment)));
  EXPECT_EQ(layout.find("A")->binding, 1u);  // declaration order within the stage
  EXPECT_EQ(layout.find("B")->binding, 2u);
  EXPECT_EQ(vs.reflection.uniform_blocks[0].binding, 0u);
  EXPECT_EQ(ps.reflection.uniform_blocks[0].binding, 0u);
  for (const ImageBinding& i : ps.reflection.images) EXPECT_EQ(i.binding, layout.find(i.name)->binding);
  EXPECT_EQ(test::spirv_val(vs.spirv), "");
  EXPECT_EQ(test::spirv_val(ps.spirv), "");
  // Linking is deterministic: a second run from fresh compiles gives the same words.
  CompiledShader vs2 = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", "vs_3_0"));
  CompiledShader ps2 = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_3_0"));
  link_program({&vs2, &ps2}, sink);
  EXPECT_EQ(vs2.spirv, vs.spirv);
  EXPECT_EQ(ps2.spirv, ps.spirv);
}

TEST(ProgramLink, VaryingsMatchBySemanticNotDeclarationOrder) {
  // The pixel shader declares its inputs in the opposite order to the vertex outputs,
  // which D3D allows; Vulkan matches by location, so the link step must line them up.
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(test::unit(test::kD3D9Effect, ShaderStage::vertex, "VS", "vs_2_0"));
  CompiledShader ps = compiler.compile(test::unit(test::kD3D9Effect, ShaderStage::fragment, "PS", "ps_2_0"));
  ASSERT_TRUE(vs.ok && ps.ok);
  DiagnosticSink sink;
  link_program({&vs, &ps}, sink);
  EXPECT_EQ(sink.warning_count(), 0u);
  for (const InterfaceVariable& in : ps.reflection.inputs) {
    bool matched = false;
    for (const InterfaceVariable& out : vs.reflection.outputs)
      if (out.semantic == in.semantic) {
        EXPECT_EQ(out.location, in.location) << in.semantic;
        matched = true;
      }
    EXPECT_TRUE(matched) << in.semantic;
  }
  EXPECT_EQ(test::spirv_val(vs.spirv), "");
  EXPECT_EQ(test::spirv_val(ps.spirv), "");
}

TEST(ProgramLink, UnwrittenInputIsAWarning) {
  const char* src = R"(float4 VS(float4 p : POSITION, out float2 uv : TEXCOORD0) : SV_Position { uv = p.xy; return p; }
float4 PS(float2 uv : TEXCOORD0, float4 c : COLOR1) : SV_Target { return c * uv.x; }
)";
  LinkedPair l = link_sm4(src);
  ASSERT_TRUE(l.ok) << l.vs.info_log << l.ps.info_log;
  ASSERT_EQ(l.sink.warning_count(), 1u);
  EXPECT_EQ(l.sink.diagnostics()[0].id, "shader-varying-unwritten");
  EXPECT_NE(l.sink.diagnostics()[0].message.find("COLOR1"), std::string::npos);
}

// Direct3D pads a varying the pixel shader reads wider than the stage before writes it;
// Vulkan calls the missing components an error, so the producer writes them: 0, and 1 in
// w. D3D9's `TEXCOORD0_centroid` is TEXCOORD0. A geometry shader writes them before each
// vertex it emits.
TEST(ProgramLink, NarrowOutputsArePaddedToWhatThePixelShaderReads) {
  const char* src = R"(struct V { float4 p : SV_Position; float2 uv : TEXCOORD0; float k : TEXCOORD1; };
V VS(float4 p : POSITION) { V o; o.p = p; o.uv = p.xy; o.k = p.z; return o; }
[maxvertexcount(3)]
void GS(triangle V input[3], inout TriangleStream<V> s) { for (int i = 0; i < 3; ++i) s.Append(input[i]); }
float4 PS(float4 uv : TEXCOORD0_centroid, float3 k : TEXCOORD1) : SV_Target { return uv + k.xyzz; }
)";
  ShaderCompiler compiler;
  for (bool geometry : {false, true}) {
    CompiledShader vs = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", "vs_4_0"));
    CompiledShader gs = compiler.compile(test::unit(src, ShaderStage::geometry, "GS", "gs_4_0"));
    CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_4_0"));
    ASSERT_TRUE(vs.ok && gs.ok && ps.ok) << vs.info_log << gs.info_log << ps.info_log;
    DiagnosticSink sink;
    std::vector<CompiledShader*> stages{&vs, &ps};
    if (geometry) stages.push_back(&gs);
    link_program(stages, sink);
    EXPECT_EQ(sink.warning_count(), 0u) << "TEXCOORD0_centroid links to TEXCOORD0";
    const CompiledShader& producer = geometry ? gs : vs;
    const std::string text = test::spirv_dis(producer.spirv);
    EXPECT_NE(text.find("Component 2"), std::string::npos) << text;  // uv.zw
    EXPECT_NE(text.find("Component 1"), std::string::npos) << text;  // k.yz
    EXPECT_EQ(test::spirv_val(producer.spirv), "");
  }
}

TEST(ProgramLink, InputsTheCodeNeverReadsStillLinkBySemantic) {
  // spirv-opt drops the semantic of an input the pixel shader never reads (diffuse, fog);
  // the declaration still gives it, so TEXCOORD0 keeps matching the vertex output and the
  // unread, unwritten FOG is no warning.
  const char* src = R"(struct V { float4 pos : POSITION; float4 diffuse : COLOR0; float4 uv : TEXCOORD0; };
V VS(float4 p : POSITION) { V o; o.pos = p; o.diffuse = p; o.uv = p * 2; return o; }
struct P { float4 diffuse : COLOR0; float4 uv : TEXCOORD0; float fog : FOG; };
float4 PS(P i) : COLOR0 { float4 unused = i.diffuse * i.fog; return i.uv; }
)";
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", "vs_3_0"));
  CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_3_0"));
  ASSERT_TRUE(vs.ok && ps.ok) << vs.info_log << ps.info_log;
  // Valid without legalization, the pixel shader skipped it and still loads every input;
  // FOG is not written, so linking legalizes it, which drops the loads it never uses.
  EXPECT_FALSE(ps.legalized);
  DiagnosticSink sink;
  link_program({&vs, &ps}, sink);
  EXPECT_TRUE(ps.legalized);
  EXPECT_EQ(test::spirv_val(ps.spirv), "");
  EXPECT_EQ(sink.warning_count(), 0u);
  uint32_t written = 99, read = 98;
  for (const InterfaceVariable& v : vs.reflection.outputs)
    if (v.semantic == "TEXCOORD0") written = v.location;
  for (const InterfaceVariable& v : ps.reflection.inputs) {
    EXPECT_FALSE(v.semantic.empty()) << v.name;
    if (v.semantic == "TEXCOORD0") read = v.location;
    EXPECT_EQ(!v.unread, v.semantic == "TEXCOORD0") << v.name;
  }
  EXPECT_EQ(read, written);
}

TEST(ProgramLink, SemanticsAreNumberedOnFromTheirIndex) {
  EXPECT_EQ(offset_semantic("TEXCOORD1", 2), "TEXCOORD3");
  EXPECT_EQ(offset_semantic("COLOR", 1), "COLOR1");  // no number: register 0
  EXPECT_EQ(offset_semantic("NORMALS", 0), "NORMALS0");
  EXPECT_EQ(consecutive_semantics("TEXCOORD1", 3), (std::vector<std::string>{"TEXCOORD1", "TEXCOORD2", "TEXCOORD3"}));
  EXPECT_TRUE(consecutive_semantics("TEXCOORD1", 0).empty());
}

TEST(ProgramLink, ArrayVaryingElementsTakeConsecutiveSemanticIndices) {
  // D3D numbers the elements of an array varying on from its semantic's index
  // (float3 n[3] : NORMALS -> NORMALS0, NORMALS1, NORMALS2); glslang flattens the array into
  // one variable per element, each with the array's semantic. Matched by that one name, every
  // element read the last one's location: "conflicting input location" (CubeMapGS).
  const char* src = R"(struct V { float4 p : SV_Position; float3 n[3] : NORMALS; float2 uv : TEXCOORD1; };
V VS(float4 p : POSITION) { V o; o.p = p; o.n[0] = p.xyz; o.n[1] = p.yzx; o.n[2] = p.zxy; o.uv = p.xy; return o; }
float4 PS(V i) : SV_Target { return float4(i.n[0].x, i.n[1].y, i.n[2].z, i.uv.x); }
)";
  LinkedPair l = link_sm4(src);
  ASSERT_TRUE(l.ok) << l.vs.info_log << l.ps.info_log;
  EXPECT_EQ(l.sink.warning_count(), 0u);
  std::vector<std::string> semantics;
  std::set<uint32_t> locations;
  for (const InterfaceVariable& in : l.ps.reflection.inputs) {
    semantics.push_back(in.semantic);
    locations.insert(in.location);
    for (const InterfaceVariable& out : l.vs.reflection.outputs) {
      if (out.semantic == in.semantic) {
        EXPECT_EQ(out.location, in.location) << in.semantic;
      }
    }
  }
  EXPECT_EQ(semantics, (std::vector<std::string>{"NORMALS0", "NORMALS1", "NORMALS2", "TEXCOORD1"}));
  EXPECT_EQ(locations.size(), semantics.size());
  EXPECT_EQ(test::spirv_val(l.vs.spirv), "");
  EXPECT_EQ(test::spirv_val(l.ps.spirv), "");
}

TEST(ProgramLink, D3D9PixelShaderPositionInputIsThePixelPosition) {
  // The vertex shader's output struct as the pixel shader's input: its POSITION is the clip
  // position, a builtin, so no user varying carries it. The pixel shader's float4 POSITION
  // is the pixel's position (SV_Position's meaning from shader model 4 on), not an
  // unwritten input, and the pair links without legalizing anything.
  const char* src = R"(struct V { float4 pos : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION) { V o; o.pos = p; o.uv = p.xy; return o; }
float4 PS(V i) : COLOR0 { return float4(i.uv, 0, 1); }
float4 PSPos(V i) : COLOR0 { return i.pos * 0.001; }
)";
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(test::unit(src, ShaderStage::vertex, "VS", "vs_2_0"));
  for (const char* entry : {"PS", "PSPos"}) {
    CompiledShader ps = compiler.compile(test::unit(src, ShaderStage::fragment, entry, "ps_2_0"));
    ASSERT_TRUE(vs.ok && ps.ok) << vs.info_log << ps.info_log;
    ASSERT_EQ(ps.reflection.inputs.size(), 1u) << entry;
    EXPECT_EQ(ps.reflection.inputs[0].semantic, "TEXCOORD0");
    EXPECT_NE(test::spirv_dis(ps.spirv).find("BuiltIn FragCoord"), std::string::npos) << entry;
    CompiledShader linked_vs = vs;
    DiagnosticSink sink;
    link_program({&linked_vs, &ps}, sink);
    EXPECT_EQ(sink.warning_count(), 0u) << entry;
    EXPECT_FALSE(ps.legalized) << entry;
    EXPECT_EQ(test::spirv_val(ps.spirv), "") << entry;
  }
  // Only a float4 can be the pixel position: a float3 POSITION stays an (unwritten) input.
  const char* narrow = R"(struct V { float4 pos : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION) { V o; o.pos = p; o.uv = p.xy; return o; }
float4 PS(float3 pos : POSITION, float2 uv : TEXCOORD0) : COLOR0 { return float4(pos, uv.x); }
)";
  CompiledShader narrow_vs = compiler.compile(test::unit(narrow, ShaderStage::vertex, "VS", "vs_2_0"));
  CompiledShader narrow_ps = compiler.compile(test::unit(narrow, ShaderStage::fragment, "PS", "ps_2_0"));
  ASSERT_TRUE(narrow_vs.ok && narrow_ps.ok) << narrow_ps.info_log;
  EXPECT_EQ(test::spirv_dis(narrow_ps.spirv).find("BuiltIn FragCoord"), std::string::npos);
  DiagnosticSink sink;
  link_program({&narrow_vs, &narrow_ps}, sink);
  ASSERT_EQ(sink.warning_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "shader-varying-unwritten");
}

TEST(ProgramLink, DifferentBlocksWithOneNameGetTheirOwnBindings) {
  const char* vs_src = "cbuffer C { float4 a; };\nfloat4 VS() : SV_Position { return a; }\n";
  const char* ps_src = "cbuffer C { float4 a; float4 b; };\nfloat4 PS() : SV_Target { return a + b; }\n";
  ShaderCompiler compiler;
  CompiledShader vs = compiler.compile(test::unit(vs_src, ShaderStage::vertex, "VS", "vs_4_0"));
  CompiledShader ps = compiler.compile(test::unit(ps_src, ShaderStage::fragment, "PS", "ps_4_0"));
  ASSERT_TRUE(vs.ok && ps.ok);
  DiagnosticSink sink;
  ProgramLayout layout = link_program({&vs, &ps}, sink);
  ASSERT_EQ(layout.bindings.size(), 2u);
  EXPECT_NE(vs.reflection.uniform_blocks[0].binding, ps.reflection.uniform_blocks[0].binding);
}

}  // namespace
}  // namespace fx
