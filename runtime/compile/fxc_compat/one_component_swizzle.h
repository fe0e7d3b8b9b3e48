// fxc takes a one-component vector (float1, int1, bool1, ...) as a scalar-like vector whose
// `.x` or `.r` may be written as well as read: `Out.TexCd.x = 0.5 + p.x;` (vvvv's Softedge.fx
// writes its float1 texture coordinate so). glslang reads such a swizzle as a constructor
// of a scalar, not an l-value: an assignment, `+=`, `++` to it is "l-value required", and as
// an `out` argument it is written to a temporary and lost. The unit writes the swizzle as
// an index, `TexCd[0]`, of the same type, an l-value in both readings.
// Private to runtime/compile.
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "fx/token.h"

namespace fx::detail {

// The spellings that turn every `name . x` and `name . r` in `toks`, where every declaration
// of `name` (member, parameter, local, global) is of a vector type and one is of a
// one-component vector type, into `name [ 0]`, by token index (`.` -> `[`, `x` -> `0]`).
std::unordered_map<uint32_t, std::string> one_component_swizzle_spellings(const std::vector<Token>& toks);

}  // namespace fx::detail
