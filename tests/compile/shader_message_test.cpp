// glslang info logs -> ShaderMessages -> Diagnostics placed in the .fx file via #line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "compile_test_util.h"
#include "fx/diagnostic_render.h"

namespace fx {
namespace {

TEST(InfoLog, ParsesLocationsColumnsAndDropsSummaries) {
  std::vector<ShaderMessage> m = parse_info_log(
      "ERROR: a.fx:12: 'foo' : undeclared identifier \n"
      "WARNING: C:\\fx\\b.fx:3: 'x' : truncation\n"
      "ERROR: a.fx:6: 'declaration' : Expected \n"
      "a.fx(6): error at column 7, HLSL parsing failed.\n"
      "ERROR: Linking fragment stage: Missing entry point: Each stage requires one entry point\n"
      "ERROR: 2 compilation errors.  No code generated.\n");
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[0].file, "a.fx");
  EXPECT_EQ(m[0].line, 12u);
  EXPECT_EQ(m[0].column, 0u);
  EXPECT_EQ(m[0].text, "'foo' : undeclared identifier");
  EXPECT_EQ(m[1].severity, Severity::warning);
  EXPECT_EQ(m[1].file, "C:\\fx\\b.fx");
  EXPECT_EQ(m[1].line, 3u);
  EXPECT_EQ(m[2].column, 7u);  // merged from the HLSL grammar's column line
  EXPECT_EQ(m[3].file, "");
  EXPECT_EQ(m[3].line, 0u);
  EXPECT_NE(m[3].text.find("Missing entry point"), std::string::npos);
}

// The effect file as the user wrote it; the translation unit carries #line directives
// pointing into it, as the effect compiler builds them.
const char* kEffectFile = R"(// broken.fx
float4x4 WorldViewProj;

technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }

float4 VS(float4 p : POSITION) : POSITION {
  return mul(p, WorldViewProj);
}

float4 PS() : COLOR0 {
  float4 c = undefinedColor;
  return c
}
)";

TEST(ShaderDiagnostics, ErrorsMapToEffectFileLinesGolden) {
  std::string tu =
      "#line 2 \"broken.fx\"\nfloat4x4 WorldViewProj;\n#line 6 \"broken.fx\"\n"
      "float4 VS(float4 p : POSITION) : POSITION {\n  return mul(p, WorldViewProj);\n}\n\n"
      "float4 PS() : COLOR0 {\n  float4 c = undefinedColor;\n  return c\n}\n";
  SourceManager sm;
  sm.add_buffer("broken.fx", kEffectFile);
  ShaderCompiler compiler;
  DiagnosticSink sink;
  CompiledShader ps = compile_and_report(compiler, test::unit(tu.c_str(), ShaderStage::fragment, "PS", "ps_2_0"),
                                         resolver_for(sm), sink);
  EXPECT_FALSE(ps.ok);
  EXPECT_TRUE(ps.spirv.empty());
  EXPECT_EQ(render_text(sink.diagnostics(), sm),
            "broken.fx:11:1: error: 'undefinedColor' : unknown variable [shader-compile-error]\n"
            "  float4 c = undefinedColor;\n"
            "^\n"
            // Cascading errors: glslang goes on after the first one.
            "broken.fx:11:1: error: '=' :  cannot convert from ' temp void' to ' temp 4-component vector of float' "
            "[shader-compile-error]\n"
            "  float4 c = undefinedColor;\n"
            "^\n"
            "broken.fx:13:1: error: ';' : Expected [shader-compile-error]\n"
            "}\n"
            "^\n");
  nlohmann::json j = render_json(sink.diagnostics(), sm);
  EXPECT_EQ(j[0]["file"], "broken.fx");
  EXPECT_EQ(j[0]["line"], 11);
  EXPECT_EQ(j[2]["line"], 13);
}

TEST(ShaderDiagnostics, GlslErrorsNameTheEffectFile) {
  const char* tu =
      "#version 450\n#extension GL_GOOGLE_cpp_style_line_directive : require\n"
      "#line 40 \"strand.fx\"\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(missing); }\n";
  ShaderCompiler compiler;
  CompiledShader fs = compiler.compile(test::unit(tu, ShaderStage::fragment, "main", "450", ShaderLanguage::glsl));
  EXPECT_FALSE(fs.ok);
  EXPECT_EQ(test::messages_of(fs), "strand.fx:41:0: 'missing' : undeclared identifier\n");
}

TEST(ShaderDiagnostics, HlslParseFailureCarriesAColumn) {
  const char* tu = "#line 20 \"params.fx\"\nfloat4 PS() : SV_Target { return 1; }\ntexture tex;\n";
  ShaderCompiler compiler;
  CompiledShader ps = compiler.compile(test::unit(tu, ShaderStage::fragment, "PS", "ps_4_0"));
  EXPECT_FALSE(ps.ok);
  ASSERT_FALSE(ps.messages.empty());
  EXPECT_EQ(ps.messages[0].file, "params.fx");
  EXPECT_EQ(ps.messages[0].line, 21u);
  EXPECT_GT(ps.messages[0].column, 0u);
}

TEST(ShaderDiagnostics, UnresolvableLocationsKeepTheGlslangPosition) {
  DiagnosticSink sink;
  report_messages(
      {{Severity::error, "gone.fx", 4, 2, "'x' : bad", {}}, {Severity::error, "", 0, 0, "Linking: oops", {}}}, {},
      sink);
  ASSERT_EQ(sink.diagnostics().size(), 2u);
  EXPECT_EQ(sink.diagnostics()[0].message, "gone.fx:4:2: 'x' : bad");
  EXPECT_EQ(sink.diagnostics()[1].id, "shader-link-error");
}

TEST(ShaderDiagnostics, BrokenShadersGiveDiagnosticsNotCrashes) {
  const char* broken[] = {
      "",
      "float4 PS() : SV_Target {",
      "}}}}",
      "float4 PS() : SV_Target { return tex2D(nothing, 0); }",
      "#line 1 \"x.fx\"\n#error stop here\n",
      "struct S { S s; }; float4 PS() : SV_Target { return 0; }",
      "float4 NotPS() : SV_Target { return 0; }",
      "#if 1\n",
      "\xff\xfe\x00garbage",
  };
  ShaderCompiler compiler;
  for (const char* src : broken) {
    CompiledShader r = compiler.compile(test::unit(src, ShaderStage::fragment, "PS", "ps_4_0"));
    EXPECT_FALSE(r.ok) << src;
    EXPECT_FALSE(r.messages.empty()) << src;
    EXPECT_TRUE(r.spirv.empty());
  }
}

}  // namespace
}  // namespace fx
