// Private: the patch sizes of a tessellation control shader, read from its SPIR-V.
#pragma once
#include <cstdint>
#include <span>

namespace fx::vk {

// How many control points a tessellation control shader takes in and gives out per patch.
struct PatchSizes {
  // The input patch: HLSL's InputPatch<T, N> (the pipeline's patchControlPoints).
  uint32_t input = 0;
  // The OutputVertices execution mode: HLSL's [outputcontrolpoints(N)].
  uint32_t output = 0;
};

// The sizes of the module's tessellation control entry point; {0, 0} for any other stage.
// The input size is the outer array length of the per-vertex Input variables: glslang gives
// every member of an HLSL InputPatch<T, N> an array of N. A module with no per-vertex input,
// or with arrays of gl_MaxPatchVertices (32: a GLSL `gl_in[]` left unsized, which takes any
// patch size), states no input size; it is then the output size, as in most hull shaders.
PatchSizes tessellation_patch_sizes(std::span<const uint32_t> spirv);

}  // namespace fx::vk
