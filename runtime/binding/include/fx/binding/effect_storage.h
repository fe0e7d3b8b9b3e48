// fx::vk::EffectStorage: the storage buffers and storage images an effect's passes share by
// name (StructuredBuffer, RWStructuredBuffer, ByteAddressBuffer, Append/Consume buffers and
// their counters, tbuffer, RWTexture1D/2D/3D and their arrays): the application's, or stand-ins that let a
// preview run a compute pass and the draws that read what it wrote (zeroed, or for previews a
// pattern in the buffers no pass writes), and read back what the passes wrote. Render thread
// only: a stand-in image is cleared, and read back, with a submission on the context's queue.
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

// What a stand-in buffer starts with: zeros, or with `pattern` (previews, for a buffer no
// pass writes: positions, weights, indices a shader only reads) stand_in_pattern(element).
struct StandInFill {
  bool pattern = false;
  ScalarKind element = ScalarKind::other;
};

// The words of a preview's stand-in for a buffer that passes only read: word i is
// 2·frac(i·0.618034) − 1 for float elements (values spread over [-1, 1) as positions,
// weights or colours), i mod 64 for integer ones (indices that stay inside any stand-in),
// zero for others.
std::vector<uint32_t> stand_in_pattern(ScalarKind element, size_t words);

// The first layer (or slice) of a storage image, read back: `width` x `height` texels of
// `format`, each storage_format_channels(format) 32-bit words.
struct StorageTexels {
  uint32_t width = 0, height = 0;
  VkFormat format = VK_FORMAT_UNDEFINED;
  std::vector<uint32_t> words;
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

  // What the storage buffer `name` reads and writes: the application's range, else a
  // stand-in of kStandInBufferBytes filled as `fill` says (made on first use, shared by every
  // pass naming it).
  std::optional<VkDescriptorBufferInfo> buffer(std::string_view name, DiagnosticSink& sink, StandInFill fill = {});
  // The view of the storage image `name`: the application's, else a stand-in of `shape` in
  // `format`, cleared to zero and in VK_IMAGE_LAYOUT_GENERAL: `extent.width` texels wide,
  // `extent.height` high (2D, 3D), kStandInLayers deep (3D) or layers (arrays).
  // VK_NULL_HANDLE with "vk-storage-image-unbound" when no stand-in fits (`shape` nullopt:
  // an array of images) or the format cannot be a storage image.
  VkImageView image(std::string_view name, VkFormat format, std::optional<StorageImageShape> shape, VkExtent2D extent,
                    DiagnosticSink& sink);
  // The buffer view of the texel buffer `name`: the application's, else a view in `format`
  // of a stand-in buffer of kStandInBufferBytes filled as `fill` says. VK_NULL_HANDLE with
  // "vk-storage-image-unbound" when `format` is VK_FORMAT_UNDEFINED (an element without a
  // 32-bit format) and the application gave no view.
  VkBufferView texel_view(std::string_view name, VkFormat format, DiagnosticSink& sink, StandInFill fill = {});

  // The words of the stand-in for storage buffer `name`, once the device has finished the
  // work that wrote it; nullopt for the application's buffer or a name never bound.
  std::optional<std::vector<uint32_t>> read_buffer(std::string_view name) const;
  // The first layer (or slice) of the stand-in for storage image `name`, copied out with a
  // submission of its own; nullopt for the application's image or a name never bound.
  std::optional<StorageTexels> read_image(std::string_view name, DiagnosticSink& sink);
  // The buffers and texel buffers whose stand-ins hold stand_in_pattern() (for tools that say
  // what a preview made up).
  std::vector<std::string> patterned() const;
  ~EffectStorage();
  EffectStorage(const EffectStorage&) = delete;
  EffectStorage& operator=(const EffectStorage&) = delete;

 private:
  struct StorageBuffer {
    std::string name;
    VkDescriptorBufferInfo info{};
    std::optional<Buffer> stand_in;
    bool patterned = false;
  };
  struct TexelBuffer {
    std::string name;
    VkBufferView view = VK_NULL_HANDLE;
    std::optional<Buffer> stand_in;
    VkBufferView stand_in_view = VK_NULL_HANDLE;  // owned
    bool patterned = false;
  };
  struct StorageImage {
    std::string name;
    VkImageView view = VK_NULL_HANDLE;
    std::optional<GpuImage> stand_in;
  };
  StorageBuffer& buffer_entry(std::string_view name);
  StorageImage& image_entry(std::string_view name);
  TexelBuffer& texel_entry(std::string_view name);
  // A stand-in buffer of kStandInBufferBytes for `usage`, filled as `fill` says.
  std::optional<Buffer> stand_in_buffer(const std::string& name, VkBufferUsageFlags usage, StandInFill fill,
                                        DiagnosticSink& sink);

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
// The stand-in format of a read-only texel buffer (`Buffer<float3>`): storage_image_format's,
// and for a three-component element the four-component one (R32G32B32 texel buffers are
// optional in Vulkan; a shader's Load of a samplerBuffer reads any float format).
VkFormat sampled_texel_buffer_format(std::string_view element);
// The 32-bit channels of a format storage_image_format() gives (1, 2 or 4); 0 for others.
uint32_t storage_format_channels(VkFormat format);
// The scalar of such a format's channels; ScalarKind::other for others.
ScalarKind storage_format_scalar(VkFormat format);

}  // namespace fx::vk
