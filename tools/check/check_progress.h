// "[37/122 files, 4.1 s]" on one line of a terminal while a long `fxkit check` runs; nothing
// at all when stderr is not a terminal (a pipe, a CI log).
#pragma once
#include <chrono>
#include <cstddef>

namespace fx::tools {

class CheckProgress {
 public:
  // `shown`: draw at all (the caller tests isatty(stderr)).
  CheckProgress(size_t total, bool shown);
  // `done` files finished: redraws at most ten times a second, from the first half second on.
  void update(size_t done);
  // Erases the line, so that what is printed next starts on a clean line.
  void clear();

 private:
  using Clock = std::chrono::steady_clock;
  size_t total_;
  bool shown_;
  bool drawn_ = false;
  Clock::time_point start_ = Clock::now(), last_{};
};

}  // namespace fx::tools
