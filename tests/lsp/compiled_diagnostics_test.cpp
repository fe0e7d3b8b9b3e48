// Compiled-shader diagnostics in the language server, with glslang in a real compile
// worker: a shader error appears once its compile ends, with "also reported for" the other
// passes that compile it, goes away after the fix, and the compile of an outdated text never
// overwrites newer diagnostics; technique validity per caps profile as code lenses. Driven
// by the scheduler's events, never by the clock.
#include <gtest/gtest.h>

#include "compile_events.h"
#include "effect_folder.h"
#include "fx/compile/compile_workers.h"
#include "lsp_session.h"
#include "shader_check.h"

namespace {

using fx::testing::CompileEvents;
using fx::testing::LspSession;
using fx::tools::lsp::CompileScheduler;
using fx::tools::lsp::CompileSnapshot;
using nlohmann::json;

constexpr const char* kEffect = R"(float4x4 WorldViewProj : WORLDVIEWPROJECTION;
texture Diffuse;
sampler2D DiffuseSampler = sampler_state { Texture = <Diffuse>; MinFilter = Linear; };
struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; };
VSOut VS(float4 p : POSITION, float2 uv : TEXCOORD0) {
  VSOut o;
  o.pos = mul(p, WorldViewProj);
  o.uv = uv;
  return o;
}
float4 PS(VSOut i) : COLOR {
  return tex2D(DiffuseSampler, i.uv);
}
technique Main {
  pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); }
}
technique Again {
  pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); }
}
)";

class CompiledDiagnosticsTest : public ::testing::Test {
 protected:
  CompiledDiagnosticsTest() : folder_("lsp_compiled") {
    std::string error;
    check_ = std::make_unique<fx::tools::lsp::ShaderCheck>(fx::CompileWorkers::start({.workers = 1}, error));
    EXPECT_EQ(error, "");
    folder_.write("main.fx", kEffect);
    initialized_ = session_.initialize(
        {}, folder_.path(),
        {{"window", {{"workDoneProgress", true}}}, {"workspace", {{"codeLens", {{"refreshSupport", true}}}}}});
  }
  std::string main() const { return folder_.path("main.fx"); }
  // Removes `, i.uv` from the tex2D call of PS (line 11): a call glslang has no overload for.
  void break_the_call(int version) { session_.change(main(), version, 11, 29, 11, 35, ""); }
  void fix_the_call(int version) { session_.change(main(), version, 11, 29, 11, 29, ", i.uv"); }

  fx::testing::EffectFolder folder_;
  CompileEvents events_;
  std::unique_ptr<fx::tools::lsp::ShaderCheck> check_;
  CompileScheduler scheduler_{[this](const CompileSnapshot& s) {
                                events_.started(s.generation);
                                return check_->check(s);
                              },
                              std::chrono::milliseconds(0), [this] { events_.ready(); }};
  LspSession session_{&scheduler_};
  json initialized_;  // the server's reply to initialize
};

TEST_F(CompiledDiagnosticsTest, ShaderErrorAppearsAfterTheCompileAndGoesAfterTheFix) {
  session_.open(main(), kEffect);
  EXPECT_TRUE(session_.diagnostics(main()).empty());  // the front end's, at once
  events_.wait_ready(1);
  EXPECT_TRUE(session_.diagnostics(main()).empty());  // the compile found nothing either

  break_the_call(2);
  EXPECT_TRUE(session_.diagnostics(main()).empty());  // the front end and semantic model see no problem
  events_.wait_ready(2);
  json d = session_.diagnostics(main());
  ASSERT_EQ(d.size(), 1u) << d.dump(1);
  EXPECT_EQ(d[0]["severity"], 1);
  EXPECT_EQ(d[0]["range"]["start"]["line"], 11);
  EXPECT_NE(d[0]["message"].get<std::string>().find("tex2D"), std::string::npos) << d[0].dump();
  ASSERT_TRUE(d[0].contains("relatedInformation")) << d[0].dump();
  EXPECT_NE(d[0]["relatedInformation"].back()["message"].get<std::string>().find("also reported for Again.P0"),
            std::string::npos)
      << d[0].dump();
  EXPECT_EQ(session_.publications(main()).back()["version"], 2);

  fix_the_call(3);
  session_.diagnostics(main());
  events_.wait_ready(3);
  EXPECT_TRUE(session_.diagnostics(main()).empty());

  // Progress: one begin and one end per compile, on the server-created token.
  size_t begins = 0, ends = 0, creates = 0;
  for (const json& m : session_.sent()) {
    if (m.value("method", "") == "window/workDoneProgress/create") ++creates;
    if (m.value("method", "") != "$/progress") continue;
    const std::string kind = m["params"]["value"]["kind"];
    begins += kind == "begin";
    ends += kind == "end";
  }
  EXPECT_EQ(creates, 3u);
  EXPECT_EQ(begins, 3u);
  EXPECT_EQ(ends, 3u);
}

TEST_F(CompiledDiagnosticsTest, OutdatedCompileNeverOverwritesNewerDiagnostics) {
  session_.open(main(), kEffect);
  session_.diagnostics(main());
  events_.wait_ready(1);
  session_.diagnostics(main());
  events_.hold(2);
  break_the_call(2);
  session_.diagnostics(main());  // schedules the compile of the broken text (generation 2)
  events_.wait_started(2);
  fix_the_call(3);
  session_.diagnostics(main());  // the fixed text (generation 3) waits behind it
  events_.release(2);            // the broken text's compile ends after the fix
  events_.wait_ready(2);         // the fixed text's result; the broken one was thrown away
  EXPECT_TRUE(session_.diagnostics(main()).empty());
  for (const json& p : session_.publications(main())) EXPECT_TRUE(p["diagnostics"].empty()) << p.dump(1);
  EXPECT_EQ(scheduler_.stats().discarded, 1u);
}

