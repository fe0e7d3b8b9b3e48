// fxc takes the dimension of a D3D9 `sampler` declared without one from the intrinsics that
// read it: `tex1D(s, x)` makes `s` a sampler1D, `tex3D` a sampler3D, `texCUBE` a samplerCUBE
// (foo_wave_seekbar's waveform is a `sampler` read with tex1D); glslang reads a bare `sampler`
// as two-dimensional. The unit writes the dimension into the declaration. Private to
// runtime/compile.
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "fx/token.h"

namespace fx::detail {

// The spellings `sampler1D`, `sampler3D` or `samplerCUBE` for each `sampler` type token in
// `toks` whose declared name (a global or a parameter) only tex1D*, only tex3D* or only
// texCUBE* calls read, by token index. A name read by calls of two dimensions, or by tex2D
// alone, keeps its declaration.
std::unordered_map<uint32_t, std::string> untyped_sampler_spellings(const std::vector<Token>& toks);

}  // namespace fx::detail
