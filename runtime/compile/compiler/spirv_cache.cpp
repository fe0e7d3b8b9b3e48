#include "fx/compile/spirv_cache.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>
#include <thread>

#include <unistd.h>

#define XXH_INLINE_ALL  // xxHash header-only: fxkit links no libxxhash
#include <xxhash.h>

#include "shader_serialize.h"

namespace fx {
namespace {

// On-disk entry: header, SPIR-V words, then the metadata JSON (entry point, reflection,
// messages). The format version changes whenever the layout or the JSON schema does.
constexpr char kMagic[8] = {'F', 'X', 'S', 'P', 'I', 'R', 'V', '\0'};
constexpr uint32_t kFormatVersion = 5;

struct FileHeader {
  char magic[8];
  uint32_t format_version;
  uint32_t reserved;
  uint64_t key_low, key_high;
  uint64_t spirv_bytes, meta_bytes;
  uint64_t checksum;  // xxh3-64 of everything after the header
};
static_assert(sizeof(FileHeader) == 56);

void hash_field(XXH3_state_t* state, std::string_view bytes) {
  // Length first, so ("ab","c") and ("a","bc") hash differently.
  uint64_t size = bytes.size();
  XXH3_128bits_update(state, &size, sizeof size);
  XXH3_128bits_update(state, bytes.data(), bytes.size());
}

constexpr std::string_view kHexDigits = "0123456789abcdef";

}  // namespace

std::string SpirvCacheKey::hex() const {
  std::string s(32, '0');
  for (int i = 0; i < 16; ++i) {
    s[static_cast<size_t>(15 - i)] = kHexDigits[(high >> (4 * i)) & 0xf];
    s[static_cast<size_t>(31 - i)] = kHexDigits[(low >> (4 * i)) & 0xf];
  }
  return s;
}

SpirvCacheKey spirv_cache_key(const TranslationUnit& unit, const CompileOptions& options) {
  XXH3_state_t* state = XXH3_createState();
  if (!state) return {};
  XXH3_128bits_reset(state);
  hash_field(state, "fxkit-spirv-cache-1");
  hash_field(state, ShaderCompiler::glslang_version());
  hash_field(state, unit.source);
  hash_field(state, to_string(unit.stage));
  hash_field(state, to_string(unit.language));
  hash_field(state, unit.entry_point);
  hash_field(state, unit.profile);
  // The name appears in messages glslang writes before the first #line.
  hash_field(state, unit.name);
  for (const ShaderDefine& d : unit.defines) {
    hash_field(state, d.name);
    hash_field(state, d.value);
  }
  const uint8_t opts[] = {static_cast<uint8_t>(options.target), options.debug_info, options.keep_hlsl_semantics,
                          options.warnings_as_errors, options.validate};
  hash_field(state, std::string_view(reinterpret_cast<const char*>(opts), sizeof opts));
  XXH128_hash_t h = XXH3_128bits_digest(state);
  XXH3_freeState(state);
  return {h.low64, h.high64};
}

SpirvCache::SpirvCache(std::filesystem::path directory, size_t memory_budget)
    : directory_(std::move(directory)), memory_budget_(memory_budget) {}

namespace {

// What an entry holds, roughly: its words, its log and a flat allowance for reflection.
size_t entry_bytes(const CompiledShader& s) {
  return sizeof(CompiledShader) + s.spirv.size() * sizeof(uint32_t) + s.info_log.size() + 1024;
}

}  // namespace

void SpirvCache::remember(const SpirvCacheKey& key, const CompiledShader& shader) {
  if (auto it = memory_.find(key); it != memory_.end()) {
    stats_.memory_bytes -= it->second.bytes;
    lru_.erase(it->second.use);
    memory_.erase(it);
  }
  const size_t bytes = entry_bytes(shader);
  if (bytes > memory_budget_) return;
  lru_.push_front(key);
  memory_.emplace(key, Entry{shader, bytes, lru_.begin()});
  stats_.memory_bytes += bytes;
  while (stats_.memory_bytes > memory_budget_ && !lru_.empty()) {
    auto victim = memory_.find(lru_.back());
    stats_.memory_bytes -= victim->second.bytes;
    memory_.erase(victim);
    lru_.pop_back();
    ++stats_.evictions;
  }
}

std::optional<CompiledShader> SpirvCache::find(const SpirvCacheKey& key) {
  {
    std::lock_guard lock(mutex_);
    auto it = memory_.find(key);
    if (it != memory_.end()) {
      ++stats_.memory_hits;
      lru_.splice(lru_.begin(), lru_, it->second.use);
      return it->second.shader;
    }
  }
  if (!directory_.empty()) {
    if (std::optional<CompiledShader> loaded = load_file(key)) {
      std::lock_guard lock(mutex_);
      ++stats_.disk_hits;
      remember(key, *loaded);
      return loaded;
    }
  }
  std::lock_guard lock(mutex_);
  ++stats_.misses;
  return std::nullopt;
}

void SpirvCache::store(const SpirvCacheKey& key, const CompiledShader& shader) {
  if (!shader.ok) return;
  {
    std::lock_guard lock(mutex_);
    ++stats_.stores;
    remember(key, shader);
  }
  if (!directory_.empty()) write_file(key, shader);
}

void SpirvCache::clear_memory() {
  std::lock_guard lock(mutex_);
  memory_.clear();
  lru_.clear();
  stats_.memory_bytes = 0;
}

SpirvCacheStats SpirvCache::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

std::optional<CompiledShader> SpirvCache::load_file(const SpirvCacheKey& key) {
  std::filesystem::path path = directory_ / (key.hex() + ".spvc");
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  auto reject = [&]() -> std::optional<CompiledShader> {
    std::lock_guard lock(mutex_);
    ++stats_.disk_rejects;
    return std::nullopt;
  };
  std::error_code ec;
  uint64_t file_size = std::filesystem::file_size(path, ec);
  FileHeader h{};
  if (ec || file_size < sizeof h || !in.read(reinterpret_cast<char*>(&h), sizeof h)) return reject();
  if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 || h.format_version != kFormatVersion || h.key_low != key.low ||
      h.key_high != key.high || h.spirv_bytes % 4 != 0 || h.spirv_bytes > file_size || h.meta_bytes > file_size ||
      sizeof h + h.spirv_bytes + h.meta_bytes != file_size)
    return reject();
  std::string payload(h.spirv_bytes + h.meta_bytes, '\0');
  if (!in.read(payload.data(), static_cast<std::streamsize>(payload.size()))) return reject();
  if (XXH3_64bits(payload.data(), payload.size()) != h.checksum) return reject();
  CompiledShader shader;
  shader.spirv.resize(h.spirv_bytes / 4);
  std::memcpy(shader.spirv.data(), payload.data(), h.spirv_bytes);
  if (!read_shader_metadata(std::string_view(payload).substr(h.spirv_bytes), shader)) return reject();
  shader.ok = true;
  return shader;
}

