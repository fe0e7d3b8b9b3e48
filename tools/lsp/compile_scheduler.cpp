// The background compile thread of the language server (compile_scheduler.h).
#include "compile_scheduler.h"

namespace fx::tools::lsp {

CompileScheduler::CompileScheduler(Compile compile, std::chrono::milliseconds debounce, Ready ready)
    : compile_(std::move(compile)), debounce_(debounce), ready_(std::move(ready)), thread_([this] { run(); }) {}

CompileScheduler::~CompileScheduler() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void CompileScheduler::schedule(CompileSnapshot snapshot) {
  {
    std::lock_guard lock(mutex_);
    const std::string uri = snapshot.uri;
    latest_[uri] = snapshot.generation;
    auto [it, fresh] = waiting_.try_emplace(uri);
    if (!fresh) ++stats_.replaced;
    it->second = {std::move(snapshot), Clock::now() + debounce_};
  }
  changed_.notify_all();
}

void CompileScheduler::cancel(const std::string& uri) {
  std::lock_guard lock(mutex_);
  if (waiting_.erase(uri)) ++stats_.replaced;
  latest_.erase(uri);
}

bool CompileScheduler::newest(const std::string& uri, uint64_t generation) const {
  auto it = latest_.find(uri);
  return it != latest_.end() && it->second == generation;
}

std::vector<CompileResult> CompileScheduler::take_results() {
  std::lock_guard lock(mutex_);
  std::vector<CompileResult> out;
  for (CompileResult& r : results_)
    if (newest(r.uri, r.generation)) out.push_back(std::move(r));
  results_.clear();
  return out;
}

CompileScheduler::Stats CompileScheduler::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

void CompileScheduler::run() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    if (waiting_.empty()) {
      changed_.wait(lock);
      continue;
    }
    // The snapshot due first; wait for it unless something newer comes in meanwhile.
    auto next = waiting_.begin();
    for (auto it = waiting_.begin(); it != waiting_.end(); ++it)
      if (it->second.due < next->second.due) next = it;
    if (Clock::now() < next->second.due) {
      changed_.wait_until(lock, next->second.due);
      continue;
    }
    CompileSnapshot snapshot = std::move(next->second.snapshot);
    waiting_.erase(next);
    lock.unlock();
    CompileResult result{snapshot.uri, snapshot.generation, {}};
    try {
      result.findings = compile_(snapshot);
    } catch (const std::exception& e) {  // shown where the editor shows problems, not lost
      result.findings.diagnostics.push_back(
          {{"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}}},
           {"severity", 1},
           {"source", "fxkit"},
           {"message", std::string("compiling the shaders failed: ") + e.what()}});
    }
    lock.lock();
    ++stats_.compiled;
    if (!newest(result.uri, result.generation)) {
      ++stats_.discarded;
      continue;
    }
    results_.push_back(std::move(result));
    lock.unlock();
    if (ready_) ready_();
    lock.lock();
  }
}

}  // namespace fx::tools::lsp
