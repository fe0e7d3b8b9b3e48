// Small readers and rewriters over SPIR-V words: what the compiler needs after glslang
// (semantics, binding remaps, stripping Google HLSL extensions). Private to runtime/compile.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fx::spirv {

constexpr uint32_t kMagic = 0x07230203;

// Which side of a stage interface a variable is on.
enum class Interface { input, output };

// HLSL semantic per location of the stage's inputs or outputs, read from OpDecorateString
// UserSemantic (emitted when glslang's hlslFunctionality1 is on). Upper-cased.
std::map<uint32_t, std::string> interface_semantics(const std::vector<uint32_t>& words, Interface side);

// D3D9 vertex shaders write the clip position to the POSITION semantic, which glslang treats
// as a user varying. Re-decorates that output as BuiltIn Position. Returns its old location.
std::optional<uint32_t> promote_position_output(std::vector<uint32_t>& words);

// Moves interface variables from one location to another (keys are current locations).
size_t remap_locations(std::vector<uint32_t>& words, Interface side, const std::map<uint32_t, uint32_t>& remap);

// Removes SPV_GOOGLE_hlsl_functionality1 / SPV_GOOGLE_decorate_string instructions so the
// module needs no device extension. Returns false when `words` is not a SPIR-V module.
bool strip_hlsl_semantics(std::vector<uint32_t>& words);

// How many image samples or fetches take a non-constant Offset operand, which Vulkan allows
// only for gathers (HLSL's `t.Sample(s, uv, int2(i, 0))` in an [unroll] loop).
size_t variable_image_offsets(const std::vector<uint32_t>& words);

// (set, binding) pair of a descriptor.
using SetBinding = std::pair<uint32_t, uint32_t>;
// Rewrites DescriptorSet/Binding decorations of every variable whose current pair is a key
// of `remap`. Returns how many variables changed.
size_t remap_bindings(std::vector<uint32_t>& words, const std::map<SetBinding, SetBinding>& remap);

// (set, binding) of every decorated variable, by result id.
std::map<uint32_t, SetBinding> variable_bindings(const std::vector<uint32_t>& words);

}  // namespace fx::spirv
