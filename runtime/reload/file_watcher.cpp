// FileWatcher: directory-level inotify watches (or polling), snapshots and coalescing.
#include "fx/reload/file_watcher.h"

#include <sys/inotify.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <unordered_map>
#include <utility>

#include "file_snapshot.h"
#include "inotify_queue.h"
#include "network_filesystem.h"
#include "pending_changes.h"
#include "wake_source.h"

namespace fx {

const char* to_string(FileEventKind kind) { return kind == FileEventKind::deleted ? "deleted" : "changed"; }

const char* to_string(WatchBackend backend) {
  switch (backend) {
    case WatchBackend::automatic: return "automatic";
    case WatchBackend::inotify: return "inotify";
    case WatchBackend::polling: return "polling";
  }
  return "automatic";
}

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using detail::Activity;
using detail::FileSnapshot;

struct WatchedFile {
  fs::path reported;      // the spelling first passed to watch()
  std::string directory;  // key into Impl::directories
  int refs = 0;
  FileSnapshot delivered;  // the state consumers were last told about
  FileSnapshot observed;   // the state the last comparison saw (polling, rescans)
};

struct WatchedDirectory {
  int refs = 0;  // watched files inside
  int wd = -1;   // inotify descriptor; -1 means the directory is polled
  bool network_reported = false;
  std::unordered_map<std::string, std::string> names;  // entry name -> file key
};

// A watched path split the way inotify reports it: (directory, entry name).
struct ResolvedPath {
  std::string directory, name, key;
};

std::optional<ResolvedPath> resolve(const fs::path& file) {
  std::error_code ec;
  fs::path absolute = fs::absolute(file, ec);
  if (ec) return std::nullopt;
  absolute = absolute.lexically_normal();
  if (!absolute.has_filename()) return std::nullopt;
  // Resolving the directory's symlinks makes two spellings of one directory share a watch.
  fs::path directory = fs::weakly_canonical(absolute.parent_path(), ec);
  if (ec) directory = absolute.parent_path();
  ResolvedPath r;
  r.directory = directory.string();
  r.name = absolute.filename().string();
  r.key = (directory / absolute.filename()).string();
  return r;
}

}  // namespace

struct FileWatcher::Impl {
  FileWatcherOptions options;
  WatchBackend active = WatchBackend::polling;
  std::unique_ptr<detail::InotifyQueue> inotify;  // null for the polling backend
  detail::WakeSource wake;
  detail::PendingChanges pending;
  DiagnosticSink diagnostics;
  FileWatcherStats stats;
  std::unordered_map<std::string, WatchedFile> files;
  std::unordered_map<std::string, WatchedDirectory> directories;
  // One inode watched under two spellings yields one descriptor, so it may map to several.
  std::unordered_map<int, std::vector<std::string>> wd_directories;
  size_t inotify_directories = 0;
  Clock::time_point next_scan;
  bool limit_reported = false;

  explicit Impl(FileWatcherOptions opts) : options(opts), pending(opts.coalesce_window, opts.close_grace) {
    if (options.backend != WatchBackend::polling) {
      inotify = std::make_unique<detail::InotifyQueue>();
      if (inotify->ok()) {
        active = WatchBackend::inotify;
        wake.add(inotify->fd());
      } else {
        diagnostics.warning("watch-inotify-unavailable", {},
                            std::string("inotify is unavailable (") + std::strerror(inotify->error()) +
                                "); watching files by polling every " + std::to_string(options.poll_interval.count()) +
                                " ms");
        inotify.reset();
      }
    }
    if (!wake.ok())
      diagnostics.warning("watch-handle-unavailable", {},
                          std::string("cannot create the watcher's wait handle (") + std::strerror(wake.error()) +
                              "); wait_handle() is -1");
    next_scan = Clock::now();
  }

  size_t polled_directories() const { return directories.size() - inotify_directories; }

  // Gives `dir` a kernel watch if possible; otherwise it stays polled.
  void try_attach(const std::string& key, WatchedDirectory& dir) {
    if (!inotify || dir.wd >= 0) return;
    if (options.backend == WatchBackend::automatic && detail::is_network_filesystem(key)) {
      if (!dir.network_reported)
        diagnostics.report(Severity::note, "watch-network-filesystem", {},
                           "'" + key +
                               "' is on a network file system where inotify misses "
                               "remote edits; polling it every " +
                               std::to_string(options.poll_interval.count()) + " ms");
      dir.network_reported = true;
      return;
    }
    if (inotify_directories >= options.max_inotify_directories) {
      report_limit(
          key, "the watcher's limit of " + std::to_string(options.max_inotify_directories) + " directories is reached");
      return;
    }
    int error = 0;
    int wd = inotify->add_directory(key, error);
    if (wd < 0) {
      if (error == ENOSPC)
        report_limit(key,
                     "the kernel's inotify watch limit is reached "
                     "(fs.inotify.max_user_watches)");
      else if (error != ENOENT && error != ENOTDIR)  // missing: retried at each scan
        diagnostics.warning("watch-directory-failed", {},
                            "cannot watch '" + key + "' (" + std::strerror(error) + "); polling it instead");
      return;
    }
    dir.wd = wd;
    ++inotify_directories;
    wd_directories[wd].push_back(key);
  }

