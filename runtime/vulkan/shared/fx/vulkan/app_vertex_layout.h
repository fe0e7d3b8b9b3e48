// fx::vk::VertexLayout: what the application's geometry looks like (attributes by semantic,
// vertex buffer bindings), one type from the engine's declaration to the pipeline; the public
// API names it fxkit::VertexLayout (fxkit/target.h).
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace fx::vk {

// One attribute the application's vertex buffers provide.
struct VertexAttribute {
  std::string semantic{};  // "POSITION", "NORMAL", "TEXCOORD0" (TEXCOORD == TEXCOORD0)
  VkFormat format = VK_FORMAT_R32G32B32_SFLOAT;
  uint32_t offset = 0;   // bytes from the start of the vertex
  uint32_t binding = 0;  // vertex buffer binding
};

// One vertex buffer binding.
struct VertexBinding {
  uint32_t binding = 0;
  uint32_t stride = 0;
  VkVertexInputRate rate = VK_VERTEX_INPUT_RATE_VERTEX;
};

// What the application's geometry looks like. Vertex shader inputs are matched to the
// attributes by semantic (GLSL inputs by name); an input with no attribute is an error
// naming the semantics on offer.
struct VertexLayout {
  std::vector<VertexAttribute> attributes{};
  std::vector<VertexBinding> bindings{};
};

}  // namespace fx::vk
