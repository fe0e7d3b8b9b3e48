// fxkit::ScriptFrame: the application's frame a technique's DXSAS Script runs into
// (Technique::run_script), and fxkit::ScriptTarget, a render target the script draws.
#pragma once
#include <vulkan/vulkan.h>

#include <functional>
#include <string>

#include "fxkit/target.h"

namespace fxkit {

// What Technique::run_script draws into and with, for one frame.
struct ScriptFrame {
  // The application's images, outside rendering, and the attachment layouts they are in:
  // the colour attachment (Target::formats' first colour format), and the depth(-stencil)
  // attachment (Target::formats' depth; VK_NULL_HANDLE when the Target has none).
  // run_script renders in these layouts and leaves the images in them, written and visible
  // to later rendering.
  VkImageView color = VK_NULL_HANDLE;
  VkImageView depth = VK_NULL_HANDLE;
  VkImageLayout color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkImageLayout depth_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  // The part of the images the script draws into (RenderColorTarget0= and Draw=Buffer's
  // quad); the script's render targets are sized from its extent.
  VkRect2D area{};
  // Draw=Geometry: binds the application's vertex buffers (Target::vertex_layout) and draws
  // its mesh, as after Technique::apply.
  std::function<void(VkCommandBuffer)> draw_geometry;
  // ScriptExternal=: draws the application's scene into the script's current target, which
  // is rendering with attachments of `formats` over `area`. Empty leaves the target as the
  // script cleared it.
  std::function<void(VkCommandBuffer, const Formats& formats, const VkRect2D& area)> draw_scene;
};

// A render target of a technique's script (a RENDERCOLORTARGET texture parameter), to show
// (a thumbnail): its colour image, in SHADER_READ_ONLY_OPTIMAL after run_script.
struct ScriptTarget {
  std::string name{};  // the texture parameter's
  VkImageView view = VK_NULL_HANDLE;
  VkExtent2D extent{};
  VkFormat format = VK_FORMAT_UNDEFINED;
};

}  // namespace fxkit