TEST_F(CompiledDiagnosticsTest, TechniqueValidityPerCapsProfileAsCodeLenses) {
  session_.open(main(), kEffect);
  session_.diagnostics(main());
  events_.wait_ready(1);
  session_.diagnostics(main());
  const json document = {{"textDocument", {{"uri", fx::tools::lsp::path_to_uri(main())}}}};
  json lenses = session_.request("textDocument/codeLens", document)["result"];
  ASSERT_EQ(lenses.size(), 2u) << lenses.dump(1);
  EXPECT_EQ(lenses[0]["range"]["start"]["line"], 13);  // technique Main
  EXPECT_EQ(lenses[1]["range"]["start"]["line"], 16);  // technique Again
  EXPECT_EQ(lenses[0]["command"]["title"], "valid on dx9, modern; dx8: vs_2_0 not supported on dx8");
  size_t refreshes = 0;
  for (const json& m : session_.sent()) refreshes += m.value("method", "") == "workspace/codeLens/refresh";
  EXPECT_EQ(refreshes, 1u);
  // Once the text changes, the lenses wait for its compile.
  break_the_call(2);
  session_.diagnostics(main());
  EXPECT_TRUE(session_.request("textDocument/codeLens", document)["result"].empty());
  events_.wait_ready(2);
  session_.diagnostics(main());
  lenses = session_.request("textDocument/codeLens", document)["result"];
  ASSERT_EQ(lenses.size(), 2u) << lenses.dump(1);
  EXPECT_EQ(lenses[0]["command"]["title"].get<std::string>().rfind("valid on none", 0), 0u) << lenses.dump(1);
}

// A lens's command is one the server announces and runs: VS Code and Neovim run a clicked
// lens's command through workspace/executeCommand, and the server shows every caps
// profile's verdict with all its reasons.
TEST_F(CompiledDiagnosticsTest, ATechniqueLensCommandShowsEveryProfilesReasons) {
  EXPECT_EQ(initialized_["result"]["capabilities"]["executeCommandProvider"]["commands"],
            json::array({fx::tools::lsp::kTechniqueValidityCommand}))
      << initialized_.dump(1);
  session_.open(main(), kEffect);
  session_.diagnostics(main());
  events_.wait_ready(1);
  session_.diagnostics(main());
  const json document = {{"textDocument", {{"uri", fx::tools::lsp::path_to_uri(main())}}}};
  const json lenses = session_.request("textDocument/codeLens", document)["result"];
  ASSERT_EQ(lenses.size(), 2u) << lenses.dump(1);
  const json& command = lenses[0]["command"];
  EXPECT_EQ(command["command"], fx::tools::lsp::kTechniqueValidityCommand);
  const size_t before = session_.sent().size();
  const json reply = session_.request("workspace/executeCommand",
                                      {{"command", command["command"]}, {"arguments", command["arguments"]}});
  EXPECT_TRUE(reply.contains("result") && reply["result"].is_null()) << reply.dump(1);
  std::string shown;
  for (size_t i = before; i < session_.sent().size(); ++i)
    if (session_.sent()[i].value("method", "") == "window/showMessage")
      shown = session_.sent()[i]["params"]["message"].get<std::string>();
  EXPECT_EQ(shown.rfind("technique 'Main'\n", 0), 0u) << shown;
  EXPECT_NE(shown.find("\ndx9: valid\n"), std::string::npos) << shown;
  EXPECT_NE(shown.find("\ndx8: invalid\n  vs_2_0 not supported on dx8"), std::string::npos) << shown;
  EXPECT_NE(shown.find("\nmodern: valid"), std::string::npos) << shown;
  const json unknown = session_.request("workspace/executeCommand", {{"command", "fxkit.noSuchCommand"}});
  EXPECT_EQ(unknown["error"]["code"], -32602) << unknown.dump(1);
}

// The compile reads what the editor holds, as the front end does: an include open with
// unsaved text is compiled in place of the file on disk (the snapshot built through
// fx::EffectFile with the open buffers as its file loader).
TEST_F(CompiledDiagnosticsTest, TheCompileReadsIncludesFromTheOpenBuffers) {
  const std::string effect =
      "#include \"tint.fxh\"\n"
      "float4 PS(float4 c : COLOR0) : COLOR { return float4(tint(c.rgb), 1); }\n"
      "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
  folder_.write("tint.fxh", "float3 tint(float3 c) { return c * 0.5; }\n");
  folder_.write("lit.fx", effect);
  const std::string lit = folder_.path("lit.fx");
  session_.open(folder_.path("tint.fxh"), "float3 tint(float3 c) { return float3(c.xy); }\n");
  session_.open(lit, effect);
  EXPECT_TRUE(session_.diagnostics(lit).empty());  // the front end and semantic model see no problem
  events_.wait_ready(2);                           // the header's compile and the effect's
  const json d = session_.diagnostics(lit);
  ASSERT_EQ(d.size(), 1u) << d.dump(1);
  EXPECT_EQ(d[0]["range"]["start"]["line"], 0);  // on the #include line
  EXPECT_EQ(d[0]["message"].get<std::string>().rfind("in included file tint.fxh: ", 0), 0u) << d.dump(1);
  EXPECT_EQ(d[0]["relatedInformation"][0]["location"]["uri"], fx::tools::lsp::path_to_uri(folder_.path("tint.fxh")));
}

}  // namespace