  void report_limit(const std::string& key, const std::string& why) {
    if (limit_reported) return;  // one warning, not one per directory
    limit_reported = true;
    diagnostics.warning("watch-limit-reached", {},
                        "cannot watch '" + key + "': " + why + "; this and further directories are polled every " +
                            std::to_string(options.poll_interval.count()) + " ms");
  }

  // Drops `key`'s kernel watch (the directory stays watched by polling).
  void detach(const std::string& key, WatchedDirectory& dir, bool remove_kernel_watch) {
    if (dir.wd < 0) return;
    auto it = wd_directories.find(dir.wd);
    if (it != wd_directories.end()) {
      std::erase(it->second, key);
      if (it->second.empty()) {
        if (remove_kernel_watch) inotify->remove(dir.wd);
        wd_directories.erase(it);
      }
    }
    dir.wd = -1;
    --inotify_directories;
  }

  // The kernel watch no longer describes the path (directory deleted, moved or unmounted):
  // poll the path until it can be watched again, and re-check every file inside.
  void lose_watch(int wd, bool remove_kernel_watch, Clock::time_point now) {
    auto it = wd_directories.find(wd);
    if (it == wd_directories.end()) return;
    std::vector<std::string> keys = it->second;
    for (const std::string& key : keys) {
      WatchedDirectory& dir = directories[key];
      detach(key, dir, remove_kernel_watch);
      for (const auto& [name, file_key] : dir.names) pending.note(file_key, Activity::rescanned, now);
    }
  }

  void on_record(const detail::InotifyRecord& r, Clock::time_point now) {
    ++stats.notifications;
    if (r.mask & IN_Q_OVERFLOW) {
      ++stats.queue_overflows;
      size_t changed = compare_all(now);
      diagnostics.warning("watch-queue-overflow", {},
                          "the inotify queue overflowed; rescanned " + std::to_string(files.size()) + " files, " +
                              std::to_string(changed) + " changed");
      return;
    }
    if (r.mask & IN_IGNORED) return lose_watch(r.wd, false, now);
    if (r.mask & IN_MOVE_SELF) return lose_watch(r.wd, true, now);
    if (r.name.empty()) return;  // IN_DELETE_SELF: IN_IGNORED follows
    auto it = wd_directories.find(r.wd);
    if (it == wd_directories.end()) return;  // a watch removed before its records were read
    const std::string name(r.name);
    for (const std::string& dir_key : it->second) {
      const WatchedDirectory& dir = directories[dir_key];
      auto file = dir.names.find(name);
      if (file == dir.names.end()) continue;  // an unwatched sibling
      Activity activity = Activity::rescanned;
      if (r.mask & (IN_CLOSE_WRITE | IN_MOVED_TO)) activity = Activity::written;
      else if (r.mask & IN_CREATE) activity = Activity::created;
      else if (r.mask & (IN_DELETE | IN_MOVED_FROM)) activity = Activity::removed;
      pending.note(file->second, activity, now);
    }
  }

  // Snapshots one file; queues it if its content differs from the last comparison.
  bool compare(const std::string& key, WatchedFile& file, Clock::time_point now) {
    bool hashed = false;
    FileSnapshot current = detail::take_snapshot(key, &file.observed, &hashed);
    stats.files_hashed += hashed;
    bool differs = !current.same_content(file.observed);
    file.observed = current;
    if (differs) pending.note(key, Activity::rescanned, now);
    return differs;
  }

  size_t compare_all(Clock::time_point now) {
    ++stats.rescans;
    size_t changed = 0;
    for (auto& [key, file] : files) changed += compare(key, file, now);
    return changed;
  }

  // Re-attaches missing directories, then compares the files of every polled directory.
  void scan_polled(Clock::time_point now) {
    for (auto& [dir_key, dir] : directories) {
      if (dir.wd >= 0) continue;
      try_attach(dir_key, dir);  // before comparing, so no edit falls between the two
      for (const auto& [name, file_key] : dir.names) compare(file_key, files[file_key], now);
    }
  }

  std::vector<FileEvent> deliver(Clock::time_point now) {
    std::vector<FileEvent> events;
    for (const detail::PendingChanges::Ready& ready : pending.take_ready(now)) {
      auto it = files.find(ready.key);
      if (it == files.end()) continue;  // unwatched while settling
      WatchedFile& file = it->second;
      bool hashed = false;
      FileSnapshot current = detail::take_snapshot(ready.key, &file.observed, &hashed);
      stats.files_hashed += hashed;
      if (!current.readable && current.exists && file.delivered.readable)
        diagnostics.warning("watch-file-unreadable", {}, "cannot read '" + ready.key + "' to hash its content");
      std::optional<FileEventKind> kind;
      if (!current.exists) {
        if (file.delivered.exists) kind = FileEventKind::deleted;
      } else if (ready.written || !file.delivered.exists || !current.same_content(file.delivered)) {
        kind = FileEventKind::changed;
      }
      file.delivered = file.observed = current;
      if (kind) events.push_back({file.reported, *kind, ready.first_seen});
    }
    return events;
  }

