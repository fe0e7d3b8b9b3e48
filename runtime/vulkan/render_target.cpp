// Offscreen attachments, dynamic rendering begin/end, readback to fx::Image.
#include "fx/vulkan/render_target.h"

#include <utility>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "fx/vulkan/barrier.h"
#include "fx/vulkan/one_shot.h"
#include "fx/vulkan/vk_check.h"

namespace fx::vk {
namespace {

bool readable_rgba8(VkFormat f) {
  return f == VK_FORMAT_R8G8B8A8_UNORM || f == VK_FORMAT_R8G8B8A8_SRGB || f == VK_FORMAT_B8G8R8A8_UNORM ||
         f == VK_FORMAT_B8G8R8A8_SRGB;
}

bool is_bgra(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_UNORM || f == VK_FORMAT_B8G8R8A8_SRGB; }

VkFormat choose_depth(const Context& ctx, DepthAttachment want) {
  constexpr VkFormatFeatureFlags kDepth = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
  switch (want) {
    case DepthAttachment::none: return VK_FORMAT_UNDEFINED;
    case DepthAttachment::d32:
      return ctx.supports_format(VK_FORMAT_D32_SFLOAT, kDepth) ? VK_FORMAT_D32_SFLOAT : VK_FORMAT_UNDEFINED;
    case DepthAttachment::d24s8:
      if (ctx.supports_format(VK_FORMAT_D24_UNORM_S8_UINT, kDepth)) return VK_FORMAT_D24_UNORM_S8_UINT;
      return ctx.supports_format(VK_FORMAT_D32_SFLOAT_S8_UINT, kDepth) ? VK_FORMAT_D32_SFLOAT_S8_UINT
                                                                       : VK_FORMAT_UNDEFINED;
    case DepthAttachment::best: return ctx.best_depth_format();
  }
  return VK_FORMAT_UNDEFINED;
}

// An attachment over `view` in `layout`, cleared or loaded, stored.
VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout, bool cleared) {
  auto a = structure<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  a.imageView = view;
  a.imageLayout = layout;
  a.loadOp = cleared ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  return a;
}

}  // namespace

std::optional<RenderTarget> RenderTarget::create(const Context& ctx, const RenderTargetDesc& desc,
                                                 DiagnosticSink& sink) {
  if (!ctx.features().dynamic_rendering) {
    sink.error("vk-feature-missing", {}, "render targets need the dynamicRendering feature (Vulkan 1.3)");
    return std::nullopt;
  }
  if (desc.width == 0 || desc.height == 0) {
    sink.error("vk-invalid-image", {}, "a render target needs a non-zero size");
    return std::nullopt;
  }
  RenderTarget rt;
  rt.width_ = desc.width;
  rt.height_ = desc.height;

  ImageDesc color;
  color.format = desc.color_format;
  color.width = desc.width;
  color.height = desc.height;
  color.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | desc.extra_color_usage;
  color.debug_name = desc.debug_name;
  auto color_image = GpuImage::create(ctx, color, sink);
  if (!color_image) return std::nullopt;
  rt.color_ = std::move(*color_image);

  if (desc.depth != DepthAttachment::none) {
    VkFormat format = choose_depth(ctx, desc.depth);
    if (format == VK_FORMAT_UNDEFINED) {
      sink.error("vk-format-unsupported", {},
                 "device '" + ctx.info().name + "' has no suitable depth attachment format");
      return std::nullopt;
    }
    ImageDesc depth;
    depth.format = format;
    depth.width = desc.width;
    depth.height = desc.height;
    depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | desc.extra_depth_usage;
    auto depth_image = GpuImage::create(ctx, depth, sink);
    if (!depth_image) return std::nullopt;
    rt.depth_ = std::move(*depth_image);
  }

  uint32_t texel = format_texel_bytes(desc.color_format);
  if (texel != 0) {
    BufferDesc readback;
    readback.size = VkDeviceSize(desc.width) * desc.height * texel;
    readback.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    readback.memory = MemoryUsage::readback;
    auto buffer = Buffer::create(ctx, readback, sink);
    if (!buffer) return std::nullopt;
    rt.readback_ = std::move(*buffer);
  }
  return rt;
}

RenderingFormats RenderTarget::formats(std::span<const RenderTarget* const> more) const {
  RenderingFormats f;
  f.color[0] = color_.format();
  f.color_count = 1;
  append_color_formats(f, more);
  if (depth_) {
    f.depth = depth_.format();
    if (has_stencil(f.depth)) f.stencil = f.depth;
  }
  return f;
}

VkViewport RenderTarget::viewport() const { return {0.0f, 0.0f, float(width_), float(height_), 0.0f, 1.0f}; }

VkRect2D RenderTarget::scissor() const { return {{0, 0}, {width_, height_}}; }

