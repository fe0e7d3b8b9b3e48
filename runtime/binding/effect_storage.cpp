// EffectStorage: storage buffers and images by name, the application's or zeroed stand-ins.
#include "fx/binding/effect_storage.h"

#include <algorithm>

#include "fx/vulkan/barrier.h"
#include "fx/vulkan/one_shot.h"
#include "fx/vulkan/vk_check.h"

namespace fx::vk {

EffectStorage::StorageBuffer& EffectStorage::buffer_entry(std::string_view name) {
  auto it = std::find_if(buffers_.begin(), buffers_.end(), [&](const StorageBuffer& b) { return b.name == name; });
  if (it != buffers_.end()) return *it;
  buffers_.push_back({std::string(name), {}, std::nullopt});
  return buffers_.back();
}

EffectStorage::StorageImage& EffectStorage::image_entry(std::string_view name) {
  auto it = std::find_if(images_.begin(), images_.end(), [&](const StorageImage& i) { return i.name == name; });
  if (it != images_.end()) return *it;
  images_.push_back({std::string(name), VK_NULL_HANDLE, std::nullopt});
  return images_.back();
}

EffectStorage::TexelBuffer& EffectStorage::texel_entry(std::string_view name) {
  auto it = std::find_if(texels_.begin(), texels_.end(), [&](const TexelBuffer& t) { return t.name == name; });
  if (it != texels_.end()) return *it;
  texels_.push_back({std::string(name), VK_NULL_HANDLE, std::nullopt, VK_NULL_HANDLE});
  return texels_.back();
}

EffectStorage::~EffectStorage() {
  for (TexelBuffer& t : texels_)
    if (t.stand_in_view) vkDestroyBufferView(ctx_->device(), t.stand_in_view, nullptr);
}

void EffectStorage::set_texel_view(std::string_view name, VkBufferView view) { texel_entry(name).view = view; }

std::optional<Buffer> EffectStorage::zeroed_buffer(const std::string& name, VkBufferUsageFlags usage,
                                                   DiagnosticSink& sink) {
  auto buffer =
      Buffer::create(*ctx_, {kStandInBufferBytes, usage, MemoryUsage::upload, "fxkit storage stand-in"}, sink);
  if (!buffer) return std::nullopt;
  const std::vector<uint8_t> zeros(kStandInBufferBytes, 0);
  if (!buffer->write(zeros.data(), zeros.size())) {
    sink.error("vk-call-failed", {}, "could not zero the stand-in for '" + name + "'");
    return std::nullopt;
  }
  return buffer;
}

VkBufferView EffectStorage::texel_view(std::string_view name, VkFormat format, DiagnosticSink& sink) {
  TexelBuffer& t = texel_entry(name);
  if (t.view) return t.view;
  if (format == VK_FORMAT_UNDEFINED) {
    sink.error("vk-storage-image-unbound", {},
               "texel buffer '" + t.name + "' has no view: set_texel_buffer() binds one (stand-ins are buffers of " +
                   "a 32-bit float, int or uint element)");
    return VK_NULL_HANDLE;
  }
  std::optional<Buffer> buffer =
      zeroed_buffer(t.name, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, sink);
  if (!buffer) return VK_NULL_HANDLE;
  auto info = structure<VkBufferViewCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO);
  info.buffer = buffer->handle();
  info.format = format;
  info.range = VK_WHOLE_SIZE;
  if (!check(vkCreateBufferView(ctx_->device(), &info, nullptr, &t.stand_in_view), sink, "vkCreateBufferView"))
    return VK_NULL_HANDLE;
  t.stand_in = std::move(*buffer);
  t.view = t.stand_in_view;
  return t.view;
}

void EffectStorage::set_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
  buffer_entry(name).info = {buffer, offset, range};
}

void EffectStorage::set_image(std::string_view name, VkImageView view) { image_entry(name).view = view; }

