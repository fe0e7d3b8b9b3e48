// Vertex layouts declared by the application, matched to a vertex shader's input semantics.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fx/compile/shader_reflection.h"
#include "fx/diagnostic.h"
#include "fx/vulkan/app_vertex_layout.h"

namespace fx {
struct MeshVertexLayout;  // fx/mesh.h
}

namespace fx::vk {

// The Vulkan layout of a mesh library layout (fx::mesh_vertex_layout(), or one an
// application describes the same way): one binding of the layout's stride at `binding`,
// per attribute its semantic with the index appended when not 0 ("TEXCOORD", "TEXCOORD1"),
// float2/3/4 as R32G32(B32(A32))_SFLOAT, and its offset.
VertexLayout to_vertex_layout(const MeshVertexLayout& mesh, uint32_t binding = 0);

// A layout matched to one vertex shader: the exact Vulkan vertex input state.
struct VertexInput {
  std::vector<VkVertexInputAttributeDescription> attributes;  // one per shader input
  std::vector<VkVertexInputBindingDescription> bindings;
  uint64_t hash = 0;  // of the descriptions (part of a pipeline key)
};

// Canonical semantic: upper case, a trailing index of 0 dropped ("texcoord0" -> "TEXCOORD"),
// and a vertex input's SV_Position read as POSITION, as Direct3D 9's compiler reads it (XNA,
// FNA and MonoGame effects declare `float4 Position : SV_Position` for the mesh position).
std::string canonical_semantic(std::string_view semantic);

// The semantics a vertex input reads, one per location it takes: a matrix input
// (`float4x4 World : TEXCOORD4`, instancing) takes one location per column and, as in D3D,
// one semantic index each (TEXCOORD4..TEXCOORD7). Canonical spellings.
std::vector<std::string> input_semantics(const InterfaceVariable& input);

// The mesh semantic a GLSL input's name suggests ("inTexCoord" -> TEXCOORD, "aPos" ->
// POSITION), or "": what a GLSL input reads when the layout has no attribute of its name.
std::string_view glsl_input_semantic(std::string_view name);

// The format an input missing from the application's layout is read with: (0, 0, 0, 1) as
// floats, or as integers for integer inputs (BLENDINDICES as uint4), which Vulkan requires.
VkFormat default_attribute_format(const InterfaceVariable& input);

// What the buffer at a default-attribute binding holds: (0, 0, 0, 1) as floats at offset 0
// and as integers at offset 16, where with_default_attributes points integer inputs.
struct DefaultAttributeData {
  float floats[4] = {0, 0, 0, 1};
  int32_t ints[4] = {0, 0, 0, 1};
};

// `layout` plus, for every input it lacks, an attribute at `binding` whose buffer has stride
// 0: each vertex reads the same (0, 0, 0, 1), as Direct3D reads elements a vertex declaration
// lacks. Inputs are matched as match_vertex_layout matches them. The caller binds a
// buffer holding a DefaultAttributeData at `binding`.
VertexLayout with_default_attributes(VertexLayout layout, std::span<const InterfaceVariable> inputs, uint32_t binding);

// Matches every shader input to an attribute by semantic (GLSL inputs, which have none,
// match an attribute of their variable name, else the semantic glsl_input_semantic gives). A shader input with no
// attribute is "vk-vertex-attribute-missing" naming the semantic and the attributes on offer; attributes the shader
// does not read are left out. A binding referenced but not declared is "vk-vertex-binding-missing".
std::optional<VertexInput> match_vertex_layout(const VertexLayout& layout, const std::vector<InterfaceVariable>& inputs,
                                               DiagnosticSink& sink);

}  // namespace fx::vk
