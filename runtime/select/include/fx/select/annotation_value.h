// fx::AnnotationValue: a scalar or string annotation as the effect file types it, the one
// spelling selection, validation and the reload's technique facts share.
#pragma once
#include <cstdint>
#include <string>
#include <variant>

namespace fx {

using AnnotationValue = std::variant<bool, int32_t, float, std::string>;

}  // namespace fx
