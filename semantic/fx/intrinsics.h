// The one table of HLSL intrinsic functions shader code may call without declaring them:
// name, signature and a one-line summary, for name resolution, hover and completion.
#pragma once
#include <span>
#include <string_view>

namespace fx::semantic {

struct Intrinsic {
  std::string_view name;
  std::string_view signature;  // HLSL's generic form: T is any float scalar, vector or matrix
  std::string_view summary;
};

// Every row, sorted by name.
std::span<const Intrinsic> all_intrinsics();
// The row named `name` (case-sensitive, as HLSL), or nullptr.
const Intrinsic* find_intrinsic(std::string_view name);

}  // namespace fx::semantic
