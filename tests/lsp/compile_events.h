// Test helper: what a CompileScheduler's thread did, for tests that wait on it (never on a
// clock): the generations whose compile started, the results made ready, and a gate that
// holds chosen compiles until the test opens it.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <set>
#include <vector>

namespace fx::testing {

class CompileEvents {
 public:
  // In the compile function: records the start, then waits while `generation` is held.
  void started(uint64_t generation) {
    std::unique_lock lock(mutex_);
    started_.push_back(generation);
    changed_.notify_all();
    changed_.wait(lock, [&] { return !held_.count(generation); });
  }
  // The scheduler's Ready callback.
  void ready() {
    std::lock_guard lock(mutex_);
    ++ready_;
    changed_.notify_all();
  }
  void hold(uint64_t generation) {
    std::lock_guard lock(mutex_);
    held_.insert(generation);
  }
  void release(uint64_t generation) {
    std::lock_guard lock(mutex_);
    held_.erase(generation);
    changed_.notify_all();
  }
  void wait_started(uint64_t generation) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] {
      for (uint64_t g : started_)
        if (g == generation) return true;
      return false;
    });
  }
  // Waits until `count` results have been made ready in all.
  void wait_ready(size_t count) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return ready_ >= count; });
  }
  std::vector<uint64_t> started_generations() {
    std::lock_guard lock(mutex_);
    return started_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<uint64_t> started_;
  std::set<uint64_t> held_;
  size_t ready_ = 0;
};

}  // namespace fx::testing
