#include "file_snapshot.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>

#define XXH_INLINE_ALL  // xxHash header-only: fxkit links no libxxhash
#include <xxhash.h>

namespace fx::detail {
namespace {

// Larger than any file-system timestamp granularity (FAT: 2 s) plus the lag of the
// kernel's coarse clock behind clock_gettime.
constexpr int64_t kRacyMarginNs = 3'000'000'000;

int64_t to_ns(const timespec& t) { return int64_t(t.tv_sec) * 1'000'000'000 + t.tv_nsec; }

int64_t wall_clock_ns() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return to_ns(now);
}

// Streams the file through XXH3; false if it cannot be opened or read.
bool hash_file(const std::string& path, uint64_t& hash) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  XXH3_state_t state;
  XXH3_64bits_reset(&state);
  char buffer[64 * 1024];
  bool ok = true;
  for (;;) {
    ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      ok = false;
      break;
    }
    XXH3_64bits_update(&state, buffer, size_t(n));
  }
  ::close(fd);
  hash = XXH3_64bits_digest(&state);
  return ok;
}

}  // namespace

bool FileSnapshot::same_content(const FileSnapshot& other) const {
  if (exists != other.exists) return false;
  if (!exists) return true;
  return readable == other.readable && size == other.size && content_hash == other.content_hash;
}

bool FileSnapshot::same_stat(const FileSnapshot& other) const {
  return exists == other.exists && device == other.device && inode == other.inode && size == other.size &&
         mtime_ns == other.mtime_ns && ctime_ns == other.ctime_ns;
}

bool FileSnapshot::racy() const { return mtime_ns >= taken_at_ns - kRacyMarginNs; }

FileSnapshot take_snapshot(const std::string& path, const FileSnapshot* previous, bool* hashed) {
  if (hashed) *hashed = false;
  FileSnapshot snap;
  snap.taken_at_ns = wall_clock_ns();
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return snap;
  snap.exists = true;
  snap.device = uint64_t(st.st_dev);
  snap.inode = uint64_t(st.st_ino);
  snap.size = uint64_t(st.st_size);
  snap.mtime_ns = to_ns(st.st_mtim);
  snap.ctime_ns = to_ns(st.st_ctim);
  if (previous && previous->exists && previous->same_stat(snap) && !previous->racy()) {
    snap.readable = previous->readable;
    snap.content_hash = previous->content_hash;
    return snap;
  }
  snap.readable = hash_file(path, snap.content_hash);
  if (hashed) *hashed = true;
  return snap;
}

}  // namespace fx::detail
