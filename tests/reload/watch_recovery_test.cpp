// The watcher's recovery paths: kernel queue overflow, explicit rescans, watch limits,
// vanished directories, and the snapshot's racy-stat rule.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>

#include "file_snapshot.h"
#include "fx/reload/file_watcher.h"
#include "network_filesystem.h"
#include "watch_test_support.h"

namespace fx {
namespace {

using namespace std::chrono_literals;
using namespace fx::testing;

constexpr std::chrono::milliseconds kWindow = 20ms;

FileWatcherOptions fast(WatchBackend backend) {
  FileWatcherOptions o;
  o.backend = backend;
  o.coalesce_window = kWindow;
  o.poll_interval = 5ms;
  return o;
}

bool has_diagnostic(const FileWatcher& w, const std::string& id) {
  for (const Diagnostic& d : w.diagnostics().diagnostics())
    if (d.id == id) return true;
  return false;
}

size_t kernel_queue_limit() {
  std::ifstream in("/proc/sys/fs/inotify/max_queued_events");
  size_t limit = 0;
  in >> limit;
  return limit;
}

TEST(WatchRecovery, RealQueueOverflowRescansAndReportsOnlyWhatChanged) {
  size_t limit = kernel_queue_limit();
  if (limit == 0 || limit > (1u << 20)) GTEST_SKIP() << "inotify queue limit " << limit;
  ScratchDir dir;
  fs::path a = dir / "a.fx", b = dir / "b.fxh", c = dir / "c.fxh";
  for (const fs::path& p : {a, b, c}) save_truncate_write(p, "v1 " + p.filename().string());
  FileWatcher w(fast(WatchBackend::inotify));
  ASSERT_EQ(w.backend(), WatchBackend::inotify);
  for (const fs::path& p : {a, b, c}) ASSERT_TRUE(w.watch(p));
  save_truncate_write(a, "v2 a, longer");
  save_rename_over(b, "v2 b");
  // Flood the queue: each rename of an unwatched sibling queues MOVED_FROM + MOVED_TO,
  // and alternating names defeats the kernel's merging of identical records.
  fs::path x = dir / "x.tmp", y = dir / "y.tmp";
  save_truncate_write(x, "x");
  for (size_t i = 0; i < limit / 2 + 64; ++i) {
    fs::rename(x, y);
    fs::rename(y, x);
  }
  std::vector<FileEvent> events = wait_for_events(w);
  EXPECT_GE(w.stats().queue_overflows, 1u);
  EXPECT_GE(w.stats().rescans, 1u);
  EXPECT_TRUE(has_diagnostic(w, "watch-queue-overflow"));
  ASSERT_EQ(events.size(), 2u);
  std::vector<fs::path> paths{events[0].path, events[1].path};
  std::sort(paths.begin(), paths.end());
  EXPECT_EQ(paths, (std::vector<fs::path>{a, b}));
  EXPECT_TRUE(w.poll(3 * kWindow).empty());
}

TEST(WatchRecovery, ExplicitRescanFindsEditsPollingHasNotScannedYet) {
  ScratchDir dir;
  fs::path a = dir / "a.fx", b = dir / "b.fx";
  save_truncate_write(a, "v1");
  save_truncate_write(b, "v1");
  FileWatcherOptions o = fast(WatchBackend::polling);
  o.poll_interval = std::chrono::hours(1);  // only rescan() can notice anything
  FileWatcher w(o);
  ASSERT_TRUE(w.watch(a));
  ASSERT_TRUE(w.watch(b));
  EXPECT_TRUE(w.poll(0ms).empty());  // the first scan, at once
  save_truncate_write(a, "v2");
  EXPECT_TRUE(w.poll(3 * kWindow).empty());
  EXPECT_EQ(w.rescan(), 1u);
  std::vector<FileEvent> events = wait_for_events(w);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].path, a);
  EXPECT_EQ(w.rescan(), 0u);
}

TEST(WatchRecovery, SameSizeEditWithinOneClockTickIsSeenByPolling) {
  ScratchDir dir;
  fs::path a = dir / "a.fx";
  save_truncate_write(a, "AAAA");
  FileWatcher w(fast(WatchBackend::polling));
  ASSERT_TRUE(w.watch(a));
  save_truncate_write(a, "BBBB");  // same size; mtime may not move at coarse granularity
  std::vector<FileEvent> events = wait_for_events(w);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FileEventKind::changed);
}

TEST(WatchRecovery, DirectoriesOverTheWatchLimitArePolled) {
  ScratchDir one, two;
  fs::path a = one / "a.fx", b = two / "b.fxh";
  save_truncate_write(a, "a");
  save_truncate_write(b, "b");
  FileWatcherOptions o = fast(WatchBackend::inotify);
  o.max_inotify_directories = 1;
  FileWatcher w(o);
  ASSERT_TRUE(w.watch(a));
  ASSERT_TRUE(w.watch(b));
  EXPECT_EQ(w.stats().inotify_directories, 1u);
  EXPECT_EQ(w.stats().polled_directories, 1u);
  EXPECT_TRUE(has_diagnostic(w, "watch-limit-reached"));
  save_truncate_write(b, "b2");
  std::vector<FileEvent> events = wait_for_events(w);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].path, b);
  EXPECT_TRUE(w.poll(3 * kWindow).empty());
}

