// tx_1_0's `noise()`: HLSL's Perlin noise, an intrinsic only texture shaders may call.
// glslang 12's HLSL front end crashes on a call to `noise`, so calls are spelled as fxkit's
// own gradient noise, which the units of texture shaders define (EffectUnits::compute_unit);
// a pass stage that calls it gets a located error naming it, as fxc rejects noise there.
// Private to runtime/compile.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "fx/ast.h"
#include "fx/token.h"

namespace fx::detail {

// What a call to `noise` is spelled as in the units.
inline constexpr std::string_view kTextureNoise = "noise__tx_1_0";

// The spellings that turn every call `noise(` in `toks` (not a member, `x.noise(`) into a call
// of kTextureNoise, by token index; none when the effect defines a function `noise` itself.
std::unordered_map<uint32_t, std::string> texture_noise_spellings(const std::vector<Token>& toks,
                                                                  const std::vector<const ast::Function*>& functions);

// HLSL defining kTextureNoise for float, float2, float3 and float4: 3D gradient noise (Perlin's
// improved noise: quintic fade, 12 edge gradients picked by a hash of the lattice cell), in
// about -1..1 and 0 at lattice points; a float4's w shifts the point along a fixed direction.
const std::string& texture_noise_definition();

}  // namespace fx::detail
