// Vertex layouts declared by the application, matched to a vertex shader's input semantics.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fx/compile/shader_reflection.h"
#include "fx/diagnostic.h"
#include "fxkit/target.h"

namespace fx::vk {

// The application's vertex layout is the public type (fxkit/target.h): one type from the
// engine's declaration to the pipeline.
using VertexAttribute = fxkit::VertexAttribute;
using VertexBinding = fxkit::VertexBinding;
using VertexLayout = fxkit::VertexLayout;

// A layout matched to one vertex shader: the exact Vulkan vertex input state.
struct VertexInput {
  std::vector<VkVertexInputAttributeDescription> attributes;  // one per shader input
  std::vector<VkVertexInputBindingDescription> bindings;
  uint64_t hash = 0;  // of the descriptions (part of a pipeline key)
};

// Canonical semantic: upper case, a trailing index of 0 dropped ("texcoord0" -> "TEXCOORD").
std::string canonical_semantic(std::string_view semantic);

// The semantics a vertex input reads, one per location it takes: a matrix input
// (`float4x4 World : TEXCOORD4`, instancing) takes one location per column and, as in D3D,
// one semantic index each (TEXCOORD4..TEXCOORD7). Canonical spellings.
std::vector<std::string> input_semantics(const InterfaceVariable& input);

// Matches every shader input to an attribute by semantic (GLSL inputs, which have none,
// match by variable name). A shader input with no attribute is "vk-vertex-attribute-missing"
// naming the semantic and the attributes on offer; attributes the shader does not read are
// left out. A binding referenced but not declared is "vk-vertex-binding-missing".
std::optional<VertexInput> match_vertex_layout(const VertexLayout& layout,
                                               const std::vector<InterfaceVariable>& inputs,
                                               DiagnosticSink& sink);

}  // namespace fx::vk
