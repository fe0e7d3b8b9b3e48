#define XXH_INLINE_ALL
#include "check_cache.h"

#include <xxhash.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "tool_output.h"

namespace fx::tools {
namespace {

namespace fs = std::filesystem;
constexpr int kCacheEntryFormat = 1;  // bumped when the entry's shape changes

std::optional<std::string> read_whole_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string content_hash(std::string_view text) {
  XXH128_hash_t h = XXH3_128bits(text.data(), text.size());
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return hex;
}

CheckCache::CheckCache(fs::path directory, std::string options, uint64_t limit_bytes)
    : directory_(std::move(directory)), options_(std::move(options)), limit_bytes_(limit_bytes) {}

std::optional<fs::path> CheckCache::entry_path(const std::string& file) {
  std::optional<std::string> text = read_whole_file(file);
  if (!text) return std::nullopt;
  std::string key = options_ + '\0' + file + '\0' + content_hash(*text);
  return directory_ / "results" / (content_hash(key) + ".json");
}

std::optional<EffectCheck> CheckCache::find(const std::string& file) {
  std::optional<fs::path> path = entry_path(file);
  std::optional<std::string> text = path ? read_whole_file(*path) : std::nullopt;
  nlohmann::json entry = text ? nlohmann::json::parse(*text, nullptr, false) : nlohmann::json();
  EffectCheck check;
  bool fresh = entry.is_object() && entry.value("format", 0) == kCacheEntryFormat && entry.contains("hashes") &&
               from_json(entry["result"], check) && check.file == file;
  // The includes as they were read then: the same contents, or the result is stale.
  for (size_t i = 1; fresh && i < check.files.size(); ++i) {
    std::optional<std::string> now = read_whole_file(check.files[i]);
    fresh = now && entry["hashes"].size() == check.files.size() && entry["hashes"][i] == content_hash(*now);
  }
  if (!fresh) {
    ++misses_;
    return std::nullopt;
  }
  std::error_code ec;
  fs::last_write_time(*path, fs::file_time_type::clock::now(), ec);  // recently used: evicted last
  ++hits_;
  check.from_cache = true;
  return check;
}

void CheckCache::store(const EffectCheck& check) {
  std::optional<fs::path> path = entry_path(check.file);
  if (!path) return;
  nlohmann::json hashes = nlohmann::json::array();
  for (const std::string& f : check.files) {
    std::optional<std::string> text = read_whole_file(f);
    if (!text) return;  // a file vanished since it was read: not worth keeping
    hashes.push_back(content_hash(*text));
  }
  nlohmann::json entry = {{"format", kCacheEntryFormat}, {"hashes", std::move(hashes)}, {"result", to_json(check)}};
  std::error_code ec;
  fs::create_directories(path->parent_path(), ec);
  fs::path temp = *path;
  temp += ".tmp" + std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()));
  {
    std::ofstream out(temp, std::ios::binary);
    out << json_text(entry, -1);
    if (!out) return;
  }
  fs::rename(temp, *path, ec);
  if (ec) fs::remove(temp, ec);
  else ++stores_;
}

void CheckCache::evict() {
  struct Entry {
    fs::path path;
    fs::file_time_type used;
    uint64_t bytes;
  };
  std::vector<Entry> entries;
  uint64_t total = 0;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(directory_, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    Entry e{it->path(), it->last_write_time(ec), it->file_size(ec)};
    if (ec) continue;
    total += e.bytes;
    entries.push_back(std::move(e));
  }
  if (total <= limit_bytes_) return;
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= limit_bytes_) break;
    if (fs::remove(e.path, ec)) {
      total -= e.bytes;
      ++evicted_;
    }
  }
}

CheckCacheStats CheckCache::stats() const { return {hits_.load(), misses_.load(), stores_.load(), evicted_.load()}; }

}  // namespace fx::tools
