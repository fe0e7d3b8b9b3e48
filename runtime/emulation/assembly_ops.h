// Private: the shader model 1 instruction table (operand counts, which versions have each).
#pragma once
#include <cstdint>
#include <string_view>

#include "fx/emulation/assembly_program.h"

namespace fx::emulation {

struct OpInfo {
  std::string_view name;
  bool dest = true;
  uint8_t sources = 0;
  bool vertex = false;              // vs.1.0/1.1
  int8_t ps_min = -1, ps_max = -1;  // ps.1.<min>..ps.1.<max>; -1: not a pixel instruction
  bool optional_last = false;       // the last source may be left out (texm3x3spec's c#)
  bool pixel(const AsmVersion& v) const { return ps_min >= 0 && v.minor >= ps_min && v.minor <= ps_max; }
};

// The row for a lower-case base opcode, or nullptr.
const OpInfo* find_op(std::string_view name);

}  // namespace fx::emulation
