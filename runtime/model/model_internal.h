// Helpers shared by the model's source files (not installed).
#pragma once
#include <cctype>
#include <string>
#include <string_view>

#include "fx/model/type.h"

namespace fx::model_detail {

inline std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

inline bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

}  // namespace fx::model_detail

namespace fx {
// One component converted as HLSL converts (truncation to int, wrap to uint, 0/1 bools,
// float rounding).
double convert_component(double v, BaseType base);
}  // namespace fx
