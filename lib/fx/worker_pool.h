// Parallel work for the compile paths: the stages of an effect, several effects, the files
// of a `fxkit check` run. A TaskExecutor is what they take, so an engine can hand them its
// own job system; WorkerPool is fxkit's own.
#pragma once
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fx {

// Runs a batch of independent tasks. for_each may be called from several threads at once
// and from inside a task (nested batches): an implementation must not deadlock on either.
class TaskExecutor {
 public:
  virtual ~TaskExecutor() = default;
  // Calls task(i) for every i in [0, count), on any threads in any order, and returns when
  // every call has returned. Tasks must not throw.
  virtual void for_each(size_t count, const std::function<void(size_t)>& task) = 0;
  // How many tasks can run at once (1: for_each is a plain loop).
  virtual size_t concurrency() const = 0;
};

// `threads` threads of work: the caller of for_each and threads - 1 helpers. The caller
// takes tasks of its own batch too, so a task may call for_each on the same pool.
class WorkerPool final : public TaskExecutor {
 public:
  // 0: one per hardware thread (std::thread::hardware_concurrency()).
  explicit WorkerPool(size_t threads = 0);
  ~WorkerPool() override;
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void for_each(size_t count, const std::function<void(size_t)>& task) override;
  size_t concurrency() const override { return helpers_.size() + 1; }

  // The hardware threads of this machine (at least 1).
  static size_t hardware_threads();

 private:
  struct Batch {
    const std::function<void(size_t)>* task = nullptr;
    size_t count = 0;
    size_t next = 0;  // first index not yet taken
    size_t done = 0;  // calls returned
  };
  // Caller holds mutex_: the next index of `b`, removing `b` from the queue when it is the last.
  size_t take(Batch& b);
  void run(Batch& b, size_t index);
  void helper_main();

  std::mutex mutex_;
  std::condition_variable work_;      // a batch was queued, or stop
  std::condition_variable finished_;  // a batch's last call returned
  std::deque<Batch*> queue_;          // batches with indices not yet taken
  std::vector<std::thread> helpers_;
  bool stop_ = false;
};

}  // namespace fx
