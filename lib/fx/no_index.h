// fx::kNoIndex: the one "no index" value of every uint32_t index into an effect's lists
// (parameters, samplers, state objects, techniques): nothing found, nothing chosen.
#pragma once
#include <cstdint>

namespace fx {

inline constexpr uint32_t kNoIndex = 0xFFFFFFFFu;

}  // namespace fx
