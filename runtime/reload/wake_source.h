// One pollable descriptor for everything a FileWatcher waits on: kernel notifications,
// its own deadlines (timerfd) and cross-thread interrupts (eventfd), joined by epoll.
#pragma once
#include <chrono>
#include <optional>
#include <vector>

namespace fx::detail {

class WakeSource {
 public:
  using Clock = std::chrono::steady_clock;
  enum class WaitResult { ready, timed_out, interrupted };

  WakeSource();  // any part may fail; ok() says whether the combined handle exists
  ~WakeSource();
  WakeSource(const WakeSource&) = delete;
  WakeSource& operator=(const WakeSource&) = delete;

  bool ok() const { return epoll_fd_ >= 0 && timer_fd_ >= 0 && event_fd_ >= 0; }
  int error() const { return error_; }
  // The epoll descriptor (readable when any source is), or -1.
  int handle() const { return ok() ? epoll_fd_ : -1; }

  // Also wakes on `fd` becoming readable.
  void add(int fd);
  // Makes handle() readable at `deadline`; nullopt disarms.
  void arm(std::optional<Clock::time_point> deadline);
  // Thread-safe: makes the current or next wait() return `interrupted`.
  void interrupt();
  // Blocks up to `timeout` (0 = just look); consumes timer expiries and interrupts.
  WaitResult wait(std::chrono::milliseconds timeout);

 private:
  int epoll_fd_ = -1, timer_fd_ = -1, event_fd_ = -1;
  int error_ = 0;
  std::vector<int> sources_;  // for the poll(2) fallback when epoll is missing
};

}  // namespace fx::detail
