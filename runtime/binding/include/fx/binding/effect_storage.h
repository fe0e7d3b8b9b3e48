// fx::vk::EffectStorage: the storage buffers and storage images an effect's passes share by
// name (StructuredBuffer, RWStructuredBuffer, ByteAddressBuffer, Append/Consume buffers and
// their counters, tbuffer, RWTexture1D/2D/3D and their arrays): the application's, or zeroed stand-ins that let a
// preview run a compute pass and the draws that read what it wrote. Render thread only: a
// stand-in image is cleared with a submission on the context's queue.
#pragma once
#include <vulkan/vulkan.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/compile/shader_reflection.h"
#include "fx/vulkan/buffer.h"
#include "fx/vulkan/context.h"
#include "fx/vulkan/image.h"

namespace fx::vk {

// The shape of a storage image's stand-in: RWTexture1D, 2D or 3D, or a 1D or 2D array.
struct StorageImageShape {
  ImageKind kind = ImageKind::image2d;  // image1d, image2d or image3d
  bool arrayed = false;
};

class EffectStorage {
 public:
  // Bytes of a stand-in storage buffer (zeroed): 64 KiB, 4096 float4 elements.
  static constexpr VkDeviceSize kStandInBufferBytes = 64 * 1024;
  // Layers of a stand-in array image, and depth of a stand-in 3D image.
  static constexpr uint32_t kStandInLayers = 4;

  explicit EffectStorage(const Context& ctx) : ctx_(&ctx) {}

  // The application's buffer range for the storage buffer `name` (replacing a stand-in).
  void set_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range);
  // The application's view, in VK_IMAGE_LAYOUT_GENERAL, for the storage image `name`.
  void set_image(std::string_view name, VkImageView view);
  // The application's buffer view for the texel buffer `name` (Buffer<T>, RWBuffer<T>).
  void set_texel_view(std::string_view name, VkBufferView view);

  // What the storage buffer `name` reads and writes: the application's range, else a zeroed
  // stand-in of kStandInBufferBytes (made on first use, shared by every pass naming it).
  std::optional<VkDescriptorBufferInfo> buffer(std::string_view name, DiagnosticSink& sink);
  // The view of the storage image `name`: the application's, else a stand-in of `shape` in
  // `format`, cleared to zero and in VK_IMAGE_LAYOUT_GENERAL: `extent.width` texels wide,
  // `extent.height` high (2D, 3D), kStandInLayers deep (3D) or layers (arrays).
  // VK_NULL_HANDLE with "vk-storage-image-unbound" when no stand-in fits (`shape` nullopt:
  // an array of images) or the format cannot be a storage image.
  VkImageView image(std::string_view name, VkFormat format, std::optional<StorageImageShape> shape, VkExtent2D extent,
                    DiagnosticSink& sink);
  // The buffer view of the texel buffer `name`: the application's, else a view in `format`
  // of a zeroed stand-in buffer of kStandInBufferBytes. VK_NULL_HANDLE with
  // "vk-storage-image-unbound" when `format` is VK_FORMAT_UNDEFINED (an element without a
  // 32-bit format) and the application gave no view.
  VkBufferView texel_view(std::string_view name, VkFormat format, DiagnosticSink& sink);
  ~EffectStorage();
  EffectStorage(const EffectStorage&) = delete;
  EffectStorage& operator=(const EffectStorage&) = delete;

 private:
  struct StorageBuffer {
    std::string name;
    VkDescriptorBufferInfo info{};
    std::optional<Buffer> stand_in;
  };
  struct TexelBuffer {
    std::string name;
    VkBufferView view = VK_NULL_HANDLE;
    std::optional<Buffer> stand_in;
    VkBufferView stand_in_view = VK_NULL_HANDLE;  // owned
  };
  struct StorageImage {
    std::string name;
    VkImageView view = VK_NULL_HANDLE;
    std::optional<GpuImage> stand_in;
  };
  StorageBuffer& buffer_entry(std::string_view name);
  StorageImage& image_entry(std::string_view name);
  TexelBuffer& texel_entry(std::string_view name);
  // A zeroed stand-in buffer of kStandInBufferBytes for `usage`.
  std::optional<Buffer> zeroed_buffer(const std::string& name, VkBufferUsageFlags usage, DiagnosticSink& sink);

  const Context* ctx_;
  std::vector<StorageBuffer> buffers_;
  std::vector<StorageImage> images_;
  std::vector<TexelBuffer> texels_;
};

// The stand-in shape of a storage image reflection describes (`dim`, `arrayed`, `count`
// images); nullopt for an array of images or a shape RWTextures do not have.
std::optional<StorageImageShape> storage_image_shape(ImageDim dim, bool arrayed, uint32_t count);

// The format glslang gives an HLSL RWTexture's or (RW)Buffer's element type (float4 -> R32G32B32A32_SFLOAT,
// uint -> R32_UINT, ...); VK_FORMAT_UNDEFINED for an element it has no 32-bit format for.
VkFormat storage_image_format(std::string_view element);

}  // namespace fx::vk
