// Private: a double spelled as an HLSL float literal that reads back to the same float.
#pragma once
#include <cstdio>
#include <string>

namespace fx::emulation {

inline std::string hlsl_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

}  // namespace fx::emulation