  std::optional<Clock::time_point> next_deadline() const {
    std::optional<Clock::time_point> at = pending.next_deadline();
    if (polled_directories() && (!at || next_scan < *at)) at = next_scan;
    return at;
  }

  std::vector<FileEvent> poll(std::chrono::milliseconds timeout) {
    const Clock::time_point deadline = Clock::now() + timeout;
    // Consumes timer expiries and interrupts even when not blocking, so that an event loop
    // watching wait_handle() does not spin on a stale readable state.
    bool interrupted = wake.wait(std::chrono::milliseconds(0)) == detail::WakeSource::WaitResult::interrupted;
    std::vector<FileEvent> events;
    for (;;) {
      Clock::time_point now = Clock::now();
      if (inotify) inotify->drain([&](const detail::InotifyRecord& r) { on_record(r, now); });
      if (polled_directories() && now >= next_scan) {
        scan_polled(now);
        next_scan = now + options.poll_interval;
      }
      events = deliver(now);
      if (!events.empty() || interrupted || now >= deadline) break;
      Clock::time_point wake_at = deadline;
      if (auto at = next_deadline(); at && *at < wake_at) wake_at = *at;
      auto wait = std::chrono::ceil<std::chrono::milliseconds>(wake_at - now);
      interrupted = wake.wait(wait) == detail::WakeSource::WaitResult::interrupted;
    }
    wake.arm(next_deadline());
    return events;
  }

  bool watch(const fs::path& path) {
    std::optional<ResolvedPath> r = resolve(path);
    if (!r) {
      diagnostics.error("watch-bad-path", {}, "cannot watch '" + path.string() + "': not a file path");
      return false;
    }
    WatchedFile& file = files[r->key];
    if (file.refs++ > 0) return true;
    file.reported = path;
    file.directory = r->directory;
    WatchedDirectory& dir = directories[r->directory];
    dir.names[r->name] = r->key;
    if (dir.refs++ == 0) try_attach(r->directory, dir);
    // After the kernel watch exists, so an edit is either in the snapshot or reported.
    bool hashed = false;
    file.delivered = file.observed = detail::take_snapshot(r->key, nullptr, &hashed);
    stats.files_hashed += hashed;
    return true;
  }

  bool unwatch(const fs::path& path) {
    std::optional<ResolvedPath> r = resolve(path);
    if (!r) return false;
    auto it = files.find(r->key);
    if (it == files.end()) return false;
    if (--it->second.refs > 0) return true;
    const std::string dir_key = it->second.directory;
    files.erase(it);
    pending.forget(r->key);
    WatchedDirectory& dir = directories[dir_key];
    dir.names.erase(r->name);
    if (--dir.refs == 0) {
      detach(dir_key, dir, true);
      directories.erase(dir_key);
    }
    return true;
  }
};

FileWatcher::FileWatcher(FileWatcherOptions options) : impl_(std::make_unique<Impl>(options)) {}
FileWatcher::~FileWatcher() = default;
FileWatcher::FileWatcher(FileWatcher&&) noexcept = default;
FileWatcher& FileWatcher::operator=(FileWatcher&&) noexcept = default;

bool FileWatcher::watch(const std::filesystem::path& file) {
  bool ok = impl_->watch(file);
  impl_->wake.arm(impl_->next_deadline());  // a new polled directory wants its first scan
  return ok;
}
bool FileWatcher::unwatch(const std::filesystem::path& file) { return impl_->unwatch(file); }

bool FileWatcher::is_watched(const std::filesystem::path& file) const {
  std::optional<ResolvedPath> r = resolve(file);
  return r && impl_->files.count(r->key);
}

std::vector<FileEvent> FileWatcher::poll(std::chrono::milliseconds timeout) { return impl_->poll(timeout); }

std::size_t FileWatcher::rescan() {
  size_t changed = impl_->compare_all(Clock::now());
  impl_->wake.arm(impl_->next_deadline());
  return changed;
}

int FileWatcher::wait_handle() const { return impl_->wake.handle(); }

std::optional<std::chrono::steady_clock::time_point> FileWatcher::next_deadline() const {
  return impl_->next_deadline();
}

void FileWatcher::interrupt() { impl_->wake.interrupt(); }
WatchBackend FileWatcher::backend() const { return impl_->active; }
const DiagnosticSink& FileWatcher::diagnostics() const { return impl_->diagnostics; }

FileWatcherStats FileWatcher::stats() const {
  FileWatcherStats s = impl_->stats;
  s.files = impl_->files.size();
  s.inotify_directories = impl_->inotify_directories;
  s.polled_directories = impl_->polled_directories();
  return s;
}

}  // namespace fx
