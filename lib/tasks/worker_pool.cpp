#include "fx/worker_pool.h"

#include <algorithm>

namespace fx {

size_t WorkerPool::hardware_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

WorkerPool::WorkerPool(size_t threads) {
  if (threads == 0) threads = hardware_threads();
  for (size_t i = 1; i < threads; ++i) helpers_.emplace_back([this] { helper_main(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  work_.notify_all();
  for (std::thread& t : helpers_) t.join();
}

size_t WorkerPool::take(Batch& b) {
  size_t index = b.next++;
  if (b.next == b.count) queue_.erase(std::find(queue_.begin(), queue_.end(), &b));
  return index;
}

void WorkerPool::run(Batch& b, size_t index) {
  (*b.task)(index);
  std::lock_guard lock(mutex_);
  if (++b.done == b.count) finished_.notify_all();
}

void WorkerPool::for_each(size_t count, const std::function<void(size_t)>& task) {
  if (count == 0) return;
  if (helpers_.empty() || count == 1) {
    for (size_t i = 0; i < count; ++i) task(i);
    return;
  }
  Batch b{&task, count};
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(&b);
  }
  work_.notify_all();
  std::unique_lock lock(mutex_);
  while (b.next < b.count) {
    size_t index = take(b);
    lock.unlock();
    run(b, index);
    lock.lock();
  }
  // The others' calls of this batch are running: each returns without waiting on us.
  finished_.wait(lock, [&] { return b.done == b.count; });
}

void WorkerPool::helper_main() {
  std::unique_lock lock(mutex_);
  for (;;) {
    work_.wait(lock, [&] { return stop_ || !queue_.empty(); });
    if (stop_) return;
    Batch& b = *queue_.front();
    size_t index = take(b);
    lock.unlock();
    run(b, index);
    lock.lock();
  }
}

}  // namespace fx
