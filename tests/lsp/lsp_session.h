// Test helper: a LanguageServer driven in-process, as an editor would drive it: requests
// with ids, notifications, and what the server sent, kept in order.
#pragma once
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "language_server.h"

namespace fx::testing {

using nlohmann::json;

class LspSession {
 public:
  // `compiles` (optional): the scheduler of compiled-shader diagnostics the server uses.
  explicit LspSession(fx::tools::lsp::CompileScheduler* compiles = nullptr)
      : server_([this](const json& m) { sent_.push_back(m); }, compiles) {}

  // Sends a request and returns the server's reply to it (null if there was none).
  json request(const std::string& method, json params) {
    const int id = ++next_id_;
    server_.handle({{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}});
    for (const json& m : sent_)
      if (m.contains("id") && m["id"] == id && !m.contains("method")) return m;
    return nullptr;
  }
  void notify(const std::string& method, json params) {
    server_.handle({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
  }
  json initialize(json options = json::object(), std::string root = "", json capabilities = json::object()) {
    json params = {{"processId", nullptr}, {"capabilities", capabilities}, {"initializationOptions", options}};
    if (!root.empty()) params["rootUri"] = fx::tools::lsp::path_to_uri(root);
    json reply = request("initialize", params);
    notify("initialized", json::object());
    return reply;
  }
  void open(const std::string& path, const std::string& text, int version = 1) {
    notify(
        "textDocument/didOpen",
        {{"textDocument",
          {{"uri", fx::tools::lsp::path_to_uri(path)}, {"languageId", "fx"}, {"version", version}, {"text", text}}}});
  }
  // An incremental change replacing [start, end) with `text`.
  void change(const std::string& path, int version, int l0, int c0, int l1, int c1, const std::string& text) {
    notify("textDocument/didChange",
           {{"textDocument", {{"uri", fx::tools::lsp::path_to_uri(path)}, {"version", version}}},
            {"contentChanges",
             {{{"range", {{"start", {{"line", l0}, {"character", c0}}}, {"end", {{"line", l1}, {"character", c1}}}}},
               {"text", text}}}}});
  }
  // Publishes pending diagnostics and returns the last ones published for `path`.
  json diagnostics(const std::string& path) {
    server_.publish_pending();
    const std::vector<json> all = publications(path);
    return all.empty() ? json() : all.back()["diagnostics"];
  }
  // Every publication for `path` so far (the params of publishDiagnostics), in order.
  std::vector<json> publications(const std::string& path) const {
    std::vector<json> out;
    for (const json& m : sent_)
      if (m.value("method", "") == "textDocument/publishDiagnostics" &&
          m["params"]["uri"] == fx::tools::lsp::path_to_uri(path))
        out.push_back(m["params"]);
    return out;
  }
  // A request about a position of `path`; the reply's result.
  json at(const std::string& method, const std::string& path, int line, int character) {
    json reply = request(method, {{"textDocument", {{"uri", fx::tools::lsp::path_to_uri(path)}}},
                                  {"position", {{"line", line}, {"character", character}}}});
    EXPECT_TRUE(reply.contains("result")) << reply.dump();
    return reply.value("result", json());
  }

  fx::tools::lsp::LanguageServer& server() { return server_; }
  std::vector<json>& sent() { return sent_; }

 private:
  std::vector<json> sent_;
  fx::tools::lsp::LanguageServer server_;
  int next_id_ = 0;
};

// The labels of a completion result.
inline std::vector<std::string> labels(const json& items) {
  std::vector<std::string> out;
  for (const json& i : items) out.push_back(i["label"]);
  return out;
}

inline bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

}  // namespace fx::testing
