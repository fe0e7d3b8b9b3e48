// Compiled shaders keyed by a hash of everything that affects them: in memory and,
// optionally, in a directory that survives the process.
#pragma once
#include <cstdint>
#include <filesystem>
#include <list>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

#include "fx/compile/shader_compiler.h"

namespace fx {

// xxh3-128 of (source, stage, language, entry point, profile, defines, options, glslang version).
struct SpirvCacheKey {
  uint64_t low = 0, high = 0;
  std::string hex() const;  // 32 hex digits: the on-disk file name
  friend bool operator==(const SpirvCacheKey&, const SpirvCacheKey&) = default;
};

// The key of `unit` compiled with `options` by this build's glslang.
SpirvCacheKey spirv_cache_key(const TranslationUnit& unit, const CompileOptions& options);

// Counters for tests and the CLI's --stats.
struct SpirvCacheStats {
  uint64_t memory_hits = 0, disk_hits = 0, misses = 0, stores = 0;
  uint64_t disk_rejects = 0;       // files with a bad header, size or checksum (then replaced)
  uint64_t disk_write_errors = 0;  // the directory was not writable; memory still works
  uint64_t evictions = 0;          // in-memory entries dropped to stay within the budget
  uint64_t memory_bytes = 0;       // what the in-memory entries hold now (estimated)
};

// Thread-safe. Only successful compiles are stored. The in-memory entries are bounded by a
// byte budget: past it the least recently used go (the disk keeps them). Disk entries are written to a temp file
// and renamed, so a reader never sees half a file; every entry is checked (magic, format
// version, key, sizes, xxh3-64 checksum) before use.
class SpirvCache {
 public:
  // The in-memory budget by default: a few thousand shaders.
  static constexpr size_t kDefaultMemoryBudget = size_t{64} << 20;
  // `directory` empty: memory only. The directory is created on the first store.
  explicit SpirvCache(std::filesystem::path directory = {}, size_t memory_budget = kDefaultMemoryBudget);

  std::optional<CompiledShader> find(const SpirvCacheKey& key);
  void store(const SpirvCacheKey& key, const CompiledShader& shader);
  // Drops the in-memory entries (disk entries stay): simulates a new process in tests.
  void clear_memory();

  SpirvCacheStats stats() const;
  const std::filesystem::path& directory() const { return directory_; }

 private:
  struct KeyHash {
    size_t operator()(const SpirvCacheKey& k) const { return static_cast<size_t>(k.low ^ (k.high * 31)); }
  };
  struct Entry {
    CompiledShader shader;
    size_t bytes = 0;
    std::list<SpirvCacheKey>::iterator use;  // its place in lru_
  };
  // Keeps `shader` in memory as the most recently used, then evicts down to the budget.
  // Called with mutex_ held.
  void remember(const SpirvCacheKey& key, const CompiledShader& shader);
  std::optional<CompiledShader> load_file(const SpirvCacheKey& key);
  void write_file(const SpirvCacheKey& key, const CompiledShader& shader);

  std::filesystem::path directory_;
  mutable std::mutex mutex_;
  size_t memory_budget_;
  std::unordered_map<SpirvCacheKey, Entry, KeyHash> memory_;
  std::list<SpirvCacheKey> lru_;  // most recently used first
  SpirvCacheStats stats_;
};

}  // namespace fx
