// A hash table from names (string_views into the AST) to values, for the checker's global
// symbols: open addressing over one slot array, entries kept in insertion order in one
// vector. Tens of thousands of globals then cost two allocations instead of one node each.
// Private to fxkit_parser.
#pragma once
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "name_hash.h"

namespace fx::check {

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
