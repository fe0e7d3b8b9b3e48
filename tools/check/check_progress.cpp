#include "check_progress.h"

#include <cstdio>

namespace fx::tools {

CheckProgress::CheckProgress(size_t total, bool shown) : total_(total), shown_(shown) {}

void CheckProgress::update(size_t done) {
  if (!shown_) return;
  Clock::time_point now = Clock::now();
  if (now - start_ < std::chrono::milliseconds(500) || now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  double seconds = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "\r\033[K[%zu/%zu files, %.1f s]", done, total_, seconds);
  std::fflush(stderr);
  drawn_ = true;
}

void CheckProgress::clear() {
  if (!drawn_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace fx::tools
