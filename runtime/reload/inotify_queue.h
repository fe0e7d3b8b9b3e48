// A non-blocking inotify instance watching directories, decoded into records.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace fx::detail {

// One decoded inotify_event.
struct InotifyRecord {
  int wd = -1;
  uint32_t mask = 0;
  std::string_view name;  // the entry inside the watched directory; empty for the directory
};

class InotifyQueue {
 public:
  // Events that matter for the three editor save patterns, plus the directory itself
  // going away or moving (its watch then no longer describes the path).
  static const uint32_t kDirectoryMask;

  InotifyQueue();  // check ok(); on failure error() holds the errno of inotify_init1
  ~InotifyQueue();
  InotifyQueue(const InotifyQueue&) = delete;
  InotifyQueue& operator=(const InotifyQueue&) = delete;

  bool ok() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  int error() const { return error_; }

  // Adds a directory watch; returns its descriptor, or -1 with the errno in `error`.
  // Adding the same directory inode twice returns the same descriptor.
  int add_directory(const std::string& directory, int& error);
  void remove(int wd);

  // Reads every queued record without blocking and hands each to `on_record`.
  // Returns the number of records read.
  size_t drain(const std::function<void(const InotifyRecord&)>& on_record);

 private:
  int fd_ = -1;
  int error_ = 0;
};

}  // namespace fx::detail
