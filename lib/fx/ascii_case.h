// ASCII case folding for the parts of the effect language and the tools that ignore case
// (state and enum names, `asm`, `decl`, `NULL`, `TRUE`/`FALSE`, type names, semantics,
// profile and mesh names). Names are ASCII, and std::tolower's locale lookup dominated the
// parser and checker profiles, so these fold 'A'-'Z' only.
#pragma once
#include <string>
#include <string_view>

namespace fx {

// `c` with 'A'-'Z' folded to lower case; every other byte unchanged.
constexpr char ascii_lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c + ('a' - 'A')) : c; }

// A copy of `s` with 'A'-'Z' folded to lower case.
inline std::string ascii_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = ascii_lower(c);
  return out;
}

// True if `a` and `b` are equal ignoring ASCII case.
constexpr bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (ascii_lower(a[i]) != ascii_lower(b[i])) return false;
  return true;
}

}  // namespace fx
