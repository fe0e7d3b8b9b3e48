// fx::vk::RenderTarget: an offscreen color attachment (+ optional depth) rendered with
// dynamic rendering (vkCmdBeginRendering) and read back into an fx::Image.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <optional>
#include <span>

#include "fx/image.h"
#include "fx/vulkan/buffer.h"
#include "fx/vulkan/context.h"
#include "fx/vulkan/image.h"
#include "fx/vulkan/rendering_formats.h"

namespace fx::vk {

enum class DepthAttachment {
  none,
  d32,    // D32_SFLOAT
  d24s8,  // D24_UNORM_S8_UINT, falling back to D32_SFLOAT_S8_UINT where D24S8 is missing
  best,   // Context::best_depth_format()
};

// What RenderTarget::create makes.
struct RenderTargetDesc {
  uint32_t width = 0, height = 0;
  // Readback supports R8G8B8A8 and B8G8R8A8 (UNORM or SRGB) as fx::Image, and
  // R16G16B16A16_SFLOAT / R32G32B32A32_SFLOAT as fx::ImageF; others render but do not read back.
  VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM;
  DepthAttachment depth = DepthAttachment::none;
  // Extra usage for the color image (SAMPLED to read it in a later pass).
  VkImageUsageFlags extra_color_usage = 0;
  const char* debug_name = nullptr;
  // Extra usage for the depth image (TRANSFER_SRC to copy it out).
  VkImageUsageFlags extra_depth_usage = 0;
};

// How begin() initialises the attachments: a value clears, nullopt keeps the contents.
struct ClearValues {
  std::optional<std::array<float, 4>> color = std::array<float, 4>{0, 0, 0, 1};
  std::optional<float> depth = 1.0f;
  uint32_t stencil = 0;
};

class RenderTarget {
 public:
  // Reports "vk-feature-missing" without dynamic rendering, "vk-format-unsupported" if the
  // color or depth format cannot be an attachment, or allocation failures.
  static std::optional<RenderTarget> create(const Context& ctx, const RenderTargetDesc& desc, DiagnosticSink& sink);

  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  VkExtent2D extent() const { return {width_, height_}; }
  // One colour attachment, and the depth (and stencil) format if the target has depth; then
  // the colour attachment of each of `more` (multiple render targets, as begin() binds them).
  RenderingFormats formats(std::span<const RenderTarget* const> more = {}) const;
  GpuImage& color() { return color_; }
  const GpuImage& color() const { return color_; }
  // The depth attachment, or null if the target has none.
  GpuImage* depth() { return depth_ ? &depth_ : nullptr; }
  const GpuImage* depth() const { return depth_ ? &depth_ : nullptr; }
  // Full-target viewport (depth 0..1, y down as in Vulkan) and scissor.
  VkViewport viewport() const;
  VkRect2D scissor() const;

  // Transitions the attachments and calls vkCmdBeginRendering over this target's area. The
  // colours of `more` (at least this size; up to kMaxColorAttachments in all) are attachments
  // 1, 2, ... after this one's, cleared or kept as this one's; the depth is this target's.
  void begin(VkCommandBuffer cmd, const ClearValues& clear = {}, std::span<RenderTarget* const> more = {});
  // Calls vkCmdEndRendering; the color stays in COLOR_ATTACHMENT_OPTIMAL.
  void end(VkCommandBuffer cmd);

  // Records a copy of the color attachment into the target's host-visible readback buffer.
  void record_readback(VkCommandBuffer cmd);
  // The pixels of the last recorded readback, once its submission has completed, as RGBA8
  // (BGRA formats are swizzled). "vk-readback-format" for formats it cannot convert.
  std::optional<fx::Image> readback_pixels(DiagnosticSink& sink) const;
  // The same for an R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT target: the values as
  // floats, unclamped (NaN and Inf kept), for measuring shader error below one 8-bit level.
  // "vk-readback-format" otherwise.
  std::optional<fx::ImageF> readback_floats(DiagnosticSink& sink) const;
  // record_readback + submit_and_wait + readback_pixels.
  std::optional<fx::Image> read_color(const Context& ctx, DiagnosticSink& sink);

 private:
  uint32_t width_ = 0, height_ = 0;
  GpuImage color_;
  GpuImage depth_;
  Buffer readback_;
};

// The attachment infos of a dynamic rendering over `view` in `layout`: cleared to the
// value `clear` gives (colour; depth and stencil), or loaded when it gives none; stored.
VkRenderingAttachmentInfo color_attachment(VkImageView view, VkImageLayout layout, const ClearValues& clear);
VkRenderingAttachmentInfo depth_attachment(VkImageView view, VkImageLayout layout, const ClearValues& clear);
// Appends the colour format of each of `targets` to `formats` (up to kMaxColorAttachments).
void append_color_formats(RenderingFormats& formats, std::span<const RenderTarget* const> targets);

}  // namespace fx::vk
