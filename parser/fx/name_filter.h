// A set of names kept as one bit per bucket: may_contain() can answer yes for a name never
// added, never no for one that was. The preprocessor adds each macro name; the lexer ends a
// batch after an identifier the set may contain, so the tokens before it need no lookup.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fx {

class NameFilter {
 public:
  void add(std::string_view name) {
    size_t s = slot(name);
    bits_[s / 64] |= uint64_t{1} << (s % 64);
  }
  bool may_contain(std::string_view name) const {
    if (name.empty()) return false;
    size_t s = slot(name);
    return bits_[s / 64] >> (s % 64) & 1;
  }
  void clear() { bits_.fill(0); }

 private:
  static constexpr size_t kWords = 64;
  // The first character picks the bit (its low six bits tell letters and '_' apart), the
  // length and last character the word: two loads beside the length, no multiply.
  static size_t slot(std::string_view n) {
    return (n.size() * 8 + static_cast<unsigned char>(n.back())) % kWords * 64 + static_cast<unsigned char>(n[0]) % 64;
  }
  std::array<uint64_t, kWords> bits_{};
};

}  // namespace fx
