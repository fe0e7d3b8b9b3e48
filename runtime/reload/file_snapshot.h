// What a file looked like at one moment: identity, size, times and a content hash.
#pragma once
#include <cstdint>
#include <string>

namespace fx::detail {

struct FileSnapshot {
  bool exists = false;
  bool readable = false;  // false if it exists but could not be read (hash then invalid)
  uint64_t device = 0, inode = 0, size = 0;
  int64_t mtime_ns = 0, ctime_ns = 0;
  uint64_t content_hash = 0;
  int64_t taken_at_ns = 0;  // wall clock (the clock file times use) when taken

  // Same existence and content; times and identity do not matter (a touch is no edit).
  bool same_content(const FileSnapshot& other) const;
  // Same inode, size and times as `other`.
  bool same_stat(const FileSnapshot& other) const;
  // Whether the file was modified so close to when the snapshot was taken that a later
  // edit could leave mtime unchanged (coarse kernel clocks, 2 s FAT times): its stat
  // cannot vouch for its content, so the next comparison must hash.
  bool racy() const;
};

// Stats and hashes `path`. When `previous` has the same stat and is not racy its hash is
// reused without reading the file; `hashed` (optional) says whether the file was read.
FileSnapshot take_snapshot(const std::string& path, const FileSnapshot* previous, bool* hashed = nullptr);

}  // namespace fx::detail