void RenderTarget::begin(VkCommandBuffer cmd, const ClearValues& clear, std::span<RenderTarget* const> more) {
  std::array<VkRenderingAttachmentInfo, kMaxColorAttachments> colors{};
  uint32_t count = 0;
  auto attach = [&](GpuImage& image) {
    // Cleared attachments may discard their old contents (cheaper on tilers).
    if (clear.color) image.assume_layout(VK_IMAGE_LAYOUT_UNDEFINED);
    image.transition(cmd, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    colors[count++] = color_attachment(image.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, clear);
  };
  attach(color_);
  for (RenderTarget* t : more)
    if (count < kMaxColorAttachments) attach(t->color_);

  auto info = structure<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  info.renderArea = scissor();
  info.layerCount = 1;
  info.colorAttachmentCount = count;
  info.pColorAttachments = colors.data();

  VkRenderingAttachmentInfo depth{};
  if (depth_) {
    if (clear.depth) depth_.assume_layout(VK_IMAGE_LAYOUT_UNDEFINED);
    depth_.transition(cmd, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    depth = depth_attachment(depth_.view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, clear);
    info.pDepthAttachment = &depth;
    if (has_stencil(depth_.format())) info.pStencilAttachment = &depth;
  }
  vkCmdBeginRendering(cmd, &info);
}

void RenderTarget::end(VkCommandBuffer cmd) { vkCmdEndRendering(cmd); }

VkRenderingAttachmentInfo color_attachment(VkImageView view, VkImageLayout layout, const ClearValues& clear) {
  VkRenderingAttachmentInfo color = attachment(view, layout, clear.color.has_value());
  if (clear.color)
    for (int i = 0; i < 4; ++i) color.clearValue.color.float32[i] = (*clear.color)[i];
  return color;
}

VkRenderingAttachmentInfo depth_attachment(VkImageView view, VkImageLayout layout, const ClearValues& clear) {
  VkRenderingAttachmentInfo depth = attachment(view, layout, clear.depth.has_value());
  depth.clearValue.depthStencil = {clear.depth.value_or(1.0f), clear.stencil};
  return depth;
}

void append_color_formats(RenderingFormats& formats, std::span<const RenderTarget* const> targets) {
  for (const RenderTarget* t : targets)
    if (formats.color_count < kMaxColorAttachments) formats.color[formats.color_count++] = t->color().format();
}

void RenderTarget::record_readback(VkCommandBuffer cmd) {
  if (!readback_) return;
  color_.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {width_, height_, 1};
  vkCmdCopyImageToBuffer(cmd, color_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.handle(), 1, &region);
  memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                 VK_ACCESS_HOST_READ_BIT);
}

std::optional<fx::Image> RenderTarget::readback_pixels(DiagnosticSink& sink) const {
  VkFormat format = color_.format();
  if (!readable_rgba8(format) || !readback_) {
    sink.error(
        "vk-readback-format", {},
        "reading back color format " + std::to_string(int(format)) + " is not supported (R8G8B8A8 / B8G8R8A8 only)");
    return std::nullopt;
  }
  fx::Image image = fx::Image::blank(width_, height_, 4);
  if (!readback_.read(image.pixels.data(), image.pixels.size())) {
    sink.error("vk-readback-format", {}, "readback buffer is smaller than the image");
    return std::nullopt;
  }
  if (is_bgra(format))
    for (size_t i = 0; i < image.pixels.size(); i += 4) std::swap(image.pixels[i], image.pixels[i + 2]);
  return image;
}

std::optional<fx::ImageF> RenderTarget::readback_floats(DiagnosticSink& sink) const {
  VkFormat format = color_.format();
  const bool half = format == VK_FORMAT_R16G16B16A16_SFLOAT;
  if ((!half && format != VK_FORMAT_R32G32B32A32_SFLOAT) || !readback_) {
    sink.error("vk-readback-format", {},
               "reading back color format " + std::to_string(int(format)) +
                   " as floats is not supported (R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT only)");
    return std::nullopt;
  }
  fx::ImageF image = fx::ImageF::blank(width_, height_, 4);
  std::vector<uint16_t> halves(half ? image.pixels.size() : 0);
  const bool read = half ? readback_.read(halves.data(), halves.size() * sizeof(uint16_t))
                         : readback_.read(image.pixels.data(), image.pixels.size() * sizeof(float));
  if (!read) {
    sink.error("vk-readback-format", {}, "readback buffer is smaller than the image");
    return std::nullopt;
  }
  for (size_t i = 0; i < halves.size(); ++i) image.pixels[i] = glm::unpackHalf1x16(halves[i]);  // keeps Inf, NaN
  return image;
}

std::optional<fx::Image> RenderTarget::read_color(const Context& ctx, DiagnosticSink& sink) {
  if (!readable_rgba8(color_.format())) return readback_pixels(sink);  // reports the format
  if (!submit_and_wait(
          ctx, [this](VkCommandBuffer cmd) { record_readback(cmd); }, sink))
    return std::nullopt;
  return readback_pixels(sink);
}

}  // namespace fx::vk
