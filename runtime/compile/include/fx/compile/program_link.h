// Links separately compiled stages into one program: one descriptor layout for all stages
// and D3D-style varying matching by semantic.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fx/compile/shader_compiler.h"
#include "fx/diagnostic.h"

namespace fx {

// Descriptor type of a program binding (what VkDescriptorSetLayoutBinding needs).
enum class DescriptorKind : uint8_t {
  uniform_buffer,
  storage_buffer,
  combined_image_sampler,
  sampled_image,
  sampler,
  storage_image,
  uniform_texel_buffer,  // Buffer<T>: a VkBufferView read as a texture
  storage_texel_buffer,  // RWBuffer<T>
};

// One descriptor shared by the stages that use it.
struct ProgramBinding {
  std::string name;
  DescriptorKind kind = DescriptorKind::uniform_buffer;
  uint32_t set = 0, binding = 0;
  uint32_t count = 1;       // descriptor array size
  uint32_t stage_mask = 0;  // bit (1 << ShaderStage) per stage that uses it
};

// The program's descriptor layout, in binding order.
struct ProgramLayout {
  std::vector<ProgramBinding> bindings;
  const ProgramBinding* find(std::string_view name) const;
};

// Rewrites the stages' SPIR-V (and reflection) so that:
//  - every resource is in set 0; bindings are numbered in pipeline stage order, then in each
//    stage's declaration order; the same name and kind (and, for blocks, the same size) in two
//    stages gets the same binding; same-named but different resources get their own;
//  - for HLSL stages, each stage's inputs take the locations of the previous stage's outputs
//    with the same semantic (TEXCOORD = TEXCOORD0 = D3D9's TEXCOORD0_centroid), as Direct3D
//    links by semantic. Outputs are numbered densely in location order. An input no earlier
//    stage writes is a warning ("shader-varying-unwritten") and gets a location past the
//    outputs. A pixel shader input wider than the output it reads (float4 from a float2)
//    gets the missing components written by the stage before: 0, and 1 in w, as Direct3D pads.
// The outputs whose canonical semantics are `captured` (stream output) stay, read or not.
// Stages must be ok() and listed once each; their order in `stages` does not matter.
ProgramLayout link_program(const std::vector<CompiledShader*>& stages, DiagnosticSink& sink,
                           std::span<const std::string> captured = {});

// A semantic as Direct3D links it: upper case, "TEXCOORD" and "TEXCOORD0" the same register,
// and so D3D9's "TEXCOORD0_centroid" (the same register, interpolated at the centroid).
std::string canonical_semantic(std::string semantic);

// The semantic `k` registers after `semantic`, as Direct3D numbers the registers of an array or
// a matrix varying: "TEXCOORD1", 2 -> "TEXCOORD3" ("COLOR", 1 -> "COLOR1": no number is 0).
std::string offset_semantic(std::string_view semantic, uint32_t k);
// The `count` semantics from `semantic` on: "TEXCOORD1", 3 -> TEXCOORD1, TEXCOORD2, TEXCOORD3.
std::vector<std::string> consecutive_semantics(std::string_view semantic, uint32_t count);

}  // namespace fx