void SpirvCache::write_file(const SpirvCacheKey& key, const CompiledShader& shader) {
  std::error_code ec;
  std::filesystem::create_directories(directory_, ec);
  std::string meta = write_shader_metadata(shader);
  std::string payload(reinterpret_cast<const char*>(shader.spirv.data()), shader.spirv.size() * 4);
  payload += meta;
  FileHeader h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.format_version = kFormatVersion;
  h.key_low = key.low, h.key_high = key.high;
  h.spirv_bytes = shader.spirv.size() * 4;
  h.meta_bytes = meta.size();
  h.checksum = XXH3_64bits(payload.data(), payload.size());
  // A per-process, per-thread temp name: concurrent writers of one key each rename a
  // complete file, and the last rename wins with identical contents.
  std::filesystem::path final_path = directory_ / (key.hex() + ".spvc");
  std::filesystem::path temp = directory_ / (key.hex() + ".tmp" + std::to_string(getpid()) + "-" +
                                             std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())));
  bool written = false;
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    written = static_cast<bool>(out.flush());
  }
  if (written) std::filesystem::rename(temp, final_path, ec);
  if (!written || ec) {
    std::filesystem::remove(temp, ec);
    std::lock_guard lock(mutex_);
    ++stats_.disk_write_errors;
  }
}

}  // namespace fx
