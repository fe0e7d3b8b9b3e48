// The language server per request, driven in-process: initialize and its capabilities,
// text sync, diagnostics (front end and semantic model, includes), hover, definition,
// references, code actions, document symbols, completion, cancellation, configuration, shutdown and exit.
#include "language_server.h"

#include <gtest/gtest.h>

#include "effect_folder.h"
#include "lsp_session.h"

namespace {

using fx::testing::has;
using fx::testing::labels;
using fx::testing::LspSession;
using nlohmann::json;

constexpr const char* kEffect = R"(#include "lights.fxh"
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
float Gloss : SPECULARPOWER < float UIMin = 1; float UIMax = 128; > = 20;
texture Diffuse;
sampler2D DiffuseSampler = sampler_state { Texture = <Diffuse>; MinFilter = Linear; AddressU = Wrap; };
struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; float3 n : TEXCOORD1; };
VSOut VS(float4 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0) {
  VSOut o = (VSOut)0;
  o.pos = mul(p, WorldViewProj);
  o.uv = uv;
  o.n = n;
  return o;
}
float4 PS(VSOut i) : COLOR {
  float d = saturate(dot(normalize(i.n), -SunDirection));
  return tex2D(DiffuseSampler, i.uv) * d + pow(d, Gloss);
}
technique Main {
  pass P0 {
    VertexShader = compile vs_2_0 VS();
    PixelShader = compile ps_2_0 PS();
    CullMode = CCW;
  }
}
)";

class LanguageServerTest : public ::testing::Test {
 protected:
  LanguageServerTest() : folder_("lsp_server") {
    folder_.write("lights.fxh", "// lights\nfloat3 SunDirection = {0, -1, 0};\n");
    folder_.write("main.fx", kEffect);
  }
  std::string path(const std::string& name) const { return folder_.path(name); }
  void open_main() {
    session_.initialize({}, folder_.path());
    session_.open(path("main.fx"), kEffect);
  }

  fx::testing::EffectFolder folder_;
  LspSession session_;
};

TEST_F(LanguageServerTest, InitializeAnnouncesCapabilities) {
  json reply = session_.initialize();
  const json& caps = reply["result"]["capabilities"];
  EXPECT_EQ(caps["textDocumentSync"]["change"], 2);  // incremental
  EXPECT_TRUE(caps["hoverProvider"].get<bool>());
  EXPECT_TRUE(caps["definitionProvider"].get<bool>());
  EXPECT_TRUE(caps["referencesProvider"].get<bool>());
  EXPECT_EQ(caps["codeActionProvider"]["codeActionKinds"][0], "quickfix");
  EXPECT_TRUE(caps["documentSymbolProvider"].get<bool>());
  EXPECT_TRUE(caps["completionProvider"].is_object());
}

TEST_F(LanguageServerTest, RequestsBeforeInitializeAreRefused) {
  json reply = session_.request("textDocument/hover", json::object());
  EXPECT_EQ(reply["error"]["code"], -32002);
}

TEST_F(LanguageServerTest, CleanEffectPublishesNoDiagnostics) {
  open_main();
  json d = session_.diagnostics(path("main.fx"));
  ASSERT_TRUE(d.is_array());
  EXPECT_TRUE(d.empty()) << d.dump(1);
}

TEST_F(LanguageServerTest, IncrementalEditsGetSemanticAndFrontEndDiagnostics) {
  open_main();
  ASSERT_TRUE(session_.diagnostics(path("main.fx")).empty());
  // Line 14: `  float d = saturate(...)`; line 15 `return tex2D(...) * d + pow(d, Gloss);`.
  // Rename the use of Gloss to Glos: an unknown identifier with a did-you-mean.
  session_.change(path("main.fx"), 2, 15, 50, 15, 55, "Glos");
  json d = session_.diagnostics(path("main.fx"));
  ASSERT_EQ(d.size(), 1u) << d.dump(1);
  EXPECT_EQ(d[0]["code"], "unknown-identifier");
  EXPECT_EQ(d[0]["message"], "use of undeclared identifier 'Glos'; did you mean 'Gloss'?");
  EXPECT_EQ(d[0]["range"]["start"]["line"], 15);
  EXPECT_EQ(d[0]["range"]["start"]["character"], 50);
  EXPECT_EQ(d[0]["relatedInformation"][0]["location"]["range"]["start"]["line"], 2);  // Gloss is declared here
  // A state value typo: the front end's diagnostic.
  session_.change(path("main.fx"), 3, 21, 15, 21, 18, "CWW");
  d = session_.diagnostics(path("main.fx"));
  ASSERT_EQ(d.size(), 2u) << d.dump(1);
  EXPECT_EQ(d[0]["code"], "unknown-state-value");
  // Undo both: no diagnostics left, none stale.
  session_.change(path("main.fx"), 4, 15, 50, 15, 54, "Gloss");
  session_.change(path("main.fx"), 5, 21, 15, 21, 18, "CCW");
  EXPECT_TRUE(session_.diagnostics(path("main.fx")).empty());
}

