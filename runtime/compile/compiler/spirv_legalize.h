// spirv-opt passes fxkit runs on glslang's HLSL output: legalization after the fact, the
// unrolling that makes loop-stepped texture offsets constant, and unconsumed outputs
// removed. Private to runtime/compile.
#pragma once
#include <cstdint>
#include <set>
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

// Direct3D links stages by semantic and ignores a vertex output no pixel shader input
// takes; Vulkan without maintenance4 calls each such output a performance problem (the
// validation layer's Shader-OutputNotConsumed, once per pipeline). This drops the stores to
// outputs of a pre-rasterization stage at locations not in `consumed` and then the outputs
// themselves; builtins (Position, clip distances) stay. Returns false (and leaves `words` as
// they were) when the optimizer fails.
bool remove_unconsumed_outputs(std::vector<uint32_t>& words, const std::set<uint32_t>& consumed);

}  // namespace fx::spirv
