#include "inotify_queue.h"

#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace fx::detail {

const uint32_t InotifyQueue::kDirectoryMask =
    IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE | IN_DELETE | IN_DELETE_SELF | IN_MOVE_SELF | IN_ONLYDIR;

InotifyQueue::InotifyQueue() {
  fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd_ < 0) error_ = errno;
}

InotifyQueue::~InotifyQueue() {
  if (fd_ >= 0) ::close(fd_);
}

int InotifyQueue::add_directory(const std::string& directory, int& error) {
  int wd = inotify_add_watch(fd_, directory.c_str(), kDirectoryMask);
  error = wd < 0 ? errno : 0;
  return wd;
}

void InotifyQueue::remove(int wd) {
  // Fails harmlessly when the kernel already dropped the watch (directory deleted).
  inotify_rm_watch(fd_, wd);
}

size_t InotifyQueue::drain(const std::function<void(const InotifyRecord&)>& on_record) {
  if (fd_ < 0) return 0;
  // Big enough for many records; the kernel never splits a record across reads.
  alignas(struct inotify_event) char buffer[16 * 1024];
  size_t count = 0;
  for (;;) {
    ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // EAGAIN: queue empty
    for (size_t at = 0; at + sizeof(inotify_event) <= size_t(n);) {
      inotify_event header;
      std::memcpy(&header, buffer + at, sizeof header);
      const char* name = buffer + at + sizeof(inotify_event);
      InotifyRecord record{header.wd, header.mask,
                           header.len ? std::string_view(name, strnlen(name, header.len)) : std::string_view()};
      on_record(record);
      ++count;
      at += sizeof(inotify_event) + header.len;
    }
  }
  return count;
}

}  // namespace fx::detail
