// Image + memory + default view creation, format facts, layout tracking.
#include "fx/vulkan/image.h"

#include <algorithm>
#include <utility>

#include "fx/vulkan/barrier.h"
#include "fx/vulkan/memory.h"
#include "fx/vulkan/vk_check.h"

namespace fx::vk {

uint32_t full_mip_count(uint32_t width, uint32_t height, uint32_t depth) {
  uint32_t largest = std::max({width, height, depth, 1u});
  uint32_t levels = 1;
  while (largest > 1) {
    largest >>= 1;
    ++levels;
  }
  return levels;
}

bool is_depth_format(VkFormat format) {
  switch (format) {
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D16_UNORM_S8_UINT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT: return true;
    default: return false;
  }
}

bool is_integer_format(VkFormat format) {
  return format == VK_FORMAT_R32G32B32A32_UINT || format == VK_FORMAT_R32G32B32A32_SINT;
}

bool has_stencil(VkFormat format) {
  return format == VK_FORMAT_S8_UINT || format == VK_FORMAT_D16_UNORM_S8_UINT ||
         format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

uint32_t depth_bits(VkFormat format) {
  switch (format) {
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_D16_UNORM_S8_UINT: return 16;
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT: return 32;
    default: return 24;
  }
}

VkImageAspectFlags format_aspect(VkFormat format) {
  VkImageAspectFlags aspect = 0;
  if (is_depth_format(format)) aspect |= VK_IMAGE_ASPECT_DEPTH_BIT;
  if (has_stencil(format)) aspect |= VK_IMAGE_ASPECT_STENCIL_BIT;
  return aspect ? aspect : VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT);
}

uint32_t format_texel_bytes(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_R8_SRGB:
    case VK_FORMAT_S8_UINT: return 1;
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_D16_UNORM: return 2;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_X8_D24_UNORM_PACK32: return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT: return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
    default: return 0;
  }
}

std::optional<GpuImage> GpuImage::create(const Context& ctx, const ImageDesc& requested, DiagnosticSink& sink) {
  ImageDesc desc = requested;
  const bool cube = desc.kind == ImageKind::cube;
  const bool three_d = desc.kind == ImageKind::image3d;
  const bool one_d = desc.kind == ImageKind::image1d;
  if (desc.width == 0 || desc.height == 0 || desc.depth == 0 || desc.array_layers == 0 ||
      (!three_d && desc.depth != 1) || (three_d && desc.array_layers != 1) || (one_d && desc.height != 1) ||
      (cube && desc.width != desc.height)) {
    sink.error("vk-invalid-image", {},
               "invalid image shape " + std::to_string(desc.width) + "x" + std::to_string(desc.height) + "x" +
                   std::to_string(desc.depth) + ", " + std::to_string(desc.array_layers) + " layer(s)" +
                   (cube ? " (cube faces must be square)" : ""));
    return std::nullopt;
  }
  if (desc.mip_levels == 0) desc.mip_levels = full_mip_count(desc.width, desc.height, desc.depth);
  if (cube) desc.array_layers *= 6;

  auto info = structure<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  info.flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  info.imageType = three_d ? VK_IMAGE_TYPE_3D : one_d ? VK_IMAGE_TYPE_1D : VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, desc.depth};
  info.mipLevels = desc.mip_levels;
  info.arrayLayers = desc.array_layers;
  info.samples = desc.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;

  VkImageFormatProperties limits{};
  VkResult supported = vkGetPhysicalDeviceImageFormatProperties(ctx.physical_device(), info.format, info.imageType,
                                                                info.tiling, info.usage, info.flags, &limits);
  if (supported != VK_SUCCESS || limits.maxExtent.width < desc.width || limits.maxExtent.height < desc.height ||
      limits.maxExtent.depth < desc.depth || limits.maxMipLevels < desc.mip_levels ||
      limits.maxArrayLayers < desc.array_layers || !(limits.sampleCounts & desc.samples)) {
    sink.error("vk-format-unsupported", {},
               "device '" + ctx.info().name + "' cannot create a " + std::to_string(desc.width) + "x" +
                   std::to_string(desc.height) + "x" + std::to_string(desc.depth) + " image of format " +
                   std::to_string(int(desc.format)) + " with the requested usage, mips, layers and samples");
    return std::nullopt;
  }

  GpuImage img;
  img.device_ = ctx.device();
  img.desc_ = desc;
  if (!check(vkCreateImage(img.device_, &info, nullptr, &img.image_), sink, "vkCreateImage")) return std::nullopt;
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(img.device_, img.image_, &req);
  auto allocation = allocate_memory(ctx, req, MemoryUsage::device_local, sink);
  if (!allocation) return std::nullopt;
  img.memory_ = allocation->memory;
  if (!check(vkBindImageMemory(img.device_, img.image_, img.memory_, 0), sink, "vkBindImageMemory"))
    return std::nullopt;

  auto view = structure<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  view.image = img.image_;
  const bool array = desc.array_view || desc.array_layers > (cube ? 6u : 1u);
  if (three_d) view.viewType = VK_IMAGE_VIEW_TYPE_3D;
  else if (cube) view.viewType = array ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_CUBE;
  else if (one_d) view.viewType = array ? VK_IMAGE_VIEW_TYPE_1D_ARRAY : VK_IMAGE_VIEW_TYPE_1D;
  else view.viewType = array ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  view.format = desc.format;
  view.subresourceRange = img.full_range();
  if (!check(vkCreateImageView(img.device_, &view, nullptr, &img.view_), sink, "vkCreateImageView"))
    return std::nullopt;
  if (desc.debug_name) ctx.set_object_name(VK_OBJECT_TYPE_IMAGE, uint64_t(img.image_), desc.debug_name);
  return img;
}

GpuImage::GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
  if (this == &other) return *this;
  reset();
  device_ = std::exchange(other.device_, VK_NULL_HANDLE);
  image_ = std::exchange(other.image_, VK_NULL_HANDLE);
  view_ = std::exchange(other.view_, VK_NULL_HANDLE);
  memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
  desc_ = other.desc_;
  layout_ = std::exchange(other.layout_, VK_IMAGE_LAYOUT_UNDEFINED);
  return *this;
}

void GpuImage::reset() {
  if (device_) {
    if (view_) vkDestroyImageView(device_, view_, nullptr);
    if (image_) vkDestroyImage(device_, image_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
  }
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
}

VkImageSubresourceRange GpuImage::full_range() const { return {aspect(), 0, desc_.mip_levels, 0, desc_.array_layers}; }

void GpuImage::transition(VkCommandBuffer cmd, VkImageLayout to) {
  if (layout_ == to) return;
  transition_image(cmd, image_, full_range(), layout_, to);
  layout_ = to;
}

}  // namespace fx::vk
