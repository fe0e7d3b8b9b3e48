// Helpers for the watcher tests: a scratch directory, the three editor save patterns and
// bounded waits on FileWatcher::poll (never a fixed sleep).
#pragma once
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/patience.h"
#include "fx/reload/file_watcher.h"

namespace fx::testing {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// A fresh directory under the test temp dir, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (fs::path(::testing::TempDir()) / "fxkit_watch_XXXXXX").string();
    char* made = mkdtemp(pattern.data());
    path_ = made ? fs::path(made) : fs::path();
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

// Editor save pattern 1: open with truncation, write, close (CLOSE_WRITE).
inline void save_truncate_write(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
}

// Editor save pattern 2: write a temporary sibling, rename it over the file (MOVED_TO).
inline void save_rename_over(const fs::path& file, const std::string& text) {
  fs::path temp = file;
  temp += ".tmp-save";
  save_truncate_write(temp, text);
  fs::rename(temp, file);
}

// Editor save pattern 3 (vim's backup): rename the original away, write a new file,
// drop the backup (MOVED_FROM, CREATE, CLOSE_WRITE, then a sibling DELETE).
inline void save_backup_rename(const fs::path& file, const std::string& text) {
  fs::path backup = file;
  backup += "~";
  fs::rename(file, backup);
  save_truncate_write(file, text);
  fs::remove(backup);
}

// Waits until at least one event arrives (giving up after fx::testing::patience()); returns
// what arrived.
inline std::vector<FileEvent> wait_for_events(FileWatcher& watcher,
                                              std::chrono::milliseconds limit = fx::testing::patience()) {
  auto deadline = std::chrono::steady_clock::now() + limit;
  for (;;) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return {};
    std::vector<FileEvent> events = watcher.poll(left);
    if (!events.empty()) return events;
  }
}

}  // namespace fx::testing
