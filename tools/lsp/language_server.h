// The fxkit language server: LSP requests and notifications mapped to analyses of the
// open documents (document_analysis.h) and the features over them (language_features.h). Messages
// come in one at a time through handle(); what the server sends goes to a callback, so
// tests drive it without a process and `fxkit lsp` wires it to stdio (run_stdio).
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "compile_scheduler.h"
#include "document_analysis.h"
#include "text_document.h"
#include "workspace_config.h"

namespace fx::tools::lsp {

using json = nlohmann::json;

class LanguageServer {
 public:
  using Send = std::function<void(const json&)>;
  // `compiles` (optional, not owned): compiled-shader diagnostics are scheduled there and
  // published with the front end's when they arrive; without it, only the front end's.
  explicit LanguageServer(Send send, CompileScheduler* compiles = nullptr);

  // One message from the client: a request (answered through send), a notification, or
  // the reply to a request of ours.
  void handle(const json& message);
  // Marks a request as cancelled before it is handled ($/cancelRequest): it is answered
  // with RequestCancelled instead. The transport calls this as soon as it reads the notice.
  void cancel(const json& id);
  // Publishes the diagnostics of every document changed since its last publication, and of
  // those whose compile finished, and schedules the compiles of the changed ones. The
  // transport calls this when no message is waiting, so a burst of edits is analyzed once,
  // and when the scheduler has a result.
  void publish_pending();

  bool exited() const { return exited_; }
  // The process's exit code once exited(): 0 after shutdown, 1 without.
  int exit_code() const { return shutdown_ ? 0 : 1; }

 private:
  struct OpenDocument {
    TextDocument text;
    std::shared_ptr<const DocumentAnalysis> analysis;  // of text at analysis->version(), or null
    bool publish = false;                              // diagnostics not yet published for the text
    json compiled = json::array();                     // the compiled shaders' diagnostics of compile_generation
    json code_lenses = json::array();                  // its techniques' validity
    uint64_t compile_generation = 0;                   // the snapshot scheduled last (0: none)
    std::string progress;                              // the token of the pending compile's progress report, if shown
  };

  void request(const std::string& method, const json& id, const json& params);
  void notification(const std::string& method, const json& params);
  json initialize(const json& params);
  void execute_command(const json& id, const json& params);  // workspace/executeCommand
  void configure();
  void did_open(const json& params);
  void did_change(const json& params);
  void did_close(const json& params);
  // The document a request names, analyzed up to date; throws for an unknown document.
  std::pair<OpenDocument*, std::shared_ptr<const DocumentAnalysis>> analyzed(const json& params);
  void invalidate_includers(const std::string& path);
  void schedule_compile(OpenDocument& d);
  void end_compile(OpenDocument& d);  // ends the progress report of its compile
  void publish(const std::string& uri, OpenDocument& d);
  void reply(const json& id, json result);
  void reply_error(const json& id, int code, const std::string& message);

  Send send_;
  CompileScheduler* compiles_ = nullptr;
  uint64_t next_generation_ = 0, next_request_ = 0;  // snapshots; our requests and tokens
  bool progress_ = false;        // the client takes server-initiated progress (window.workDoneProgress)
  bool refresh_lenses_ = false;  // the client asks for code lenses again when told (workspace/codeLens/refresh)
  std::map<std::string, OpenDocument> documents_;  // by URI
  std::set<std::string> cancelled_;                // request ids, as JSON text
  WorkspaceConfig config_;
  std::string root_;
  json initialization_options_, settings_;
  bool initialized_ = false, shutdown_ = false, exited_ = false;
};

// How long a document must be quiet before its shaders are compiled.
inline constexpr std::chrono::milliseconds kCompileDebounce{200};

// Serves the protocol over two file descriptors until `exit` or the end of input; returns
// the exit code. With `compile`, compiled-shader diagnostics are published too (on a
// CompileScheduler whose results wake the loop).
int run_stdio(int in_fd, int out_fd, CompileScheduler::Compile compile = {});

}  // namespace fx::tools::lsp
