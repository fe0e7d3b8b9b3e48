// Small readers and rewriters over SPIR-V words: what the compiler needs after glslang
// (semantics, binding remaps, stripping Google HLSL extensions). Private to runtime/compile.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fx::spirv {

constexpr uint32_t kMagic = 0x07230203;

// Which side of a stage interface a variable is on.
enum class Interface { input, output };

// HLSL semantic per location of the stage's inputs or outputs, read from OpDecorateString
// UserSemantic (emitted when glslang's hlslFunctionality1 is on). Upper-cased.
std::map<uint32_t, std::string> interface_semantics(const std::vector<uint32_t>& words, Interface side);

// Re-decorates the interface variable with one of `semantics` (upper case) as a builtin:
// an output as BuiltIn Position (a D3D9 vertex shader's POSITION, which glslang treats as a
// user varying, and an `inout ... : SV_Position` parameter, which glslang gives a location
// on both sides), an input as BuiltIn FragCoord (a D3D9 pixel shader's POSITION input, the
// vertex shader's output struct reused as its input: the pixel's position, as SV_Position
// is in shader model 4; only a float4 input can). Returns the variable's old location.
std::optional<uint32_t> promote_position(std::vector<uint32_t>& words, Interface side,
                                         std::initializer_list<std::string_view> semantics);

// Moves interface variables from one location to another (keys are current locations).
size_t remap_locations(std::vector<uint32_t>& words, Interface side, const std::map<uint32_t, uint32_t>& remap);

// Removes SPV_GOOGLE_hlsl_functionality1 / SPV_GOOGLE_decorate_string instructions so the
// module needs no device extension. Returns false when `words` is not a SPIR-V module.
bool strip_hlsl_semantics(std::vector<uint32_t>& words);

// How many image samples or fetches take a non-constant Offset operand, which Vulkan allows
// only for gathers (HLSL's `t.Sample(s, uv, int2(i, 0))` in an [unroll] loop).
size_t variable_image_offsets(const std::vector<uint32_t>& words);

// Sets the Unroll control (and clears DontUnroll) on every loop; returns how many loops.
// fxc unrolls a loop with a constant trip count whose counter reaches a texture offset even
// without `[unroll]`, so such a module's loops are all offered to spirv-opt's unroller,
// which unrolls only the loops it can.
size_t request_loop_unroll(std::vector<uint32_t>& words);

// Rewrites OpAny and OpAll of a scalar bool, which glslang writes for HLSL's any(x) and
// all(x) of a scalar (fxc takes them: x != 0), as OpCopyObject: the SPIR-V instructions take
// only bool vectors. Returns how many it rewrote.
size_t scalar_any_all(std::vector<uint32_t>& words);

// Whether the module keeps an image, sampler or sampled image (or an aggregate holding one)
// anywhere but UniformConstant memory, or passes one by value: Vulkan forbids both, glslang
// writes them for HLSL that copies a sampler into a local or passes it to a function, and
// spirv-opt's legalization removes them. SPIRV-Tools' validator does not catch them.
bool opaque_values_in_memory(const std::vector<uint32_t>& words);

// Locations of the stage inputs the code reads: loaded, indexed, copied or passed to a
// function or an extended instruction (InterpolateAt*). An input declared and never used,
// which spirv-opt's legalization leaves behind with its loads removed, is not among them.
std::set<uint32_t> read_input_locations(const std::vector<uint32_t>& words);

// The 32-bit component type of a padded output.
enum class Scalar { float32, int32, uint32 };

// Gives the output at `location` components [first, first + count) it does not write: a new
// Output variable there (Component `first`) of `scalar`s, holding 0 (1 in the fourth
// component, Direct3D's default for a missing component), stored at the entry function's
// start, or before every vertex a geometry shader emits. For a pixel shader that reads
// a float4 TEXCOORD0 the vertex shader writes as a float2: Direct3D pads it, Vulkan calls the
// missing components an error. False (and `words` unchanged) when the module is not a
// vertex, tessellation evaluation or geometry shader.
bool pad_output(std::vector<uint32_t>& words, uint32_t location, uint32_t first, uint32_t count, Scalar scalar);

// One output variable transform feedback captures: the one at `location`, or with no location
// the standalone BuiltIn Position variable (an HLSL SV_Position output).
struct XfbOutput {
  std::optional<uint32_t> location;
  uint32_t buffer = 0, offset = 0, stride = 0;
};

// Decorates each of `outputs` with XfbBuffer, XfbStride and Offset, and gives the entry point
// the Xfb execution mode (and the module the TransformFeedback capability). False, with
// `words` unchanged, when an output is not a variable of its own (a member of a block).
bool decorate_transform_feedback(std::vector<uint32_t>& words, const std::vector<XfbOutput>& outputs);

// (set, binding) pair of a descriptor.
using SetBinding = std::pair<uint32_t, uint32_t>;
// Rewrites DescriptorSet/Binding decorations of every variable whose current pair is a key
// of `remap`. Returns how many variables changed.
size_t remap_bindings(std::vector<uint32_t>& words, const std::map<SetBinding, SetBinding>& remap);

// (set, binding) of every decorated variable, by result id.
std::map<uint32_t, SetBinding> variable_bindings(const std::vector<uint32_t>& words);

// (set, binding) of every image and sampler variable a depth-comparing sample or gather
// (OpImage*Dref*) reads. glslang's HLSL front end gives a texture a depth-image type only
// when SampleCmp names its comparison sampler directly: a texture handed to a helper
// function (`float Shadow(SamplerComparisonState s, Texture2D t, ...)`) keeps a colour type
// in reflection while the code compares against it.
std::set<SetBinding> depth_compared_bindings(const std::vector<uint32_t>& words);

}  // namespace fx::spirv
