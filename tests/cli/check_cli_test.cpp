// `fxkit check` as a user and a CI job run it: exit codes (0 clean, 1 errors, 2 usage or
// I/O), clickable text diagnostics, and the JSON document.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "fxkit_cli.h"

namespace {

using fx::testing::run_fxkit;
namespace fs = std::filesystem;

const std::string kData = std::string(FXKIT_SOURCE_DIR) + "/tests/parser/data/";

// A file in a fresh temporary folder, for includes and broken copies.
std::string write_temp(const std::string& name, const std::string& text) {
  fs::path dir = fs::path(::testing::TempDir()) / ("fxkit_check_cli_" + std::to_string(::getpid()));
  fs::create_directories((dir / name).parent_path());
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

TEST(CheckCli, CleanEffectExitsZeroAndPrintsNothing) {
  auto r = run_fxkit("check " + kData + "sdk_sample.fx", true);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

// A DXSAS Script mistake is a warning at its column inside the annotation's string.
TEST(CheckCli, ScriptMistakeIsLocatedInsideTheString) {
  std::string path = write_temp("script.fx",
                                "float4 PS() : COLOR0 { return 1; }\n"
                                "technique T < string Script = \"Clear=Color; Pass=Bler;\"; > {\n"
                                "  pass Blur { PixelShader = compile ps_2_0 PS(); }\n"
                                "}\n");
  auto r = run_fxkit("check " + path, true);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(path + ":2:50: warning: technique 'T' has no pass 'Bler'; did you mean 'Blur'?"),
            std::string::npos)
      << r.err;
}

TEST(CheckCli, ErrorsExitOneWithFileLineColumnAndCaret) {
  std::string path = write_temp("broken.fx",
                                "float4 Color;\n"
                                "technique T { pass P { CullMod = None; } }\n");
  auto r = run_fxkit("check " + path, true);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(path + ":2:24: error: unknown state 'CullMod' in a pass; did you mean "
                              "'CullMode'? [unknown-state]\n"
                              "technique T { pass P { CullMod = None; } }\n"
                              "                       ^~~~~~~\n"),
            std::string::npos)
      << r.err;
}

// What select and render refuse, check refuses, located alike: the effect model's errors
// (an unknown type, an unsized array its initializer does not fill) were clean in check and
// reached render without a location.
TEST(CheckCli, CheckSelectAndRenderRefuseModelErrorsAtTheSameLocation) {
  const std::string tail =
      "float4 VS(float4 p : POSITION) : SV_Position { return p; }\n"
      "float4 PS() : SV_Target { return 1; }\n"
      "technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); "
      "SetPixelShader(CompileShader(ps_5_0, PS())); } }\n";
  const struct {
    const char* name;
    std::string text, error;
  } cases[] = {
      {"unknown_view.fx", "float4 Tint;\nRWTexture4D<float4> Canvas;\n" + tail,
       ":2:1: error: unknown type 'RWTexture4D'; did you mean 'RWTexture2D'? [unknown-type]"},
      {"unfilled_array.fx", "float2 Offsets[] = { 1, 2, 3 };\n" + tail,
       ":1:1: error: the initializer's 3 values do not fill whole elements of float2 (2 each) [bad-array-size]"},
  };
  for (const auto& c : cases) {
    const std::string path = write_temp(c.name, c.text);
    for (const std::string command : {"check ", "select --caps modern ", "render --out /dev/null "}) {
      auto r = run_fxkit(command + path, true);
      EXPECT_EQ(r.status, 1) << command << path;
      EXPECT_NE(r.err.find(path + c.error), std::string::npos) << command << path << "\n" << r.err;
    }
  }
}

// Unknown names in shader code are the semantic model's findings, located with their
// did-you-mean as the editor and the reload messages show them; a local fxc takes with an
// empty annotation block (`float var < > = 0;`) is a declaration, not a finding.
TEST(CheckCli, UnknownNamesInShaderCodeAreReportedBeforeTheCompiler) {
  const std::string tail =
      "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
      "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
  const std::string broken = write_temp("unknown_name.fx",
                                        "float Gloss = 2;\n"
                                        "struct Light { float3 colour; };\n"
                                        "Light Sun;\n"
                                        "float4 PS() : COLOR { return float4(Sun.color * Glos, 1); }\n" +
                                            tail);
  auto r = run_fxkit("check " + broken, true);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(broken + ":4:41: error: no member named 'color' in 'Light'; did you mean 'colour'? "
                                "[unknown-member]"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(broken + ":4:49: error: use of undeclared identifier 'Glos'; did you mean 'Gloss'? "
                                "[unknown-identifier]"),
            std::string::npos)
      << r.err;
  size_t errors = 0;
  for (size_t at = r.err.find(": error: "); at != std::string::npos; at = r.err.find(": error: ", at + 1)) ++errors;
  EXPECT_EQ(errors, 2u) << "glslang, which would repeat them, did not run: " << r.err;

  const std::string annotated =
      write_temp("annotated_local.fx", "float4 PS() : COLOR { float var < > = 0.5; return var; }\n" + tail);
  r = run_fxkit("check " + annotated, true);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

#ifdef FXKIT_COMPILE_WORKER_BINARY
// A glslang crash, forced by a worker that aborts on a marker in the unit (through a
// wrapper named by FXKIT_COMPILE_WORKER, as a user points fxkit at another worker), is a
// located error on that shader; the replaced worker goes on to the next file.
TEST(CheckCli, ACompilerCrashIsALocatedErrorAndTheNextFileIsStillChecked) {
  std::string crash = write_temp("crash/a.fx",
                                 "float FXKIT_TEST_CRASH = 1;\n"
                                 "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                                 "float4 PS() : COLOR { return FXKIT_TEST_CRASH; }\n"
                                 "technique T { pass P { VertexShader = compile vs_3_0 VS();\n"
                                 "  PixelShader = compile ps_3_0 PS(); } }\n");
  write_temp("crash/b.fx",
             "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
             "float4 PS() : COLOR { return float3(1, 2).xyzz; }\n"
             "technique T { pass P { VertexShader = compile vs_3_0 VS();\n"
             "  PixelShader = compile ps_3_0 PS(); } }\n");
  std::string wrapper = write_temp("crash-worker.sh", std::string("#!/bin/sh\nexec ") + FXKIT_COMPILE_WORKER_BINARY +
                                                          " \"$@\" --abort-on FXKIT_TEST_CRASH\n");
  fs::permissions(wrapper, fs::perms::owner_all);
  std::string folder = fs::path(crash).parent_path().string();
  ::setenv("FXKIT_COMPILE_WORKER", wrapper.c_str(), 1);
  auto r = run_fxkit("check --jobs 1 " + folder, true);
  ::unsetenv("FXKIT_COMPILE_WORKER");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(crash + ":3:8: error: the shader compiler (glslang) was killed by signal 6"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("[compiler-crashed]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("b.fx:2:"), std::string::npos) << "b.fx is compiled after the crash: " << r.err;
}
#endif

// The case: a one-letter typo in a vertex shader. `check` compiles the shaders by
// default, so it fails, once, at the token's column, naming the declared parameter; the
// pixel shader, which does not call the function, adds nothing.
TEST(CheckCli, ShaderTypoIsOneErrorAtItsColumnWithDidYouMean) {
#ifndef FXKIT_CLI_COMPILES
  GTEST_SKIP() << "a parser-only build has no shader compiler";
#endif
  std::string path = write_temp("typo.fx",
                                "float4x4 WorldViewProj : WORLDVIEWPROJECTION;\n"
                                "float4 Color = {1, 0, 0, 1};\n"
                                "float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjj); }\n"
                                "float4 PS() : COLOR { return Color; }\n"
                                "technique T { pass P {\n"
                                "  VertexShader = compile vs_2_0 VS();\n"
                                "  PixelShader = compile ps_2_0 PS();\n"
                                "} }\n");
  for (std::string flags : {"", "--compile ", "--jobs 1 ", "--jobs 2 "}) {
    auto r = run_fxkit("check " + flags + path, true);
    EXPECT_EQ(r.status, 1) << flags << r.err;
    EXPECT_NE(r.err.find(path + ":3:59: error: use of undeclared identifier 'WorldViewProjj'; did you mean "
                                "'WorldViewProj'? [unknown-identifier]"),
              std::string::npos)
        << flags << r.err;
    size_t errors = 0;
    for (size_t at = r.err.find("error:"); at != std::string::npos; at = r.err.find("error:", at + 1)) ++errors;
    EXPECT_EQ(errors, 1u) << flags << r.err;
    EXPECT_NE(r.err.find("0 clean, 0 warnings, 1 error"), std::string::npos) << r.err;
  }
  // The semantic model finds it before glslang runs, so the front end alone finds it too.
  auto fast = run_fxkit("check --syntax-only " + path, true);
  EXPECT_EQ(fast.status, 1) << fast.err;
  EXPECT_NE(fast.err.find(path + ":3:59: error: use of undeclared identifier 'WorldViewProjj'"), std::string::npos)
      << fast.err;
  EXPECT_EQ(run_fxkit("check --syntax-only --compile " + path).status, 2);
}

TEST(CheckCli, IncludeDirsDefinesAndIncludeNotes) {
  std::string header = write_temp("lights.fxh", "#ifndef LIGHTS\n#error LIGHTS must be defined\n#endif\n");
  std::string main = write_temp("main.fx", "#include \"lights.fxh\"\ntechnique T { pass P {} }\n");
  auto missing = run_fxkit("check " + main, true);
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("lights.fxh:2:1: error: LIGHTS must be defined [error-directive]"), std::string::npos)
      << missing.err;
  EXPECT_NE(missing.err.find("main.fx:1:1: note: included from here"), std::string::npos) << missing.err;
  EXPECT_EQ(run_fxkit("check -D LIGHTS=4 " + main).status, 0);
}

// -I and -D take one value each, as in fxc and clang: FILE may come after them, options
// after FILE, and the value may be attached (-IDIR, -DNAME=V).
TEST(CheckCli, IncludeAndDefineTakeOneValueEach) {
  std::string header = write_temp("inc/both.fxh", "");
  fs::path inc = fs::path(header).parent_path();
  std::string main = write_temp("needs.fx",
                                "#include \"both.fxh\"\n#if !defined(A) || B != 2\n#error A and B=2 needed\n#endif\n"
                                "technique T { pass P {} }\n");
  std::vector<std::string> commands = {"check -I " + inc.string() + " -D A -D B=2 " + main + " --json",
                                       "check -I" + inc.string() + " -DA -DB=2 " + main,
                                       "check " + main + " -I " + inc.string() + " -D A -D B=2"};
#ifdef FXKIT_CLI_COMPILES  // info and compile need the runtime
  commands.push_back("info -I " + inc.string() + " -D A -D B=2 " + main + " --json");
  commands.push_back("compile -I " + inc.string() + " -D A -D B=2 " + main + " --json");
#endif
  for (const std::string& args : commands) {
    auto r = run_fxkit(args, true);
    EXPECT_NE(r.status, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find("error"), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_EQ(run_fxkit("check -I " + inc.string() + " -D A " + main).status, 1);
}

TEST(CheckCli, WerrorTurnsWarningsIntoFailures) {
  std::string path = write_temp("dup.fx", "technique T { pass P { ZEnable = TRUE; ZEnable = FALSE; } }\n");
  EXPECT_EQ(run_fxkit("check " + path).status, 0);
  EXPECT_EQ(run_fxkit("check --werror " + path).status, 1);
}

TEST(CheckCli, JsonHasDiagnosticsAndASummary) {
  std::string path =
      write_temp("json.fx",
                 "float4 Diffuse : DIFFUSE < string UIName = \"Diffuse\"; >;\n"
                 "technique T < string Scheme = \"quality\"; > { pass P0 { ZEnable = Maybe; } pass P1 {} }\n");
  auto r = run_fxkit("check --json " + path);
  EXPECT_EQ(r.status, 1);
  nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << r.out;
  ASSERT_EQ(j["diagnostics"].size(), 1u) << r.out;
  const auto& d = j["diagnostics"][0];
  EXPECT_EQ(d["file"], path);
  EXPECT_EQ(d["line"], 2);
  EXPECT_EQ(d["severity"], "error");
  EXPECT_EQ(d["id"], "unknown-state-value");
  EXPECT_TRUE(d["end"].is_object());
  EXPECT_TRUE(d["notes"].is_array());
  ASSERT_EQ(j["effects"].size(), 1u);
  const auto& e = j["effects"][0];
  EXPECT_EQ(e["parameters"][0]["name"], "Diffuse");
  EXPECT_EQ(e["parameters"][0]["semantic"], "DIFFUSE");
  EXPECT_EQ(e["techniques"][0]["name"], "T");
  EXPECT_EQ(e["techniques"][0]["passes"].size(), 2u);
  EXPECT_EQ(j["errors"], 1);
}

TEST(CheckCli, JsonSurvivesInvalidUtf8InTheEffect) {
  // Found by the fuzzer: a message quoting bytes that are not UTF-8 (then a state name;
  // stray bytes are now reported once by the lexer and dropped, so an #error quotes them).
  std::string path = write_temp("latin1.fx", "#error Pi\x91\x9alShader\ntechnique T { pass P { } }\n");
  auto r = run_fxkit("check --json " + path);
  EXPECT_EQ(r.status, 1);
  nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << r.out;
  bool replaced = false;  // the quoted bytes come out as U+FFFD
  for (const auto& d : j["diagnostics"])
    replaced = replaced || d["message"].get<std::string>().find("\xEF\xBF\xBD") != std::string::npos;
  EXPECT_TRUE(replaced) << r.out;
}

TEST(CheckCli, UsageAndIoErrorsExitTwo) {
  EXPECT_EQ(run_fxkit("check").status, 2);
  EXPECT_EQ(run_fxkit("check /nonexistent/effect.fx").status, 2);
  EXPECT_EQ(run_fxkit("check --profile fx_9_9 " + kData + "sdk_sample.fx").status, 2);
  EXPECT_EQ(run_fxkit("frobnicate").status, 2);
}

// Every shader of the seed listings compiles (check compiles by default); their assembly
// and fixed-function passes run through the legacy path, so `check` does not report them.
TEST(CheckCli, EverySeedListingChecksClean) {
  for (const char* name : {"brdf.fx", "wood.fx", "state_snippets.fx", "sdk_sample.fx"}) {
    auto r = run_fxkit(std::string("check ") + kData + name, true);
    EXPECT_EQ(r.status, 0) << name << "\n" << r.err;
    EXPECT_EQ(r.err.find("error:"), std::string::npos) << name << "\n" << r.err;
    EXPECT_EQ(r.err.find("shader-not-compiled"), std::string::npos) << name << "\n" << r.err;
  }
  auto effects =
      run_fxkit("check -I " + std::string(FXKIT_SOURCE_DIR) + "/effects " + FXKIT_SOURCE_DIR + "/effects", true);
  EXPECT_EQ(effects.status, 0) << effects.err;
  EXPECT_NE(effects.err.find(", 0 errors"), std::string::npos) << effects.err;
}

}  // namespace
