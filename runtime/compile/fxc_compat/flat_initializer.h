// HLSL initializer lists are flat: `float4 a[3] = { 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2 };`
// fills the array's vectors component by component, and `float a[2][3] = { 1, 2, 3, 4, 5, 6 };`
// its rows element by element (the DirectX SDK's PRT shaders zero their
// radiance arrays so, noise shaders fill int4 permutation tables so); glslang wants one
// element per vector. The unit writes such a list grouped into constructors.
// Private to runtime/compile.
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "fx/token.h"

namespace fx::detail {

// The new spellings of the tokens of every flat initializer list of an array of vectors or a
// multi-dimensional array of scalars or vectors in `toks` (`float4 a[2]`: `{` -> `{ float4(`,
// every 4th `,` -> `), float4(`, `}` -> `) }`; `float a[2][3]`: `{` -> `{ {`, the 3rd `,` ->
// `}, {`, `}` -> `} }`), by token index. Lists whose scalars do not fill the array exactly,
// with a size that is not a decimal literal, or that nest braces, are left alone.
std::unordered_map<uint32_t, std::string> flat_initializer_spellings(const std::vector<Token>& toks);

}  // namespace fx::detail
