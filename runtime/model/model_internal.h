// Helpers shared by the model's source files (not installed).
#pragma once
#include <string>
#include <string_view>

#include "fx/ascii_case.h"
#include "fx/model/type.h"

namespace fx {
// One component converted as HLSL converts (truncation to int, wrap to uint, 0/1 bools,
// float rounding).
double convert_component(double v, BaseType base);
}  // namespace fx
