// The hash of the parser's private tables of names: the checker's symbols (NameTable) and
// the state table's enumeration values. Private to fxkit_parser.
#pragma once
#include <cstdint>
#include <cstring>
#include <string_view>

namespace fx {

// A hash of a name a word at a time: the effect's names are mostly 8 to 24 characters, and
// std::hash (libstdc++'s _Hash_bytes) cost about 60 instructions for each of them.
inline size_t name_hash(std::string_view name) {
  constexpr uint64_t kMultiplier = 0x9E3779B97F4A7C15ull;
  auto load64 = [](const char* p) {
    uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
  };
  auto load32 = [](const char* p) {
    uint32_t v;
    std::memcpy(&v, p, 4);
    return uint64_t{v};
  };
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

}  // namespace fx
