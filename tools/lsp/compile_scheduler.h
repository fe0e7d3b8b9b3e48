// Compiled-shader diagnostics off the request thread, as clangd's TUScheduler does for its
// builds: one background thread takes the newest snapshot of each document after a quiet
// period (the debounce), so a burst of keystrokes compiles once; a snapshot replaced before
// it ran is dropped, and the result of one replaced while it ran is thrown away.
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "text_document.h"
#include "workspace_config.h"

namespace fx::tools::lsp {

using json = nlohmann::json;

// What a compile needs, copied from the server at the time it is scheduled.
struct CompileSnapshot {
  std::string uri;
  uint64_t generation = 0;  // the server's number for this snapshot; newer ones are larger
  TextDocument document;
  WorkspaceConfig config;
  std::map<std::string, std::string> open;  // paths to the texts of the open documents
};

// The command of a technique validity lens: its argument is an object with the
// technique's name and a message giving its validity and every reason per caps profile,
// which the server shows (workspace/executeCommand, window/showMessage).
inline constexpr const char* kTechniqueValidityCommand = "fxkit.showTechniqueValidity";

// What a compile found: LSP Diagnostics, and CodeLenses (technique validity).
struct CompileFindings {
  json diagnostics = json::array();
  json code_lenses = json::array();
};

struct CompileResult {
  std::string uri;
  uint64_t generation = 0;
  CompileFindings findings;
};

class CompileScheduler {
 public:
  // Runs on the scheduler's thread: what compiling the snapshot finds.
  using Compile = std::function<CompileFindings(const CompileSnapshot&)>;
  // Called on the scheduler's thread when a result is ready to take (the transport wakes).
  using Ready = std::function<void()>;

  CompileScheduler(Compile compile, std::chrono::milliseconds debounce, Ready ready);
  ~CompileScheduler();  // waits for a running compile to end
  CompileScheduler(const CompileScheduler&) = delete;
  CompileScheduler& operator=(const CompileScheduler&) = delete;

  // Compiles `snapshot` once its document has been quiet for the debounce, in place of any
  // snapshot of the same document still waiting; a running one's result becomes outdated.
  void schedule(CompileSnapshot snapshot);
  // Drops the document's waiting snapshot and outdates a running one (closed, or no longer
  // worth compiling).
  void cancel(const std::string& uri);
  // The results that are still the newest of their document, each once.
  std::vector<CompileResult> take_results();

  // Counters for tests and the bench.
  struct Stats {
    uint64_t compiled = 0;   // compiles run to the end
    uint64_t replaced = 0;   // snapshots dropped before they ran
    uint64_t discarded = 0;  // results thrown away because their document changed meanwhile
  };
  Stats stats() const;

 private:
  using Clock = std::chrono::steady_clock;
  struct Waiting {
    CompileSnapshot snapshot;
    Clock::time_point due;
  };
  void run();
  bool newest(const std::string& uri, uint64_t generation) const;  // with mutex_ held

  Compile compile_;
  std::chrono::milliseconds debounce_;
  Ready ready_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::string, Waiting> waiting_;  // by URI
  std::map<std::string, uint64_t> latest_;  // the newest generation scheduled, by URI
  std::vector<CompileResult> results_;
  Stats stats_;
  bool stopping_ = false;
  std::thread thread_;  // last: starts once the rest is built
};

}  // namespace fx::tools::lsp
