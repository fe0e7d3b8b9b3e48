// `fxkit check --cache DIR`: check results by a content hash of the effect, everything it
// includes and the options, so a run over an unchanged folder only reads and hashes files.
// SPIR-V lives beside them (DIR/spirv, fx::SpirvCache), so a changed effect recompiles only
// the shaders whose text changed. The folder is bounded: the least recently used entries
// go first.
#pragma once
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "effect_check.h"

namespace fx::tools {

struct CheckCacheStats {
  uint64_t hits = 0, misses = 0, stores = 0, evicted = 0;
};

// find() and store() may be called from several threads at once (for different files).
class CheckCache {
 public:
  // `options` names everything besides the files that changes a result (flags, fxkit's
  // build); `limit_bytes` bounds the folder after evict().
  CheckCache(std::filesystem::path directory, std::string options, uint64_t limit_bytes);

  // The stored result for `file` when it and every file it read are unchanged.
  std::optional<EffectCheck> find(const std::string& file);
  // Stores a result (written to a temporary file and renamed: readers never see half).
  void store(const EffectCheck& check);
  // Removes the least recently used files until the folder holds at most the limit.
  void evict();

  std::filesystem::path spirv_directory() const { return directory_ / "spirv"; }
  CheckCacheStats stats() const;

 private:
  std::optional<std::filesystem::path> entry_path(const std::string& file);

  std::filesystem::path directory_;
  std::string options_;
  uint64_t limit_bytes_;
  std::atomic<uint64_t> hits_{0}, misses_{0}, stores_{0}, evicted_{0};
};

// A hash of `text` as 32 hex digits (xxh3-128).
std::string content_hash(std::string_view text);

}  // namespace fx::tools