TEST_F(LanguageServerTest, DiagnosticsInAnIncludeSitOnTheIncludeLine) {
  folder_.write("lights.fxh", "// lights\nfloat3 SunDirection = {0, -1, 0}\nfloat x;\n");  // no `;`
  open_main();
  json d = session_.diagnostics(path("main.fx"));
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d[0]["range"]["start"]["line"], 0);
  EXPECT_NE(d[0]["message"].get<std::string>().find("in included file lights.fxh: "), std::string::npos);
  const json& related = d[0]["relatedInformation"][0];
  EXPECT_EQ(related["location"]["uri"], fx::tools::lsp::path_to_uri(path("lights.fxh")));
  EXPECT_GE(related["location"]["range"]["start"]["line"], 1);
}

TEST_F(LanguageServerTest, OpenIncludeOverridesTheDisk) {
  open_main();
  session_.open(path("lights.fxh"), "float3 SunDirections = {0, -1, 0};\n");
  json d = session_.diagnostics(path("main.fx"));
  ASSERT_EQ(d.size(), 1u) << d.dump(1);
  EXPECT_EQ(d[0]["message"], "use of undeclared identifier 'SunDirection'; did you mean 'SunDirections'?");
}

TEST_F(LanguageServerTest, HoverOnParameterStateAndIntrinsic) {
  open_main();
  json h = session_.at("textDocument/hover", path("main.fx"), 15, 52);  // Gloss in PS
  ASSERT_TRUE(h.is_object());
  std::string text = h["contents"]["value"];
  EXPECT_NE(text.find("float Gloss : SPECULARPOWER"), std::string::npos) << text;
  EXPECT_NE(text.find("- semantic: `SPECULARPOWER`"), std::string::npos) << text;
  EXPECT_NE(text.find("- default: `20`"), std::string::npos) << text;
  EXPECT_NE(text.find("- annotation: `float UIMin = 1`"), std::string::npos) << text;
  text = session_.at("textDocument/hover", path("main.fx"), 21, 6)["contents"]["value"];  // CullMode
  EXPECT_NE(text.find("**CullMode**"), std::string::npos) << text;
  EXPECT_NE(text.find("allowed values: "), std::string::npos) << text;
  EXPECT_NE(text.find("CCW"), std::string::npos) << text;
  text = session_.at("textDocument/hover", path("main.fx"), 14, 14)["contents"]["value"];  // saturate
  EXPECT_NE(text.find("T saturate(T x)"), std::string::npos) << text;
  text = session_.at("textDocument/hover", path("main.fx"), 10, 5)["contents"]["value"];  // o.n
  EXPECT_NE(text.find("float3 n (member of VSOut)"), std::string::npos) << text;
  EXPECT_TRUE(session_.at("textDocument/hover", path("main.fx"), 1, 0).is_null() ||
              session_.at("textDocument/hover", path("main.fx"), 1, 0).is_object());
}

TEST_F(LanguageServerTest, DefinitionAcrossIncludesAndFromPasses) {
  open_main();
  json loc = session_.at("textDocument/definition", path("main.fx"), 14, 50);  // SunDirection
  ASSERT_TRUE(loc.is_object());
  EXPECT_EQ(loc["uri"], fx::tools::lsp::path_to_uri(path("lights.fxh")));
  EXPECT_EQ(loc["range"]["start"]["line"], 1);
  EXPECT_EQ(loc["range"]["start"]["character"], 7);
  loc = session_.at("textDocument/definition", path("main.fx"), 19, 35);  // compile vs_2_0 VS()
  EXPECT_EQ(loc["uri"], fx::tools::lsp::path_to_uri(path("main.fx")));
  EXPECT_EQ(loc["range"]["start"]["line"], 6);
  loc = session_.at("textDocument/definition", path("main.fx"), 10, 4);  // o.n -> the member
  EXPECT_EQ(loc["range"]["start"]["line"], 5);
  loc = session_.at("textDocument/definition", path("main.fx"), 0, 12);  // #include
  EXPECT_EQ(loc["uri"], fx::tools::lsp::path_to_uri(path("lights.fxh")));
}

