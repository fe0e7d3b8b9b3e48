// Behaviour of fx::FileWatcher, run against both backends with real files.
#include "fx/reload/file_watcher.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/stat.h>

#include <algorithm>
#include <thread>

#include "watch_test_support.h"

namespace fx {
namespace {

using namespace std::chrono_literals;
using namespace fx::testing;

// Short enough to keep the suite fast; the save patterns finish before poll() runs, so the
// window's length does not decide correctness here.
constexpr std::chrono::milliseconds kWindow = 20ms;

class FileWatcherTest : public ::testing::TestWithParam<WatchBackend> {
 protected:
  FileWatcherOptions options() const {
    FileWatcherOptions o;
    o.backend = GetParam();
    o.coalesce_window = kWindow;
    o.poll_interval = 5ms;
    return o;
  }
  // After an event settled, nothing more may follow for a few windows.
  static void expect_quiet(FileWatcher& w) {
    std::vector<FileEvent> more = w.poll(3 * kWindow);
    EXPECT_TRUE(more.empty()) << "unexpected event for " << more.front().path;
  }
  static void expect_one(const std::vector<FileEvent>& events, const fs::path& path, FileEventKind kind) {
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].path, path);
    EXPECT_EQ(events[0].kind, kind) << to_string(events[0].kind);
  }

  ScratchDir dir;
};

TEST_P(FileWatcherTest, UsesTheRequestedBackend) {
  FileWatcher w(options());
  EXPECT_EQ(w.backend(), GetParam());
  EXPECT_EQ(w.diagnostics().diagnostics().size(), 0u);
}

TEST_P(FileWatcherTest, TruncateAndWriteIsOneChange) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "technique t {}");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  save_truncate_write(fx, "technique t { pass p {} }");
  expect_one(wait_for_events(w), fx, FileEventKind::changed);
  expect_quiet(w);
}

TEST_P(FileWatcherTest, WriteTempAndRenameOverIsOneChange) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "old");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  save_rename_over(fx, "new content");
  expect_one(wait_for_events(w), fx, FileEventKind::changed);
  expect_quiet(w);
}

TEST_P(FileWatcherTest, BackupRenameIsOneChange) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "old");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  save_backup_rename(fx, "new content");
  expect_one(wait_for_events(w), fx, FileEventKind::changed);
  expect_quiet(w);
}

TEST_P(FileWatcherTest, OnlyTheEditedFileIsReported) {
  fs::path a = dir / "a.fx", b = dir / "common.fxh";
  save_truncate_write(a, "a");
  save_truncate_write(b, "b");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(a));
  ASSERT_TRUE(w.watch(b));
  EXPECT_EQ(w.stats().files, 2u);
  save_rename_over(b, "b2");
  expect_one(wait_for_events(w), b, FileEventKind::changed);
  expect_quiet(w);
}

TEST_P(FileWatcherTest, EditingAnUnwatchedSiblingReportsNothing) {
  fs::path a = dir / "a.fx", sibling = dir / "notes.txt";
  save_truncate_write(a, "a");
  save_truncate_write(sibling, "x");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(a));
  save_truncate_write(sibling, "y");
  save_rename_over(sibling, "z");
  save_backup_rename(sibling, "w");
  EXPECT_TRUE(w.poll(4 * kWindow).empty());
}

TEST_P(FileWatcherTest, DeleteThenRecreate) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "v1");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  fs::remove(fx);
  expect_one(wait_for_events(w), fx, FileEventKind::deleted);
  expect_quiet(w);
  save_truncate_write(fx, "v2");
  expect_one(wait_for_events(w), fx, FileEventKind::changed);
  expect_quiet(w);
}

TEST_P(FileWatcherTest, DeleteAndRecreateWithinTheWindowIsOneChange) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "v1");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  fs::remove(fx);
  save_truncate_write(fx, "v2");
  expect_one(wait_for_events(w), fx, FileEventKind::changed);
  expect_quiet(w);
}

TEST_P(FileWatcherTest, FileCreatedAfterWatchIsAChange) {
  fs::path fx = dir / "later.fxh";
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  EXPECT_TRUE(w.poll(0ms).empty());
  save_truncate_write(fx, "#define X 1");
  expect_one(wait_for_events(w), fx, FileEventKind::changed);
  expect_quiet(w);
}

TEST_P(FileWatcherTest, TouchWithoutNewContentIsNotAnEdit) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "same");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  timespec times[2] = {{0, UTIME_NOW}, {0, UTIME_NOW}};
  ASSERT_EQ(utimensat(AT_FDCWD, fx.c_str(), times, 0), 0);
  EXPECT_TRUE(w.poll(4 * kWindow).empty());
}

