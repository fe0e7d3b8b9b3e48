// fxc reads one sample of a multisampled texture with the `sample` operator,
// `ms.sample[s][pos]` (Texture2DMS, Texture2DMSArray); glslang knows only `ms.Load(pos, s)`.
// The unit writes the operator as that call. Private to runtime/compile.
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "fx/token.h"

namespace fx::detail {

// The spellings that turn every `name . sample [s] [pos]` in `toks`, where `name` is declared
// a Texture2DMS or Texture2DMSArray, into `name . Load(pos, s)`, by token index: `sample`
// becomes `Load`, the sample index moves after the position, and the tokens it leaves are
// blanks (so every other token keeps its column).
std::unordered_map<uint32_t, std::string> multisample_operator_spellings(const std::vector<Token>& toks);

}  // namespace fx::detail
