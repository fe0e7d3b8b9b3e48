// Request dispatch and document lifecycle of the language server (language_server.h).
#include "language_server.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <deque>
#include <filesystem>

#include "json_rpc.h"
#include "language_features.h"

namespace fx::tools::lsp {
namespace {

// JSON-RPC and LSP error codes.
constexpr int kParseError = -32700, kInvalidRequest = -32600, kMethodNotFound = -32601, kInvalidParams = -32602,
              kInternalError = -32603, kServerNotInitialized = -32002, kRequestCancelled = -32800;

Position position_of(const json& p) { return {p.at("line").get<uint32_t>(), p.at("character").get<uint32_t>()}; }

std::map<std::string, std::string> texts_by_path(const auto& documents) {
  std::map<std::string, std::string> out;
  for (const auto& [uri, d] : documents) out.emplace(d.text.path, d.text.text);
  return out;
}

}  // namespace

LanguageServer::LanguageServer(Send send, CompileScheduler* compiles) : send_(std::move(send)), compiles_(compiles) {}

void LanguageServer::reply(const json& id, json result) {
  send_({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
}

void LanguageServer::reply_error(const json& id, int code, const std::string& message) {
  send_({{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}});
}

void LanguageServer::cancel(const json& id) { cancelled_.insert(id.dump()); }

void LanguageServer::handle(const json& message) {
  if (!message.is_object()) {
    reply_error(nullptr, kInvalidRequest, "a message must be a JSON object");
    return;
  }
  const auto method = message.find("method");
  const auto id = message.find("id");
  if (method == message.end() || !method->is_string()) {
    if (id == message.end()) reply_error(nullptr, kInvalidRequest, "a message needs a method");
    return;  // a reply to a request of ours: the server sends none that need one
  }
  const json params = message.value("params", json::object());
  try {
    if (id != message.end()) request(method->get<std::string>(), *id, params);
    else notification(method->get<std::string>(), params);
  } catch (const json::exception& e) {
    if (id != message.end()) reply_error(*id, kInvalidParams, e.what());
  } catch (const std::exception& e) {
    if (id != message.end()) reply_error(*id, kInternalError, e.what());
  }
}

void LanguageServer::request(const std::string& method, const json& id, const json& params) {
  if (cancelled_.erase(id.dump())) {
    reply_error(id, kRequestCancelled, "cancelled");
    return;
  }
  if (method == "initialize") {
    reply(id, initialize(params));
    return;
  }
  if (!initialized_) {
    reply_error(id, kServerNotInitialized, "initialize first");
    return;
  }
  if (shutdown_) {
    reply_error(id, kInvalidRequest, "the server is shutting down");
    return;
  }
  if (method == "shutdown") {
    shutdown_ = true;
    reply(id, nullptr);
  } else if (method == "textDocument/hover") {
    auto [doc, a] = analyzed(params);
    reply(id, hover(*a, doc->text, position_of(params.at("position"))));
  } else if (method == "textDocument/definition") {
    auto [doc, a] = analyzed(params);
    reply(id, definition(*a, doc->text, position_of(params.at("position"))));
  } else if (method == "textDocument/references") {
    auto [doc, a] = analyzed(params);
    const bool declaration = params.value("context", json::object()).value("includeDeclaration", false);
    reply(id, references(*a, position_of(params.at("position")), declaration));
  } else if (method == "textDocument/codeAction") {
    auto [doc, a] = analyzed(params);
    reply(id, code_actions(*a, doc->text, params.at("range")));
  } else if (method == "textDocument/codeLens") {
    // Technique validity comes with the compile: none while the text has changed since.
    reply(id, analyzed(params).first->code_lenses);
  } else if (method == "workspace/executeCommand") {
    execute_command(id, params);
  } else if (method == "textDocument/documentSymbol") {
    reply(id, document_symbols(*analyzed(params).second));
  } else if (method == "textDocument/completion") {
    auto [doc, a] = analyzed(params);
    reply(id, completion(*a, doc->text, position_of(params.at("position"))));
  } else {
    reply_error(id, kMethodNotFound, "fxkit lsp does not handle " + method);
  }
}

void LanguageServer::notification(const std::string& method, const json& params) {
  if (method == "exit") {
    exited_ = true;
  } else if (method == "$/cancelRequest") {
    cancel(params.at("id"));
  } else if (!initialized_ || shutdown_) {
    return;
  } else if (method == "textDocument/didOpen") {
    did_open(params);
  } else if (method == "textDocument/didChange") {
    did_change(params);
  } else if (method == "textDocument/didClose") {
    did_close(params);
  } else if (method == "workspace/didChangeConfiguration") {
    settings_ = params.value("settings", json::object()).value("fxkit", json::object());
    configure();
  }
}

json LanguageServer::initialize(const json& params) {
  initialized_ = true;
  if (params.contains("rootUri") && params["rootUri"].is_string())
    root_ = uri_to_path(params["rootUri"].get<std::string>());
  else if (params.contains("rootPath") && params["rootPath"].is_string()) root_ = params["rootPath"].get<std::string>();
  initialization_options_ = params.value("initializationOptions", json::object());
  const json capabilities = params.value("capabilities", json::object());
  progress_ = capabilities.value("window", json::object()).value("workDoneProgress", false);
  refresh_lenses_ =
      capabilities.value("workspace", json::object()).value("codeLens", json::object()).value("refreshSupport", false);
  configure();
  return {{"capabilities",
           {{"textDocumentSync", {{"openClose", true}, {"change", 2}}},
            {"hoverProvider", true},
            {"definitionProvider", true},
            {"referencesProvider", true},
            {"codeActionProvider", {{"codeActionKinds", {"quickfix"}}}},
            {"documentSymbolProvider", true},
            {"codeLensProvider", {{"resolveProvider", false}}},
            {"executeCommandProvider", {{"commands", {kTechniqueValidityCommand}}}},
            {"completionProvider", {{"triggerCharacters", {".", "="}}}}}},
          {"serverInfo", {{"name", "fxkit"}}}};
}

void LanguageServer::execute_command(const json& id, const json& params) {
  const std::string command = params.at("command").get<std::string>();
  if (command != kTechniqueValidityCommand) {
    reply_error(id, kInvalidParams, "fxkit lsp has no command " + command);
    return;
  }
  // A technique validity lens clicked: every profile's verdict and reasons, as a message.
  const std::string message = params.at("arguments").at(0).at("message").get<std::string>();
  send_({{"jsonrpc", "2.0"}, {"method", "window/showMessage"}, {"params", {{"type", 3}, {"message", message}}}});
  reply(id, nullptr);
}

void LanguageServer::configure() {
  WorkspaceConfig config;
  std::vector<std::string> problems;
  merge_workspace_file(root_, config, problems);
  config.merge(initialization_options_, root_, problems);
  config.merge(settings_, root_, problems);
  config_ = std::move(config);
  for (const std::string& p : problems)
    send_(
        {{"jsonrpc", "2.0"}, {"method", "window/showMessage"}, {"params", {{"type", 2}, {"message", "fxkit: " + p}}}});
  for (auto& [uri, d] : documents_) {
    d.analysis.reset();
    d.publish = true;
  }
}

void LanguageServer::did_open(const json& params) {
  const json& item = params.at("textDocument");
  OpenDocument d;
  d.text.uri = item.at("uri").get<std::string>();
  d.text.path = uri_to_path(d.text.uri);
  if (d.text.path.empty()) d.text.path = d.text.uri;
  d.text.version = item.value("version", int64_t{0});
  d.text.text = item.at("text").get<std::string>();
  d.publish = true;
  invalidate_includers(d.text.path);
  documents_[d.text.uri] = std::move(d);
}

void LanguageServer::did_change(const json& params) {
  const json& item = params.at("textDocument");
  auto it = documents_.find(item.at("uri").get<std::string>());
  if (it == documents_.end()) return;
  OpenDocument& d = it->second;
  for (const json& change : params.at("contentChanges")) {
    if (change.contains("range")) {
      const json& r = change.at("range");
      d.text.replace(position_of(r.at("start")), position_of(r.at("end")), change.at("text").get<std::string>());
    } else {
      d.text.text = change.at("text").get<std::string>();
    }
  }
  d.text.version = item.value("version", d.text.version + 1);
  d.analysis.reset();
  d.publish = true;
  invalidate_includers(d.text.path);
}

void LanguageServer::did_close(const json& params) {
  const std::string uri = params.at("textDocument").at("uri").get<std::string>();
  auto it = documents_.find(uri);
  if (it == documents_.end()) return;
  const std::string path = it->second.text.path;
  if (compiles_) compiles_->cancel(uri);
  end_compile(it->second);
  documents_.erase(it);
  invalidate_includers(path);  // they read it from disk again
  send_({{"jsonrpc", "2.0"},
         {"method", "textDocument/publishDiagnostics"},
         {"params", {{"uri", uri}, {"diagnostics", json::array()}}}});
}

void LanguageServer::invalidate_includers(const std::string& path) {
  for (auto& [uri, d] : documents_) {
    if (!d.analysis) continue;
    const std::vector<std::string>& files = d.analysis->parsed().files;
    if (std::find(files.begin(), files.end(), path) != files.end()) {
      d.analysis.reset();
      d.publish = true;
    }
  }
}

std::pair<LanguageServer::OpenDocument*, std::shared_ptr<const DocumentAnalysis>> LanguageServer::analyzed(
    const json& params) {
  const std::string uri = params.at("textDocument").at("uri").get<std::string>();
  auto it = documents_.find(uri);
  if (it == documents_.end()) throw std::invalid_argument(uri + " is not open");
  OpenDocument& d = it->second;
  if (!d.analysis) d.analysis = std::make_shared<const DocumentAnalysis>(d.text, config_, texts_by_path(documents_));
  return {&d, d.analysis};
}

void LanguageServer::publish(const std::string& uri, OpenDocument& d) {
  json diagnostics = document_diagnostics(*d.analysis);
  for (const json& c : d.compiled) diagnostics.push_back(c);
  send_({{"jsonrpc", "2.0"},
         {"method", "textDocument/publishDiagnostics"},
         {"params", {{"uri", uri}, {"version", d.text.version}, {"diagnostics", std::move(diagnostics)}}}});
}

void LanguageServer::schedule_compile(OpenDocument& d) {
  if (!compiles_) return;
  for (const fx::Diagnostic& diagnostic : d.analysis->diagnostics())
    if (diagnostic.severity >= fx::Severity::error) {  // glslang would only repeat them
      compiles_->cancel(d.text.uri);
      end_compile(d);
      return;
    }
  d.compile_generation = ++next_generation_;
  compiles_->schedule({d.text.uri, d.compile_generation, d.text, config_, texts_by_path(documents_)});
  if (!progress_ || !d.progress.empty()) return;
  // Server-initiated progress: the token is created, then used at once (as rust-analyzer
  // and clangd do); a client that refuses it ignores the reports.
  d.progress = "fxkit/compile/" + std::to_string(++next_request_);
  send_({{"jsonrpc", "2.0"},
         {"id", d.progress},
         {"method", "window/workDoneProgress/create"},
         {"params", {{"token", d.progress}}}});
  const std::string file = std::filesystem::path(d.text.path).filename().string();
  send_(
      {{"jsonrpc", "2.0"},
       {"method", "$/progress"},
       {"params",
        {{"token", d.progress},
         {"value", {{"kind", "begin"}, {"title", "Compiling shaders"}, {"message", file}, {"cancellable", false}}}}}});
}

void LanguageServer::end_compile(OpenDocument& d) {
  if (d.progress.empty()) return;
  send_({{"jsonrpc", "2.0"},
         {"method", "$/progress"},
         {"params", {{"token", d.progress}, {"value", {{"kind", "end"}}}}}});
  d.progress.clear();
}

void LanguageServer::publish_pending() {
  std::set<std::string> compiled;
  if (compiles_)
    for (CompileResult& r : compiles_->take_results()) {
      auto it = documents_.find(r.uri);
      // Only the result of the snapshot scheduled last: an older one describes other text.
      if (it == documents_.end() || it->second.compile_generation != r.generation) continue;
      it->second.compiled = std::move(r.findings.diagnostics);
      it->second.code_lenses = std::move(r.findings.code_lenses);
      end_compile(it->second);
      compiled.insert(r.uri);
    }
  for (auto& [uri, d] : documents_) {
    if (!d.publish && !compiled.count(uri)) continue;
    if (!d.analysis) d.analysis = std::make_shared<const DocumentAnalysis>(d.text, config_, texts_by_path(documents_));
    if (d.publish) {
      d.publish = false;
      d.compiled = json::array();  // placed in the old text; the new compile brings its own
      d.code_lenses = json::array();
      schedule_compile(d);
    }
    publish(uri, d);
    d.analysis->index_tokens();  // after the publication: hover and definition then find it built
  }
  if (!compiled.empty() && refresh_lenses_)
    send_({{"jsonrpc", "2.0"},
           {"id", "fxkit/codeLens/" + std::to_string(++next_request_)},
           {"method", "workspace/codeLens/refresh"}});
}

namespace {

// A pipe the compile thread writes a byte to when a result is ready, so the loop wakes.
struct WakePipe {
  int fds[2] = {-1, -1};
  WakePipe() {
    if (::pipe2(fds, O_NONBLOCK | O_CLOEXEC) != 0) fds[0] = fds[1] = -1;
  }
  ~WakePipe() {
    for (int fd : fds)
      if (fd >= 0) ::close(fd);
  }
  void wake() const {
    const char byte = 1;
    [[maybe_unused]] ssize_t n = ::write(fds[1], &byte, 1);  // full: a wake-up is pending anyway
  }
  void drain() const {
    char bytes[64];
    while (::read(fds[0], bytes, sizeof bytes) > 0) {
    }
  }
};

// Waits until `in_fd` has input (true) or `wake_fd` is written to (false).
bool wait_for_input(int in_fd, int wake_fd) {
  for (;;) {
    pollfd p[2] = {{in_fd, POLLIN, 0}, {wake_fd, POLLIN, 0}};
    if (::poll(p, wake_fd >= 0 ? 2 : 1, -1) < 0) {
      if (errno == EINTR) continue;
      return true;  // let the read report the problem
    }
    if (p[0].revents) return true;
    if (wake_fd >= 0 && p[1].revents) return false;
  }
}

}  // namespace

int run_stdio(int in_fd, int out_fd, CompileScheduler::Compile compile) {
  MessageReader reader(in_fd);
  WakePipe wake;
  std::unique_ptr<CompileScheduler> compiles;
  if (compile)
    compiles = std::make_unique<CompileScheduler>(std::move(compile), kCompileDebounce, [&wake] { wake.wake(); });
  LanguageServer server([out_fd](const json& m) { write_message(out_fd, m); }, compiles.get());
  std::deque<json> queue;
  auto enqueue = [&](const std::string& text) {
    json message = json::parse(text, nullptr, false);
    if (message.is_discarded()) {
      write_message(out_fd, {{"jsonrpc", "2.0"},
                             {"id", nullptr},
                             {"error", {{"code", kParseError}, {"message", "the message is no JSON"}}}});
      return;
    }
    // A cancellation takes effect on the queued request it names, before that is handled.
    if (message.is_object() && message.value("method", "") == "$/cancelRequest" && message.contains("params") &&
        message["params"].is_object() && message["params"].contains("id"))
      server.cancel(message["params"]["id"]);
    else queue.push_back(std::move(message));
  };
  while (!server.exited()) {
    if (queue.empty()) {
      server.publish_pending();
      if (!reader.more_waiting() && !wait_for_input(in_fd, compiles ? wake.fds[0] : -1)) {
        wake.drain();
        continue;
      }
      std::optional<std::string> text = reader.read();
      if (!text) break;
      enqueue(*text);
    }
    while (reader.more_waiting()) {
      std::optional<std::string> text = reader.read();
      if (!text) break;
      enqueue(*text);
    }
    if (queue.empty()) continue;
    json message = std::move(queue.front());
    queue.pop_front();
    server.handle(message);
  }
  return server.exited() ? server.exit_code() : 1;
}

}  // namespace fx::tools::lsp
