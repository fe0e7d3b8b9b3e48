// Compact source locations: one 32-bit offset into the SourceManager's address space.
#pragma once
#include <cstdint>

namespace fx {

// A position in some buffer (file, include instance, macro expansion or scratch space).
// 0 is "no location". Ordering is only meaningful within one buffer.
struct SourceLocation {
  uint32_t raw = 0;
  bool valid() const { return raw != 0; }
  SourceLocation offset(uint32_t delta) const { return {raw + delta}; }
  friend bool operator==(SourceLocation, SourceLocation) = default;
};

// A half-open range [begin, end) of characters.
struct SourceRange {
  SourceLocation begin, end;
  bool valid() const { return begin.valid(); }
};

}  // namespace fx
