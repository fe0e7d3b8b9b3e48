// A hash table from names (string_views into the AST) to values, for the checker's global
// symbols: open addressing over one slot array, entries kept in insertion order in one
// vector. Tens of thousands of globals then cost two allocations instead of one node each.
// Private to fxkit_parser.
#pragma once
#include <cstdint>
#include <cstring>
#include <string_view>
#include <utility>
#include <vector>

namespace fx::check {

// A hash of a name a word at a time: the effect's names are mostly 8 to 24 characters, and
// std::hash (libstdc++'s _Hash_bytes) cost about 60 instructions for each of them.
inline size_t name_hash(std::string_view name) {
  constexpr uint64_t kMultiplier = 0x9E3779B97F4A7C15ull;
  auto load64 = [](const char* p) { uint64_t v; std::memcpy(&v, p, 8); return v; };
  auto load32 = [](const char* p) { uint32_t v; std::memcpy(&v, p, 4); return uint64_t{v}; };
  const char* p = name.data();
  const size_t n = name.size();
  uint64_t h = n * kMultiplier;
  if (n >= 8) {
    for (size_t i = 0; i + 8 < n; i += 8) h = (h ^ load64(p + i)) * kMultiplier;
    h ^= load64(p + n - 8);  // the last 8 characters, overlapping the previous word
  } else if (n >= 4) {
    h ^= load32(p) | load32(p + n - 4) << 32;
  } else if (n > 0) {
    auto byte = [&](size_t i) { return uint64_t{static_cast<unsigned char>(p[i])}; };
    h ^= byte(0) | byte(n / 2) << 8 | byte(n - 1) << 16;
  }
  // The table masks the low bits, and a multiply carries differences only upwards (names
  // often differ in their last character, the top byte of the last word): MurmurHash3's
  // finalizer mixes every bit into the low ones.
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 33;
  h *= 0xC4CEB9FE1A85EC53ull;
  return static_cast<size_t>(h ^ (h >> 33));
}

template <class Value>
class NameTable {
 public:
  using Entry = std::pair<std::string_view, Value>;

  void reserve(size_t n) {
    entries_.reserve(n);
    if (2 * n > slots_.size()) rehash(2 * n);
  }
  // Inserts `value` under a new `name` and returns {it, true}, or returns the entry already
  // there and false.
  std::pair<Entry*, bool> emplace(std::string_view name, const Value& value) {
    if (2 * (entries_.size() + 1) > slots_.size()) rehash(2 * (entries_.size() + 1));
    size_t hash = name_hash(name);
    size_t slot = hash & mask_;
    for (; slots_[slot] != kEmpty; slot = (slot + 1) & mask_)
      if (entries_[slots_[slot]].first == name) return {&entries_[slots_[slot]], false};
    slots_[slot] = static_cast<uint32_t>(entries_.size());
    entries_.emplace_back(name, value);
    return {&entries_.back(), true};
  }
  const Value* find(std::string_view name) const {
    if (slots_.empty()) return nullptr;
    size_t hash = name_hash(name);
    for (size_t slot = hash & mask_; slots_[slot] != kEmpty; slot = (slot + 1) & mask_)
      if (entries_[slots_[slot]].first == name) return &entries_[slots_[slot]].second;
    return nullptr;
  }
  // In insertion order.
  typename std::vector<Entry>::const_iterator begin() const { return entries_.begin(); }
  typename std::vector<Entry>::const_iterator end() const { return entries_.end(); }

 private:
  static constexpr uint32_t kEmpty = UINT32_MAX;
  void rehash(size_t at_least) {
    size_t capacity = 16;
    while (capacity < at_least) capacity *= 2;
    slots_.assign(capacity, kEmpty);
    mask_ = capacity - 1;
    for (size_t i = 0; i < entries_.size(); ++i) {
      size_t slot = name_hash(entries_[i].first) & mask_;
      while (slots_[slot] != kEmpty) slot = (slot + 1) & mask_;
      slots_[slot] = static_cast<uint32_t>(i);
    }
  }

  std::vector<Entry> entries_;
  std::vector<uint32_t> slots_;  // index into entries_; load factor <= 1/2
  size_t mask_ = 0;
};

}  // namespace fx::check
