// Private to runtime/select: the compiled-program half of technique validation (limits
// and compile success of a pass's linked program).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/select/device_caps.h"
#include "fx/source_manager.h"

namespace fx {
class EffectPrograms;
}  // namespace fx

namespace fx::detail {

// What compiling one pass said about the device.
struct PassProgramCheck {
  bool found = false;                    // the programs know this pass
  std::vector<Diagnostic> reasons;       // compile/link failures, limits exceeded (severity note)
  std::vector<std::string> image_names;  // texture/sampler bindings of the compiled stages
};

// Compiles (or reuses) the program of pass `pass` of technique number `technique_index`
// (named `technique`, "" when unnamed) and checks it against `caps`.
PassProgramCheck check_pass_program(EffectPrograms& programs, uint32_t technique_index, std::string_view technique,
                                    uint32_t pass, SourceRange pass_range, const DeviceCaps& caps);

// unmet_reason for a limit, or "" when met or when the caps do not state it (0).
std::string unmet_limit(const DeviceCaps& caps, std::string_view limit, uint32_t need);

}  // namespace fx::detail
