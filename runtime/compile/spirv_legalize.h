// spirv-opt passes fxkit runs on glslang's HLSL output: legalization after the fact, and the
// unrolling that makes loop-stepped texture offsets constant. Private to runtime/compile.
#pragma once
#include <cstdint>
#include <vector>

#include <spirv-tools/libspirv.h>

namespace fx::spirv {

// The SPIRV-Tools environment of a module made for Vulkan, from its SPIR-V version.
spv_target_env vulkan_env(const std::vector<uint32_t>& words);

// Runs SPIRV-Tools' HLSL legalization (inlining, scalar replacement, dead-code elimination)
// on a module that skipped it at compile time because it was valid without it: afterwards an
// input the code never uses is no longer loaded. Returns false (and leaves `words` as they
// were) when the optimizer fails.
bool legalize(std::vector<uint32_t>& words);

// fxc unrolls `[unroll]` loops (and loops with a constant trip count whose counter reaches a
// texture offset, unmarked too) and then needs every texture offset to be an immediate;
// glslang's legalization unrolls nothing, so an offset stepped by the loop stays a variable,
// which Vulkan allows only for gathers. Full unrolling and constant folding make it a
// ConstOffset (the folder rewrites the operand once it is constant).
void unroll_and_fold(std::vector<uint32_t>& words, spv_target_env env);

}  // namespace fx::spirv
