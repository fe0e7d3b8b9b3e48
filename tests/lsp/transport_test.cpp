// The stdio transport: framing over real pipes, parse errors answered, cancellation of a
// queued request, and a fuzzed session (random edits, half the file deleted, binary
// pasted) that must end with the server alive and diagnostics matching the final text.
#include <unistd.h>

#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "json_rpc.h"
#include "language_server.h"
#include "lsp_session.h"

namespace {

using nlohmann::json;

struct Pipes {
  int to_server[2], from_server[2];
  Pipes() {
    EXPECT_EQ(::pipe(to_server), 0);
    EXPECT_EQ(::pipe(from_server), 0);
  }
  ~Pipes() {
    for (int fd : {to_server[0], to_server[1], from_server[0], from_server[1]})
      if (fd >= 0) ::close(fd);
  }
  void send(const json& m) { send_text(fx::tools::lsp::frame(m)); }
  void send_text(const std::string& text) {
    ASSERT_EQ(::write(to_server[1], text.data(), text.size()), ssize_t(text.size()));
  }
  void close_input() {
    ::close(to_server[1]);
    to_server[1] = -1;
  }
};

json message(int id, const std::string& method, json params) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}};
}

TEST(Transport, FramedSessionOverPipes) {
  Pipes p;
  int exit_code = -1;
  std::thread server([&] { exit_code = fx::tools::lsp::run_stdio(p.to_server[0], p.from_server[1]); });
  fx::tools::lsp::MessageReader replies(p.from_server[0]);
  // Everything is written before the server reads: the hover is queued behind the
  // cancellation that names it, so it is answered as cancelled.
  p.send(message(1, "initialize", {{"capabilities", json::object()}}));
  p.send_text("Content-Length: 9\r\n\r\n{broken}!");
  p.send(
      {{"jsonrpc", "2.0"},
       {"method", "textDocument/didOpen"},
       {"params", {{"textDocument", {{"uri", "file:///nowhere/t.fx"}, {"version", 1}, {"text", "float x = y;\n"}}}}}});
  p.send(message(2, "textDocument/hover",
                 {{"textDocument", {{"uri", "file:///nowhere/t.fx"}}}, {"position", {{"line", 0}, {"character", 6}}}}));
  p.send({{"jsonrpc", "2.0"}, {"method", "$/cancelRequest"}, {"params", {{"id", 2}}}});
  p.send(message(3, "shutdown", nullptr));
  p.send({{"jsonrpc", "2.0"}, {"method", "exit"}});
  std::vector<json> got;
  while (auto text = replies.read()) {
    got.push_back(json::parse(*text));
    if (got.back().value("id", json()) == 3) break;
  }
  server.join();
  EXPECT_EQ(exit_code, 0);
  // The parse error is answered as soon as it is read, before the queued requests.
  auto reply_to = [&](const json& id) {
    for (const json& m : got)
      if (m.contains("id") && m["id"] == id && !m.contains("method")) return m;
    return json();
  };
  EXPECT_TRUE(reply_to(1)["result"].contains("capabilities"));
  EXPECT_EQ(reply_to(nullptr)["error"]["code"], -32700);
  EXPECT_EQ(reply_to(2)["error"]["code"], -32800);
  EXPECT_TRUE(reply_to(3)["result"].is_null());
}

TEST(Transport, EndOfInputWithoutExitIsAnError) {
  Pipes p;
  p.send(message(1, "initialize", json::object()));
  p.close_input();
  EXPECT_EQ(fx::tools::lsp::run_stdio(p.to_server[0], p.from_server[1]), 1);
}

TEST(Transport, FuzzedEditingSessionLeavesNoStaleDiagnostics) {
  const std::string base = R"(float Gloss = 2;
struct V { float4 p : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION) { V o = (V)0; o.p = p; return o; }
float4 PS(V i) : COLOR { return float4(i.uv, Gloss, 1); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); CullMode = CCW; } }
)";
  fx::testing::LspSession s;
  s.initialize();
  s.open("/nowhere/fuzz.fx", base);
  std::mt19937 rng(38);
  std::string text = base;
  for (int step = 0; step < 300; ++step) {
    // Edit in a random line range: delete, insert random bytes (binary included), or delete half.
    const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
    const int l0 = static_cast<int>(rng() % lines), l1 = l0 + static_cast<int>(rng() % 3);
    std::string insert;
    switch (rng() % 4) {
      case 0: break;
      case 1:
        for (int k = static_cast<int>(rng() % 12); k > 0; --k) insert += static_cast<char>(rng() % 256);
        break;
      case 2: insert = "{ } ; . = < > ( ) Gloss i.uv "; break;
      case 3: insert = base.substr(rng() % base.size(), 40); break;
    }
    if (step % 50 == 49) s.change("/nowhere/fuzz.fx", step + 2, lines / 2, 0, lines + 5, 0, "");
    else s.change("/nowhere/fuzz.fx", step + 2, l0, rng() % 20, l1, rng() % 20, insert);
    if (step % 7 == 0) s.at("textDocument/hover", "/nowhere/fuzz.fx", l0, rng() % 30);
    if (step % 11 == 0) s.at("textDocument/completion", "/nowhere/fuzz.fx", l0, rng() % 30);
    if (step % 13 == 0) s.at("textDocument/definition", "/nowhere/fuzz.fx", l0, rng() % 30);
    if (step % 5 == 0) s.diagnostics("/nowhere/fuzz.fx");
  }
  // Back to the clean text in one full change: the last diagnostics are empty again.
  s.notify("textDocument/didChange", {{"textDocument", {{"uri", "file:///nowhere/fuzz.fx"}, {"version", 1000}}},
                                      {"contentChanges", {{{"text", base}}}}});
  EXPECT_TRUE(s.diagnostics("/nowhere/fuzz.fx").empty()) << s.diagnostics("/nowhere/fuzz.fx").dump(1);
  EXPECT_TRUE(s.request("shutdown", nullptr)["result"].is_null());
}

}  // namespace