// "line:character" of each location of a references result, in order.
std::vector<std::string> places(const json& locations) {
  std::vector<std::string> out;
  for (const json& l : locations)
    out.push_back(std::to_string(l["range"]["start"]["line"].get<int>()) + ":" +
                  std::to_string(l["range"]["start"]["character"].get<int>()));
  return out;
}

TEST_F(LanguageServerTest, ReferencesFromBodiesPassesAndStateBlocks) {
  open_main();
  const std::string uri = fx::tools::lsp::path_to_uri(path("main.fx"));
  auto refs = [&](int line, int character, bool declaration) {
    json reply = session_.request("textDocument/references", {{"textDocument", {{"uri", uri}}},
                                                              {"position", {{"line", line}, {"character", character}}},
                                                              {"context", {{"includeDeclaration", declaration}}}});
    EXPECT_TRUE(reply.contains("result")) << reply.dump();
    return reply.value("result", json::array());
  };
  EXPECT_EQ(places(refs(13, 7, true)), (std::vector<std::string>{"13:7", "20:33"}));  // PS: the pass names it
  EXPECT_EQ(places(refs(20, 33, false)), (std::vector<std::string>{"20:33"}));
  EXPECT_EQ(places(refs(3, 8, true)), (std::vector<std::string>{"3:8", "4:54"}));              // Diffuse: <Diffuse>
  EXPECT_EQ(places(refs(14, 8, true)), (std::vector<std::string>{"14:8", "15:39", "15:47"}));  // the local d
  json sun = refs(14, 50, true);  // declared in the include
  ASSERT_EQ(sun.size(), 2u) << sun.dump(1);
  EXPECT_EQ(sun[0]["uri"], fx::tools::lsp::path_to_uri(path("lights.fxh")));
  EXPECT_EQ(sun[1]["uri"], uri);
}

TEST_F(LanguageServerTest, CodeActionsOfferTheFixIts) {
  open_main();
  const std::string uri = fx::tools::lsp::path_to_uri(path("main.fx"));
  auto actions = [&](int line, int from, int to) {
    json reply = session_.request(
        "textDocument/codeAction",
        {{"textDocument", {{"uri", uri}}},
         {"range", {{"start", {{"line", line}, {"character", from}}}, {"end", {{"line", line}, {"character", to}}}}},
         {"context", {{"diagnostics", json::array()}}}});
    EXPECT_TRUE(reply.contains("result")) << reply.dump();
    return reply.value("result", json::array());
  };
  EXPECT_TRUE(actions(15, 50, 55).empty());
  session_.change(path("main.fx"), 2, 15, 50, 15, 55, "Glos");  // did you mean 'Gloss'?
  json a = actions(15, 52, 52);
  ASSERT_EQ(a.size(), 1u) << a.dump(1);
  EXPECT_EQ(a[0]["title"], "Change to 'Gloss'");
  EXPECT_EQ(a[0]["kind"], "quickfix");
  EXPECT_EQ(a[0]["diagnostics"][0]["code"], "unknown-identifier");
  const json& edit = a[0]["edit"]["changes"][uri][0];
  EXPECT_EQ(edit["newText"], "Gloss");
  EXPECT_EQ(edit["range"]["start"]["character"], 50);
  EXPECT_EQ(edit["range"]["end"]["character"], 54);
  EXPECT_TRUE(actions(3, 0, 5).empty());                  // nothing to fix there
  session_.change(path("main.fx"), 3, 1, 44, 1, 45, "");  // `float4x4 WorldViewProj : WORLDVIEWPROJECTION`
  a = actions(1, 0, 44);
  ASSERT_EQ(a.size(), 1u) << a.dump(1);
  EXPECT_EQ(a[0]["title"], "Insert ';'");
  EXPECT_EQ(a[0]["edit"]["changes"][uri][0]["range"]["start"]["line"], 1);
  EXPECT_EQ(a[0]["edit"]["changes"][uri][0]["range"]["start"]["character"], 44);
}

TEST_F(LanguageServerTest, DocumentSymbolsOutlineTheEffect) {
  open_main();
  json reply = session_.request("textDocument/documentSymbol",
                                {{"textDocument", {{"uri", fx::tools::lsp::path_to_uri(path("main.fx"))}}}});
  const json& symbols = reply["result"];
  std::vector<std::string> names;
  for (const json& s : symbols) names.push_back(s["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"WorldViewProj", "Gloss", "Diffuse", "DiffuseSampler", "VSOut", "VS", "PS",
                                             "Main"}));
  EXPECT_EQ(symbols[7]["children"][0]["name"], "P0");
  EXPECT_EQ(symbols[4]["children"].size(), 3u);
}

