// Watches effect files (and the files they include) for edits, to drive hot reload.
//
// Linux inotify on the files' directories (one kernel watch per directory, shared by all
// files in it), with a polling backend (mtime + size + content hash) for file systems
// without inotify. Bursts of editor activity are coalesced: a file is reported once, after
// it has been quiet for the coalescing window.
//
// Thread-safety: a FileWatcher is owned by one thread (typically a reload worker); every
// member except interrupt() and wait_handle() must be called from that thread or under the
// owner's lock. interrupt() may be called from any thread at any time while the watcher is
// alive, to wake a blocked poll() (for example to shut the worker down).
#pragma once
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/reload/file_event.h"

namespace fx {

// How changes are detected.
enum class WatchBackend {
  automatic,  // inotify when the kernel offers it, polling otherwise
  inotify,    // inotify; directories that cannot be watched are still polled
  polling,    // stat + content hash every poll_interval
};

// "automatic", "inotify" or "polling".
const char* to_string(WatchBackend backend);

// Tuning knobs; the defaults suit an editor-driven hot-reload loop.
struct FileWatcherOptions {
  WatchBackend backend = WatchBackend::automatic;
  // A file is reported once it has been quiet this long; editors save in several steps.
  std::chrono::milliseconds coalesce_window{50};
  // How often polled directories are scanned (the polling backend, and inotify directories
  // that fell back to polling because they were missing or over the watch limit).
  std::chrono::milliseconds poll_interval{250};
  // After a watched name is created, the watcher waits for the writer to close it; if no
  // close arrives (hard link, symlink) the file is reported after this long instead.
  std::chrono::milliseconds close_grace{1000};
  // Most inotify directory watches this watcher holds (the kernel limit is per user and
  // shared); directories beyond it are polled.
  std::size_t max_inotify_directories = 4096;
};

// Counters for tests, tools and tuning.
struct FileWatcherStats {
  std::size_t files = 0;                // distinct watched files
  std::size_t inotify_directories = 0;  // directories with a kernel watch
  std::size_t polled_directories = 0;   // directories scanned every poll_interval
  std::size_t notifications = 0;        // raw inotify records read
  std::size_t queue_overflows = 0;      // IN_Q_OVERFLOW records seen
  std::size_t rescans = 0;              // full snapshot comparisons (overflow or rescan())
  std::size_t files_hashed = 0;         // content hashes computed (reads of whole files)
};

// Reports edits, deletions and re-creations of a set of files.
class FileWatcher {
 public:
  // Never fails: if inotify cannot be set up it falls back to polling and records a
  // diagnostic (see diagnostics()).
  explicit FileWatcher(FileWatcherOptions options = {});
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;
  // A moved-from watcher may only be destroyed or assigned to.
  FileWatcher(FileWatcher&&) noexcept;
  FileWatcher& operator=(FileWatcher&&) noexcept;

  // Starts watching `file` (reference-counted: watching twice needs two unwatch calls).
  // The file need not exist yet; its creation is then reported as a change. Call this
  // before reading the file, so an edit racing with the read is still reported.
  // Returns false (with a diagnostic) only if the path cannot be resolved.
  bool watch(const std::filesystem::path& file);
  // Drops one reference; returns false if the file was not watched.
  bool unwatch(const std::filesystem::path& file);
  // Whether `file` is currently watched.
  bool is_watched(const std::filesystem::path& file) const;

  // Returns settled events, waiting up to `timeout` for the first one; returns as soon as
  // any are ready, or empty on timeout or interrupt(). A zero timeout never blocks.
  std::vector<FileEvent> poll(std::chrono::milliseconds timeout);

  // Compares every watched file with its last snapshot now (as after a kernel queue
  // overflow) and queues a change for each that differs; returns how many differ.
  std::size_t rescan();

  // A file descriptor that becomes readable when poll(0ms) may have work: kernel
  // notifications, a coalescing or scan deadline, or interrupt(). Add it to an event loop
  // (epoll/poll/select, level-triggered); -1 if the kernel offered no epoll.
  int wait_handle() const;
  // The next time poll() has timed work to do (a settling file or a directory scan).
  std::optional<std::chrono::steady_clock::time_point> next_deadline() const;

  // Wakes a poll() blocked in another thread; safe from any thread.
  void interrupt();

  // The backend in effect (never `automatic`).
  WatchBackend backend() const;
  // Problems met so far: inotify unavailable, watch limit reached, unreadable files.
  const DiagnosticSink& diagnostics() const;
  FileWatcherStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fx
