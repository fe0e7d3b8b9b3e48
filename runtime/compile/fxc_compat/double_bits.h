// fxc splits a double into its two 32-bit halves with `asuint(d, out low, out high)`; glslang's
// HLSL front end has no such overload (and crashes on `frexp` of a double, the usual way to
// write one). The unit defines it when the effect calls it. Private to runtime/compile.
#pragma once
#include <string_view>
#include <vector>

#include "fx/token.h"

namespace fx::detail {

// Whether `toks` call `asuint` with three arguments (the double form; the one-argument forms
// are glslang's own).
bool calls_asuint_of_a_double(const std::vector<Token>& toks);

// HLSL defining `void asuint(double d, out uint low, out uint high)`: exact for every finite
// double, infinities and NaN (as the quiet NaN 0x7FF80000_00000000 with the input's sign).
// Subnormal inputs give their bits where the device keeps 64-bit subnormals; Vulkan lets it
// flush them (shaderDenormPreserveFloat64), and then they read as zero.
std::string_view asuint_of_a_double();

}  // namespace fx::detail