TEST_F(LanguageServerTest, CompletionOfStatesValuesAndNamesInScope) {
  open_main();
  // A new line in the pass: state names.
  session_.change(path("main.fx"), 2, 21, 0, 21, 0, "    Cu\n");
  auto items = labels(session_.at("textDocument/completion", path("main.fx"), 21, 6));
  EXPECT_TRUE(has(items, "CullMode"));
  EXPECT_TRUE(has(items, "ZEnable"));
  // After `CullMode = `: its values.
  session_.change(path("main.fx"), 3, 21, 4, 21, 6, "CullMode = ");
  items = labels(session_.at("textDocument/completion", path("main.fx"), 21, 15));
  EXPECT_TRUE(has(items, "CCW"));
  EXPECT_FALSE(has(items, "ZEnable"));
  // In the sampler_state: sampler states.
  items = labels(session_.at("textDocument/completion", path("main.fx"), 4, 63));
  EXPECT_TRUE(has(items, "MagFilter"));
  // In PS's body: the locals, parameters and globals in scope, and intrinsics.
  items = labels(session_.at("textDocument/completion", path("main.fx"), 15, 2));
  EXPECT_TRUE(has(items, "d"));
  EXPECT_TRUE(has(items, "i"));
  EXPECT_TRUE(has(items, "Gloss"));
  EXPECT_TRUE(has(items, "lerp"));
  EXPECT_FALSE(has(items, "o"));  // VS's local
  // After `i.`: VSOut's members.
  items = labels(session_.at("textDocument/completion", path("main.fx"), 15, 33));  // `i.uv`: after `i.`
  EXPECT_TRUE(has(items, "uv"));
  EXPECT_TRUE(has(items, "pos"));
}

TEST_F(LanguageServerTest, CancelledRequestsAreAnsweredAsCancelled) {
  open_main();
  const json document = {{"textDocument", {{"uri", fx::tools::lsp::path_to_uri(path("main.fx"))}}}};
  session_.server().cancel(7);  // no such request yet
  json reply = session_.request("textDocument/documentSymbol", document);
  EXPECT_TRUE(reply.contains("result"));
  session_.server().cancel(reply["id"].get<int>() + 1);  // the next request
  reply = session_.request("textDocument/documentSymbol", document);
  EXPECT_EQ(reply["error"]["code"], -32800);
}

TEST_F(LanguageServerTest, ConfigurationFromTheWorkspaceFile) {
  folder_.write("inc/extra.fxh", "float ExtraGloss = 2;\n");
  folder_.write("fxkit.json", R"({"includeDirs": ["inc"], "defines": ["STRENGTH=ExtraGloss"]})");
  const std::string text =
      "#include \"extra.fxh\"\nfloat4 PS() : COLOR { return STRENGTH; }\n"
      "technique T { pass { PixelShader = compile ps_2_0 PS(); } }\n";
  folder_.write("cfg.fx", text);
  session_.initialize({}, folder_.path());
  session_.open(path("cfg.fx"), text);
  EXPECT_TRUE(session_.diagnostics(path("cfg.fx")).empty()) << session_.diagnostics(path("cfg.fx")).dump(1);
  // Without the file the include is not found.
  LspSession bare;
  bare.initialize();
  bare.open(path("cfg.fx"), text);
  json d = bare.diagnostics(path("cfg.fx"));
  ASSERT_FALSE(d.empty());
}

TEST_F(LanguageServerTest, ShutdownThenExit) {
  open_main();
  EXPECT_TRUE(session_.request("shutdown", nullptr)["result"].is_null());
  EXPECT_EQ(session_.request("textDocument/hover", json::object())["error"]["code"], -32600);
  session_.notify("exit", nullptr);
  EXPECT_TRUE(session_.server().exited());
  EXPECT_EQ(session_.server().exit_code(), 0);
}

TEST_F(LanguageServerTest, ClosingADocumentClearsItsDiagnostics) {
  open_main();
  session_.change(path("main.fx"), 2, 15, 50, 15, 55, "Glos");
  ASSERT_EQ(session_.diagnostics(path("main.fx")).size(), 1u);
  session_.notify("textDocument/didClose", {{"textDocument", {{"uri", fx::tools::lsp::path_to_uri(path("main.fx"))}}}});
  EXPECT_TRUE(session_.diagnostics(path("main.fx")).empty());
}

}  // namespace
