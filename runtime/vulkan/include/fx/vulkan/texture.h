// fx::vk::Texture: a sampled image bound to effect parameters: uploaded from an fx::Image
// (PNG), from six fx::Images (cube), from a DDS file, from a baked fx::shading::Table (1D/2D/3D lookup
// tables), or the application's VkImageView borrowed without ownership.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <functional>
#include <optional>
#include <span>

#include "fx/dds.h"
#include "fx/image.h"
#include "fx/shading/table.h"
#include "fx/vulkan/context.h"
#include "fx/vulkan/image.h"

namespace fx::vk {

// Colour encoding of 8-bit image data.
enum class ColorSpace { linear, srgb };

class Texture {
 public:
  // A 2D texture from an 8-bit image (1..4 channels; 3 channels are padded to RGBA).
  // `srgb` stores it as an SRGB format so sampling linearises it.
  static std::optional<Texture> from_image(const Context& ctx, const fx::Image& image, ColorSpace space,
                                           DiagnosticSink& sink);
  // A cube texture from six square faces in +X, -X, +Y, -Y, +Z, -Z order.
  static std::optional<Texture> cube_from_images(const Context& ctx, const std::array<const fx::Image*, 6>& faces,
                                                 ColorSpace space, DiagnosticSink& sink);
  // A 2D (depth 1) or 3D texture from a baked table; unorm8 tables become R8/RG8/RGBA8,
  // float32 tables R32/RG32/RGBA32_SFLOAT. "vk-format-unsupported" if the device cannot
  // sample the format with linear filtering.
  static std::optional<Texture> from_table(const Context& ctx, const fx::shading::Table& table, DiagnosticSink& sink);
  // A texture from a DDS file's subresources (defined in dds_texture.cpp): 1D, 2D, cube,
  // volume and arrays with their mip chains; block-compressed data is uploaded compressed
  // where the device samples the format, else BC1-BC5 are decoded to RGBA8 first and other
  // formats report "vk-format-unsupported". `array_view` views a single layer as an array.
  static std::optional<Texture> from_dds(const Context& ctx, const fx::DdsTexture& dds, bool array_view,
                                         DiagnosticSink& sink);
  // A texture whose texels the commands `produce` records write into `texels` (a buffer with
  // TRANSFER_SRC usage, tightly packed in `desc.format`, row after row, layer after layer or
  // slice after slice): a compute shader's output, copied into the image in the same
  // submission, after a barrier from compute writes to the copy. Mip level 0 only.
  static std::optional<Texture> from_device_texels(const Context& ctx, const ImageDesc& desc, VkBuffer texels,
                                                   const std::function<void(VkCommandBuffer)>& produce,
                                                   DiagnosticSink& sink);
  // Whether from_dds can make `dds` on this device (any thread: a format query only).
  static bool can_sample_dds(const Context& ctx, const fx::DdsTexture& dds);
  // A one-texel texture of one colour in the shape a shader samples (1D, 2D, 3D, cube; as an
  // array view when `array`): what stands in for a texture the effect names but has no data for.
  static std::optional<Texture> solid(const Context& ctx, const std::array<uint8_t, 4>& rgba, ImageKind kind,
                                      bool array, DiagnosticSink& sink);
  // A 1x1 2D texture of more than one sample (4 where the device has it), every sample
  // `rgba`, for a Texture2DMS(Array) the effect reads with Load(coord, sample). Cleared, as no
  // buffer copy can fill a multisampled image.
  static std::optional<Texture> solid_multisampled(const Context& ctx, const std::array<uint8_t, 4>& rgba, bool array,
                                                   DiagnosticSink& sink);
  // The same for a depth comparison: one texel of `depth` in depth_stand_in_format.
  static std::optional<Texture> solid_depth(const Context& ctx, float depth, ImageKind kind, bool array,
                                            DiagnosticSink& sink);
  // D32_SFLOAT where the device samples it, else D16_UNORM (sampleable on every device).
  static VkFormat depth_stand_in_format(const Context& ctx);
  // Borrows the application's view: the texture never destroys it. `layout` is the layout
  // the image will be in when the pass samples it.
  static Texture wrap(VkImageView view, VkImageLayout layout, ImageKind kind);

  Texture() = default;
  Texture(Texture&&) noexcept = default;
  Texture& operator=(Texture&&) noexcept = default;

  VkImageView view() const { return owned_ ? owned_.view() : borrowed_view_; }
  VkImageLayout layout() const { return layout_; }
  ImageKind kind() const { return kind_; }
  bool owns_image() const { return bool(owned_); }
  explicit operator bool() const { return view() != VK_NULL_HANDLE; }

 private:
  // Creates the image and copies `bytes` into it: into every layer of mip 0, or by `regions`.
  static std::optional<Texture> upload(const Context& ctx, const ImageDesc& desc, const uint8_t* bytes,
                                       size_t byte_count, DiagnosticSink& sink,
                                       std::span<const VkBufferImageCopy> regions = {});
  // Creates the image and, in one blocking submission, records `before` (when set) and copies
  // `source` into it, as upload() says, leaving it in SHADER_READ_ONLY_OPTIMAL.
  static std::optional<Texture> copied(const Context& ctx, const ImageDesc& desc, VkBuffer source,
                                       const std::function<void(VkCommandBuffer)>& before, DiagnosticSink& sink,
                                       std::span<const VkBufferImageCopy> regions = {});
  GpuImage owned_;
  VkImageView borrowed_view_ = VK_NULL_HANDLE;
  VkImageLayout layout_ = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  ImageKind kind_ = ImageKind::image2d;
};

}  // namespace fx::vk