std::optional<VkDescriptorBufferInfo> EffectStorage::buffer(std::string_view name, DiagnosticSink& sink) {
  StorageBuffer& b = buffer_entry(name);
  if (b.info.buffer) return b.info;
  std::optional<Buffer> stand_in = zeroed_buffer(b.name, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, sink);
  if (!stand_in) return std::nullopt;
  b.stand_in = std::move(*stand_in);
  b.info = {b.stand_in->handle(), 0, kStandInBufferBytes};
  return b.info;
}

VkImageView EffectStorage::image(std::string_view name, VkFormat format, std::optional<StorageImageShape> shape,
                                 VkExtent2D extent, DiagnosticSink& sink) {
  StorageImage& i = image_entry(name);
  if (i.view) return i.view;
  if (!shape || format == VK_FORMAT_UNDEFINED) {
    sink.error("vk-storage-image-unbound", {},
               "storage image '" + i.name + "' has no view: set_storage_image() binds one (stand-ins are " +
                   "single 1D, 2D or 3D images or arrays of a 32-bit float, int or uint element)");
    return VK_NULL_HANDLE;
  }
  ImageDesc desc;
  desc.kind = shape->kind;
  desc.format = format;
  desc.width = std::max(1u, extent.width);
  desc.height = shape->kind == ImageKind::image1d ? 1 : std::max(1u, extent.height);
  desc.depth = shape->kind == ImageKind::image3d ? kStandInLayers : 1;
  desc.array_layers = shape->arrayed ? kStandInLayers : 1;
  desc.array_view = shape->arrayed;
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  desc.debug_name = "fxkit storage image stand-in";
  std::optional<GpuImage> image = GpuImage::create(*ctx_, desc, sink);
  std::optional<OneShotCommands> commands = image ? OneShotCommands::create(*ctx_, sink) : std::nullopt;
  if (!image || !commands) return VK_NULL_HANDLE;
  const bool cleared = commands->run(
      [&](VkCommandBuffer cmd) {
        image->transition(cmd, VK_IMAGE_LAYOUT_GENERAL);
        const VkClearColorValue zero{};
        const VkImageSubresourceRange range = image->full_range();
        vkCmdClearColorImage(cmd, image->handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
        memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
      },
      sink);
  if (!cleared) return VK_NULL_HANDLE;
  i.stand_in = std::move(*image);
  i.view = i.stand_in->view();
  return i.view;
}

std::optional<StorageImageShape> storage_image_shape(ImageDim dim, bool arrayed, uint32_t count) {
  if (count != 1) return std::nullopt;
  switch (dim) {
    case ImageDim::dim_1d: return StorageImageShape{ImageKind::image1d, arrayed};
    case ImageDim::dim_2d: return StorageImageShape{ImageKind::image2d, arrayed};
    case ImageDim::dim_3d:
      if (!arrayed) return StorageImageShape{ImageKind::image3d, false};
      return std::nullopt;
    default: return std::nullopt;
  }
}

VkFormat storage_image_format(std::string_view element) {
  struct Row {
    const char* element;
    VkFormat format;
  };
  static const Row rows[] = {{"float", VK_FORMAT_R32_SFLOAT},       {"float1", VK_FORMAT_R32_SFLOAT},
                             {"float2", VK_FORMAT_R32G32_SFLOAT},   {"float4", VK_FORMAT_R32G32B32A32_SFLOAT},
                             {"int", VK_FORMAT_R32_SINT},           {"int2", VK_FORMAT_R32G32_SINT},
                             {"int4", VK_FORMAT_R32G32B32A32_SINT}, {"uint", VK_FORMAT_R32_UINT},
                             {"uint2", VK_FORMAT_R32G32_UINT},      {"uint4", VK_FORMAT_R32G32B32A32_UINT}};
  for (const Row& r : rows)
    if (element == r.element) return r.format;
  return VK_FORMAT_UNDEFINED;
}

}  // namespace fx::vk
