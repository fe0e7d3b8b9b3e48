// EffectStorage: storage buffers and images by name, the application's or stand-ins.
#include "fx/binding/effect_storage.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "fx/vulkan/barrier.h"
#include "fx/vulkan/one_shot.h"
#include "fx/vulkan/vk_check.h"

namespace fx::vk {
namespace {

// Whether stand_in_pattern gives `element` anything but zeros.
bool patterned_kind(ScalarKind element) {
  return element == ScalarKind::float32 || element == ScalarKind::int32 || element == ScalarKind::uint32;
}

// Whether a stand-in filled as `fill` says holds anything but zeros.
bool holds_pattern(StandInFill fill) { return fill.pattern && patterned_kind(fill.element); }

// The 32-bit formats of RWTexture and (RW)Buffer elements: what glslang gives each element
// type, with its channels and their scalar.
struct StorageFormatRow {
  const char* element;
  VkFormat format;
  uint32_t channels;
  ScalarKind scalar;
};
constexpr StorageFormatRow kStorageFormats[] = {
    {"float", VK_FORMAT_R32_SFLOAT, 1, ScalarKind::float32},
    {"float1", VK_FORMAT_R32_SFLOAT, 1, ScalarKind::float32},
    {"float2", VK_FORMAT_R32G32_SFLOAT, 2, ScalarKind::float32},
    {"float4", VK_FORMAT_R32G32B32A32_SFLOAT, 4, ScalarKind::float32},
    {"int", VK_FORMAT_R32_SINT, 1, ScalarKind::int32},
    {"int2", VK_FORMAT_R32G32_SINT, 2, ScalarKind::int32},
    {"int4", VK_FORMAT_R32G32B32A32_SINT, 4, ScalarKind::int32},
    {"uint", VK_FORMAT_R32_UINT, 1, ScalarKind::uint32},
    {"uint2", VK_FORMAT_R32G32_UINT, 2, ScalarKind::uint32},
    {"uint4", VK_FORMAT_R32G32B32A32_UINT, 4, ScalarKind::uint32},
};

const StorageFormatRow* storage_format_row(VkFormat format) {
  for (const StorageFormatRow& r : kStorageFormats)
    if (r.format == format) return &r;
  return nullptr;
}

}  // namespace

EffectStorage::StorageBuffer& EffectStorage::buffer_entry(std::string_view name) {
  auto it = std::find_if(buffers_.begin(), buffers_.end(), [&](const StorageBuffer& b) { return b.name == name; });
  if (it != buffers_.end()) return *it;
  buffers_.push_back({std::string(name), {}, std::nullopt, false});
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
  texels_.push_back({std::string(name), VK_NULL_HANDLE, std::nullopt, VK_NULL_HANDLE, false});
  return texels_.back();
}

EffectStorage::~EffectStorage() {
  for (TexelBuffer& t : texels_)
    if (t.stand_in_view) vkDestroyBufferView(ctx_->device(), t.stand_in_view, nullptr);
}

void EffectStorage::set_texel_view(std::string_view name, VkBufferView view) { texel_entry(name).view = view; }

std::vector<uint32_t> stand_in_pattern(ScalarKind element, size_t words) {
  std::vector<uint32_t> out(words, 0);
  if (!patterned_kind(element)) return out;
  for (size_t i = 0; i < words; ++i) {
    if (element == ScalarKind::float32) {
      const double golden = double(i) * 0.6180339887498949;
      out[i] = std::bit_cast<uint32_t>(float(2.0 * (golden - std::floor(golden)) - 1.0));
    } else {
      out[i] = uint32_t(i % 64);
    }
  }
  return out;
}

std::optional<Buffer> EffectStorage::stand_in_buffer(const std::string& name, VkBufferUsageFlags usage,
                                                     StandInFill fill, DiagnosticSink& sink) {
  auto buffer =
      Buffer::create(*ctx_, {kStandInBufferBytes, usage, MemoryUsage::upload, "fxkit storage stand-in"}, sink);
  if (!buffer) return std::nullopt;
  const std::vector<uint32_t> words =
      stand_in_pattern(fill.pattern ? fill.element : ScalarKind::other, kStandInBufferBytes / 4);
  if (!buffer->write(words.data(), kStandInBufferBytes)) {
    sink.error("vk-call-failed", {}, "could not fill the stand-in for '" + name + "'");
    return std::nullopt;
  }
  return buffer;
}

VkBufferView EffectStorage::texel_view(std::string_view name, VkFormat format, DiagnosticSink& sink, StandInFill fill) {
  TexelBuffer& t = texel_entry(name);
  if (t.view) return t.view;
  if (format == VK_FORMAT_UNDEFINED) {
    sink.error("vk-storage-image-unbound", {},
               "texel buffer '" + t.name + "' has no view: set_texel_buffer() binds one (stand-ins are buffers of " +
                   "1, 2 or 4 32-bit float, int or uint components, or 3 read-only)");
    return VK_NULL_HANDLE;
  }
  std::optional<Buffer> buffer = stand_in_buffer(
      t.name, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, fill, sink);
  if (!buffer) return VK_NULL_HANDLE;
  auto info = structure<VkBufferViewCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO);
  info.buffer = buffer->handle();
  info.format = format;
  info.range = VK_WHOLE_SIZE;
  if (!check(vkCreateBufferView(ctx_->device(), &info, nullptr, &t.stand_in_view), sink, "vkCreateBufferView"))
    return VK_NULL_HANDLE;
  t.stand_in = std::move(*buffer);
  t.view = t.stand_in_view;
  t.patterned = holds_pattern(fill);
  return t.view;
}

