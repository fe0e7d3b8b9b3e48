// fxc reads a few type names in any case: `Matrix transform;`, `FLOAT scale;`, `Vector<float, 3>`,
// `DWORD flags;` in D3D9 effects (vkd3d, which follows fxc, looks up dword, float, matrix,
// vector and the effect object types case-insensitively); glslang knows only the lower-case
// words. The unit writes them in lower case. Private to runtime/compile.
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "fx/token.h"

namespace fx::detail {

// The lower-case spellings of the numeric type names written in another case in `toks`
// where they stand as a type (before a declared name or `<`, or alone in a cast's
// parentheses), by token index; names the effect declares itself (`symbols`, sorted) stay.
std::unordered_map<uint32_t, std::string> case_insensitive_type_spellings(const std::vector<Token>& toks,
                                                                          const std::vector<std::string>& symbols);

}  // namespace fx::detail