TEST_P(FileWatcherTest, FilesInTwoDirectories) {
  ScratchDir other;
  fs::path a = dir / "a.fx", b = other / "b.fxh";
  save_truncate_write(a, "a");
  save_truncate_write(b, "b");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(a));
  ASSERT_TRUE(w.watch(b));
  save_truncate_write(a, "a2");
  save_rename_over(b, "b2");
  std::vector<FileEvent> events = wait_for_events(w);
  // Both were edited before the first poll, so both settle in the same poll.
  ASSERT_EQ(events.size(), 2u);
  std::vector<fs::path> paths{events[0].path, events[1].path};
  std::sort(paths.begin(), paths.end());
  std::vector<fs::path> expected{a, b};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(paths, expected);
  expect_quiet(w);
}

TEST_P(FileWatcherTest, WatchIsReferenceCountedAndUnwatchStopsReports) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "v1");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  ASSERT_TRUE(w.watch(dir.path() / "." / "a.fx"));  // another spelling, same file
  EXPECT_EQ(w.stats().files, 1u);
  ASSERT_TRUE(w.unwatch(fx));
  EXPECT_TRUE(w.is_watched(fx));
  save_truncate_write(fx, "v2");
  expect_one(wait_for_events(w), fx, FileEventKind::changed);
  ASSERT_TRUE(w.unwatch(fx));
  EXPECT_FALSE(w.is_watched(fx));
  EXPECT_FALSE(w.unwatch(fx));
  EXPECT_EQ(w.stats().inotify_directories + w.stats().polled_directories, 0u);
  save_truncate_write(fx, "v3");
  EXPECT_TRUE(w.poll(4 * kWindow).empty());
}

TEST_P(FileWatcherTest, BurstOfTwentyWritesIsOneEvent) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "v0");
  FileWatcherOptions o = options();
  o.coalesce_window = 150ms;  // long enough that the burst is certainly inside it
  FileWatcher w(o);
  ASSERT_TRUE(w.watch(fx));
  std::vector<FileEvent> seen;
  auto start = std::chrono::steady_clock::now();
  for (int i = 1; i <= 20; ++i) {
    save_truncate_write(fx, std::string("v").append(std::to_string(i)));
    // Polling between writes lets the watcher see the burst as it happens.
    for (FileEvent& e : w.poll(0ms)) seen.push_back(e);
  }
  auto burst = std::chrono::steady_clock::now() - start;
  if (burst > o.coalesce_window / 2) GTEST_SKIP() << "machine too loaded to time a burst";
  EXPECT_TRUE(seen.empty());
  std::vector<FileEvent> events = wait_for_events(w);
  auto delivered = std::chrono::steady_clock::now();
  expect_one(events, fx, FileEventKind::changed);
  // Delivered only once the file had been quiet for the window.
  EXPECT_GE(delivered - start, o.coalesce_window);
  EXPECT_LE(events[0].detected_at, start + burst);
  EXPECT_TRUE(w.poll(50ms).empty());
}

TEST_P(FileWatcherTest, InterruptWakesABlockedPoll) {
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(dir / "a.fx"));
  auto start = std::chrono::steady_clock::now();
  std::thread other([&] { w.interrupt(); });
  std::vector<FileEvent> events = w.poll(10s);
  other.join();
  EXPECT_TRUE(events.empty());
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
}

TEST_P(FileWatcherTest, WaitHandleSignalsSettledEvents) {
  fs::path fx = dir / "a.fx";
  save_truncate_write(fx, "v1");
  FileWatcher w(options());
  ASSERT_TRUE(w.watch(fx));
  int handle = w.wait_handle();
  ASSERT_GE(handle, 0);
  save_rename_over(fx, "v2");
  // An application loop: block on the handle, then poll without blocking.
  std::vector<FileEvent> events;
  const auto give_up = std::chrono::steady_clock::now() + fx::testing::patience();
  while (events.empty() && std::chrono::steady_clock::now() < give_up) {
    pollfd p{handle, POLLIN, 0};
    ASSERT_GE(::poll(&p, 1, 1000), 0);
    events = w.poll(0ms);
  }
  expect_one(events, fx, FileEventKind::changed);
  // Nothing pending any more: the handle must not stay readable (no busy loop).
  w.poll(0ms);
  if (GetParam() == WatchBackend::inotify) {  // polling keeps a scan deadline by design
    EXPECT_FALSE(w.next_deadline());
    pollfd p{handle, POLLIN, 0};
    EXPECT_EQ(::poll(&p, 1, 0), 0);
  }
}

TEST_P(FileWatcherTest, EmptyPathIsADiagnosticNotACrash) {
  FileWatcher w(options());
  EXPECT_FALSE(w.watch(dir.path() / ""));
  ASSERT_EQ(w.diagnostics().diagnostics().size(), 1u);
  EXPECT_EQ(w.diagnostics().diagnostics()[0].id, "watch-bad-path");
}

INSTANTIATE_TEST_SUITE_P(Backends, FileWatcherTest, ::testing::Values(WatchBackend::inotify, WatchBackend::polling),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace fx
