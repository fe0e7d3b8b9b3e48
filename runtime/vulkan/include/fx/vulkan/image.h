// fx::vk::GpuImage: a device-local VkImage with its memory and a default view, for 2D, 3D and
// cube textures, render targets and depth buffers. (fx::Image is the CPU-side pixel array.)
#pragma once
#include <vulkan/vulkan.h>

#include <optional>

#include "fx/vulkan/context.h"

namespace fx::vk {

enum class ImageKind { image2d, image3d, cube, image1d };

// What GpuImage::create makes.
struct ImageDesc {
  ImageKind kind = ImageKind::image2d;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  uint32_t width = 1, height = 1, depth = 1;  // depth > 1 only for image3d
  uint32_t mip_levels = 1;                    // 0 means the full chain
  uint32_t array_layers = 1;                  // for cube: number of cubes (6 layers each)
  bool array_view = false;                    // view it as an array even with one layer (Texture2DArray)
  VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  const char* debug_name = nullptr;
};

// Number of mip levels of a full chain for this size.
uint32_t full_mip_count(uint32_t width, uint32_t height, uint32_t depth = 1);
// Aspect bits of a format (color, depth, depth|stencil, stencil).
VkImageAspectFlags format_aspect(VkFormat format);
bool is_depth_format(VkFormat format);
// The 32-bit integer colour formats fxkit uploads (R32G32B32A32_UINT / SINT): read, not filtered.
bool is_integer_format(VkFormat format);
bool has_stencil(VkFormat format);
// Bits of a depth format's depth (16, 24 or 32); 24 for formats without depth.
uint32_t depth_bits(VkFormat format);
// Bytes per texel of uncompressed formats fxkit reads back or uploads; 0 if unknown.
uint32_t format_texel_bytes(VkFormat format);

// Move-only owner of an image, its memory and one view covering every mip and layer
// (2D, 2D_ARRAY, 3D, CUBE or CUBE_ARRAY). Tracks the layout as recorded, assuming command
// buffers execute in the order their transitions were recorded.
class GpuImage {
 public:
  // Checks format support first ("vk-format-unsupported"); reports allocation failures.
  static std::optional<GpuImage> create(const Context& ctx, const ImageDesc& desc, DiagnosticSink& sink);

  GpuImage() = default;
  GpuImage(GpuImage&& other) noexcept;
  GpuImage& operator=(GpuImage&& other) noexcept;
  GpuImage(const GpuImage&) = delete;
  GpuImage& operator=(const GpuImage&) = delete;
  ~GpuImage() { reset(); }

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  VkDeviceMemory memory() const { return memory_; }
  const ImageDesc& desc() const { return desc_; }  // mip_levels resolved, layers = real count
  VkFormat format() const { return desc_.format; }
  VkExtent3D extent() const { return {desc_.width, desc_.height, desc_.depth}; }
  VkImageAspectFlags aspect() const { return format_aspect(desc_.format); }
  // Every mip level and layer.
  VkImageSubresourceRange full_range() const;
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

  // Layout after the transitions recorded so far.
  VkImageLayout layout() const { return layout_; }
  // Tells the tracker about a transition recorded elsewhere (e.g. by a render pass).
  void assume_layout(VkImageLayout layout) { layout_ = layout; }
  // Records a whole-image transition from the tracked layout; no-op if already there.
  void transition(VkCommandBuffer cmd, VkImageLayout to);

  // Destroys the image now (the device must be done with it).
  void reset();

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  ImageDesc desc_;
  VkImageLayout layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
};

}  // namespace fx::vk