void EffectStorage::set_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
  buffer_entry(name).info = {buffer, offset, range};
}

void EffectStorage::set_image(std::string_view name, VkImageView view) { image_entry(name).view = view; }

std::optional<VkDescriptorBufferInfo> EffectStorage::buffer(std::string_view name, DiagnosticSink& sink,
                                                            StandInFill fill) {
  StorageBuffer& b = buffer_entry(name);
  if (b.info.buffer) return b.info;
  std::optional<Buffer> stand_in = stand_in_buffer(b.name, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, fill, sink);
  if (!stand_in) return std::nullopt;
  b.stand_in = std::move(*stand_in);
  b.info = {b.stand_in->handle(), 0, kStandInBufferBytes};
  b.patterned = holds_pattern(fill);
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
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
               VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // read_image
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

std::optional<std::vector<uint32_t>> EffectStorage::read_buffer(std::string_view name) const {
  auto it = std::find_if(buffers_.begin(), buffers_.end(), [&](const StorageBuffer& b) { return b.name == name; });
  if (it == buffers_.end() || !it->stand_in || it->info.buffer != it->stand_in->handle()) return std::nullopt;
  std::vector<uint32_t> words(kStandInBufferBytes / 4);
  if (!it->stand_in->read(words.data(), kStandInBufferBytes)) return std::nullopt;
  return words;
}

std::vector<std::string> EffectStorage::patterned() const {
  std::vector<std::string> names;
  for (const StorageBuffer& b : buffers_)
    if (b.patterned && b.stand_in && b.info.buffer == b.stand_in->handle()) names.push_back(b.name);
  for (const TexelBuffer& t : texels_)
    if (t.patterned && t.view == t.stand_in_view) names.push_back(t.name);
  return names;
}

std::optional<StorageTexels> EffectStorage::read_image(std::string_view name, DiagnosticSink& sink) {
  auto it = std::find_if(images_.begin(), images_.end(), [&](const StorageImage& i) { return i.name == name; });
  if (it == images_.end() || !it->stand_in || it->view != it->stand_in->view()) return std::nullopt;
  GpuImage& image = *it->stand_in;
  StorageTexels out;
  out.width = image.extent().width;
  out.height = image.extent().height;
  out.format = image.format();
  const VkDeviceSize bytes = VkDeviceSize(out.width) * out.height * 4 * storage_format_channels(out.format);
  auto staging = Buffer::create(
      *ctx_, {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::readback, "fxkit storage image readback"}, sink);
  std::optional<OneShotCommands> commands = staging ? OneShotCommands::create(*ctx_, sink) : std::nullopt;
  if (!staging || !commands) return std::nullopt;
  const bool copied = commands->run(
      [&](VkCommandBuffer cmd) {
        image.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);  // after the passes' writes
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {out.width, out.height, 1};
        vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging->handle(), 1,
                               &region);
        image.transition(cmd, VK_IMAGE_LAYOUT_GENERAL);  // where the passes expect it
        memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                       VK_ACCESS_HOST_READ_BIT);
      },
      sink);
  out.words.resize(bytes / 4);
  if (!copied || !staging->read(out.words.data(), bytes)) return std::nullopt;
  return out;
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

uint32_t storage_format_channels(VkFormat format) {
  const StorageFormatRow* row = storage_format_row(format);
  return row ? row->channels : 0;
}

ScalarKind storage_format_scalar(VkFormat format) {
  const StorageFormatRow* row = storage_format_row(format);
  return row ? row->scalar : ScalarKind::other;
}

VkFormat storage_image_format(std::string_view element) {
  for (const StorageFormatRow& r : kStorageFormats)
    if (element == r.element) return r.format;
  return VK_FORMAT_UNDEFINED;
}

VkFormat sampled_texel_buffer_format(std::string_view element) {
  if (element.size() > 1 && element.back() == '3') {
    std::string four(element);
    four.back() = '4';
    return storage_image_format(four);
  }
  return storage_image_format(element);
}

}  // namespace fx::vk
