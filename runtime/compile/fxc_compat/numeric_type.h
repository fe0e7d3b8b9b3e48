// HLSL scalar and vector type names (float, half3, int2, uint4, bool, double2, dword, ...),
// as the source rewrites of runtime/compile recognise them. Private to runtime/compile.
#pragma once
#include <cstdint>
#include <string_view>

namespace fx::detail {

// Components of a vector type name (float4, half3, int2, uint4, bool2, double3), 1 for a
// scalar type name; 0 otherwise.
uint32_t numeric_components(std::string_view type);

}  // namespace fx::detail
