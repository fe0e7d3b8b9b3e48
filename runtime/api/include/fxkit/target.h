// fxkit::Target: what the application draws effects into, stated once when the Device is
// made: attachment formats, the vertex layout of its meshes, and the two conventions that
// decide which faces are front faces.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "fx/vulkan/app_vertex_layout.h"

namespace fxkit {

// The attachments of the application's dynamic rendering (vkCmdBeginRendering).
struct Formats {
  std::vector<VkFormat> color{};  // at most 4
  VkFormat depth = VK_FORMAT_UNDEFINED;
  VkFormat stencil = VK_FORMAT_UNDEFINED;  // a depth-stencil format is given as both
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

// What the application's geometry looks like: attributes (semantic, format, offset, binding)
// and vertex buffer bindings (binding, stride, rate). Vertex shader inputs are matched to the
// attributes by semantic (GLSL inputs by name); an input with no attribute is an error
// naming the semantics on offer. The Vulkan layer's own types (fx/vulkan/app_vertex_layout.h).
using VertexAttribute = fx::vk::VertexAttribute;
using VertexBinding = fx::vk::VertexBinding;
using VertexLayout = fx::vk::VertexLayout;

// The front faces of the application's meshes, seen from outside: Direct3D's convention is
// clockwise, OpenGL's and glTF's counter-clockwise.
enum class Winding : uint8_t { unset, clockwise, counter_clockwise };

// How clip space +Y becomes up on screen: a negative viewport height (VK_KHR_maintenance1,
// core since Vulkan 1.1), or a projection matrix that flips Y itself.
enum class YFlip : uint8_t { unset, negative_viewport, projection };

struct Target {
  Formats formats{};
  VertexLayout vertex_layout{};
  // Where shader inputs the vertex layout lacks are read from. Unset (the default): such an
  // input is an error naming the attributes on offer. Set: they read (0, 0, 0, 1), as
  // Direct3D reads elements a vertex declaration lacks (integer inputs as integers), from a
  // 32-byte buffer fxkit binds at this vertex buffer binding in Technique::begin (one the
  // application's layout leaves free).
  uint32_t default_attribute_binding = kNoBinding;
  static constexpr uint32_t kNoBinding = 0xFFFFFFFFu;
  Winding front_faces = Winding::unset;  // required
  YFlip y_flip = YFlip::unset;           // required
  // The size of the images drawn into: the storage images nothing else is bound to
  // (RWTexture2D stand-ins, one compute thread per pixel) are made this size. 0 x 0: 256 x 256.
  VkExtent2D extent{0, 0};
};

}  // namespace fxkit