TEST(WatchRecovery, DeletedDirectoryIsReportedAndWatchedAgainWhenRecreated) {
  ScratchDir root;
  fs::path sub = root / "effects";
  fs::create_directory(sub);
  fs::path a = sub / "a.fx";
  save_truncate_write(a, "v1");
  FileWatcher w(fast(WatchBackend::inotify));
  ASSERT_TRUE(w.watch(a));
  fs::remove_all(sub);
  std::vector<FileEvent> events = wait_for_events(w);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FileEventKind::deleted);
  EXPECT_EQ(w.stats().polled_directories, 1u);
  fs::create_directory(sub);
  save_truncate_write(a, "v2");
  events = wait_for_events(w);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FileEventKind::changed);
  EXPECT_EQ(w.stats().inotify_directories, 1u);  // re-attached by the scan
  save_truncate_write(a, "v3");                  // and now seen through inotify again
  events = wait_for_events(w);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FileEventKind::changed);
}

TEST(WatchRecovery, MissingDirectoryIsWatchedOnceItAppears) {
  ScratchDir root;
  fs::path a = root / "later" / "a.fx";
  FileWatcher w(fast(WatchBackend::inotify));
  ASSERT_TRUE(w.watch(a));
  EXPECT_EQ(w.stats().polled_directories, 1u);
  EXPECT_FALSE(has_diagnostic(w, "watch-directory-failed"));
  fs::create_directory(root / "later");
  save_truncate_write(a, "v1");
  std::vector<FileEvent> events = wait_for_events(w);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FileEventKind::changed);
}

TEST(WatchRecovery, AutomaticPollsNetworkFileSystemsAndWatchesLocalOnes) {
  EXPECT_TRUE(detail::is_network_filesystem_type(0x6969));       // NFS
  EXPECT_TRUE(detail::is_network_filesystem_type(0xFF534D42));   // CIFS
  EXPECT_TRUE(detail::is_network_filesystem_type(0x01021997));   // 9p (WSL2 /mnt/c)
  EXPECT_FALSE(detail::is_network_filesystem_type(0xEF53));      // ext4
  EXPECT_FALSE(detail::is_network_filesystem_type(0x01021994));  // tmpfs
  ScratchDir dir;
  FileWatcher w(fast(WatchBackend::automatic));
  ASSERT_EQ(w.backend(), WatchBackend::inotify);
  ASSERT_TRUE(w.watch(dir / "a.fx"));
  bool remote = detail::is_network_filesystem(dir.path().string());
  EXPECT_EQ(w.stats().polled_directories, remote ? 1u : 0u);
  EXPECT_EQ(has_diagnostic(w, "watch-network-filesystem"), remote);
}

TEST(FileSnapshot, StatVouchesForContentOnlyWhenNotRacy) {
  ScratchDir dir;
  fs::path a = dir / "a.fx";
  save_truncate_write(a, "content");
  bool hashed = false;
  detail::FileSnapshot fresh = detail::take_snapshot(a.string(), nullptr, &hashed);
  EXPECT_TRUE(hashed);
  EXPECT_TRUE(fresh.racy());  // written just now
  detail::take_snapshot(a.string(), &fresh, &hashed);
  EXPECT_TRUE(hashed) << "a racy snapshot must not vouch for unchanged content";

  // Backdate the file: its stat can now stand for its content.
  timespec old[2] = {{1'000'000'000, 0}, {1'000'000'000, 0}};
  ASSERT_EQ(utimensat(AT_FDCWD, a.c_str(), old, 0), 0);
  detail::FileSnapshot settled = detail::take_snapshot(a.string(), nullptr, &hashed);
  EXPECT_FALSE(settled.racy());
  detail::FileSnapshot again = detail::take_snapshot(a.string(), &settled, &hashed);
  EXPECT_FALSE(hashed);
  EXPECT_TRUE(again.same_content(settled));

  // Same size and a restored mtime (cp -p, tar): ctime still moves, so it is re-hashed.
  save_truncate_write(a, "CONTENT");
  ASSERT_EQ(utimensat(AT_FDCWD, a.c_str(), old, 0), 0);
  detail::FileSnapshot edited = detail::take_snapshot(a.string(), &settled, &hashed);
  EXPECT_TRUE(hashed);
  EXPECT_FALSE(edited.same_content(settled));
}

TEST(FileSnapshot, MissingFileAndDirectoryAreAbsent) {
  ScratchDir dir;
  EXPECT_FALSE(detail::take_snapshot((dir / "none").string(), nullptr).exists);
  EXPECT_FALSE(detail::take_snapshot(dir.path().string(), nullptr).exists);
  detail::FileSnapshot none;
  EXPECT_TRUE(none.same_content(detail::take_snapshot((dir / "none").string(), nullptr)));
}

}  // namespace
}  // namespace fx
