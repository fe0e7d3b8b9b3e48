// Texture uploads through a staging buffer and a blocking one-shot submission (load time).
#include "fx/vulkan/texture.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "fx/vulkan/barrier.h"
#include "fx/vulkan/buffer.h"
#include "fx/vulkan/one_shot.h"

namespace fx::vk {

namespace {

VkFormat unorm_format(uint32_t channels, ColorSpace space) {
  const bool srgb = space == ColorSpace::srgb;
  switch (channels) {
    case 1: return srgb ? VK_FORMAT_R8_SRGB : VK_FORMAT_R8_UNORM;
    case 2: return srgb ? VK_FORMAT_R8G8_SRGB : VK_FORMAT_R8G8_UNORM;
    default: return srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  }
}

// Pixels with 3 channels padded to 4 (opaque alpha): three-channel formats are rarely
// sampleable.
std::vector<uint8_t> gpu_pixels(const fx::Image& image) {
  if (image.channels != 3) return image.pixels;
  std::vector<uint8_t> out(size_t(image.width) * image.height * 4);
  for (size_t i = 0, n = size_t(image.width) * image.height; i < n; ++i) {
    std::memcpy(&out[i * 4], &image.pixels[i * 3], 3);
    out[i * 4 + 3] = 255;
  }
  return out;
}

bool check_image(const fx::Image& image, DiagnosticSink& sink) {
  if (image.empty() || image.channels < 1 || image.channels > 4 ||
      image.pixels.size() != size_t(image.width) * image.height * image.channels) {
    sink.error("vk-texture-invalid", {}, "texture image is empty or its pixel data is malformed");
    return false;
  }
  return true;
}

}  // namespace

std::optional<Texture> Texture::upload(const Context& ctx, const ImageDesc& desc, const uint8_t* bytes,
                                       size_t byte_count, DiagnosticSink& sink,
                                       std::span<const VkBufferImageCopy> regions) {
  std::optional<Buffer> staging =
      Buffer::create(ctx, {byte_count, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::upload, "texture staging"}, sink);
  if (!staging || !staging->write(bytes, byte_count)) return std::nullopt;
  return copied(ctx, desc, staging->handle(), {}, sink, regions);
}

std::optional<Texture> Texture::from_device_texels(const Context& ctx, const ImageDesc& desc, VkBuffer texels,
                                                   const std::function<void(VkCommandBuffer)>& produce,
                                                   DiagnosticSink& sink) {
  const auto produced = [&](VkCommandBuffer cmd) {
    produce(cmd);
    memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                   VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  };
  return copied(ctx, desc, texels, produced, sink);
}

std::optional<Texture> Texture::copied(const Context& ctx, const ImageDesc& desc, VkBuffer source,
                                       const std::function<void(VkCommandBuffer)>& before, DiagnosticSink& sink,
                                       std::span<const VkBufferImageCopy> regions) {
  // Depth textures are compared and integer ones loaded, not filtered: sampling them is enough.
  const bool depth = is_depth_format(desc.format);
  const bool filtered = !depth && !is_integer_format(desc.format);
  if (!ctx.supports_format(desc.format, VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                            (filtered ? VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT : 0))) {
    sink.error("vk-format-unsupported", {},
               "the device cannot sample format " + std::to_string(int(desc.format)) +
                   (filtered ? " with linear filtering" : ""));
    return std::nullopt;
  }
  std::optional<GpuImage> image = GpuImage::create(ctx, desc, sink);
  if (!image) return std::nullopt;
  GpuImage& img = *image;
  const bool ok = submit_and_wait(
      ctx,
      [&](VkCommandBuffer cmd) {
        if (before) before(cmd);
        img.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {
            depth ? VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT) : VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT), 0, 0,
            img.desc().array_layers};
        copy.imageExtent = img.extent();
        if (regions.empty()) regions = {&copy, 1};
        vkCmdCopyBufferToImage(cmd, source, img.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               uint32_t(regions.size()), regions.data());
        img.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
      },
      sink);
  if (!ok) return std::nullopt;
  Texture t;
  t.owned_ = std::move(img);
  t.kind_ = desc.kind;
  return t;
}

std::optional<Texture> Texture::from_image(const Context& ctx, const fx::Image& image, ColorSpace space,
                                           DiagnosticSink& sink) {
  if (!check_image(image, sink)) return std::nullopt;
  ImageDesc desc;
  desc.format = unorm_format(image.channels, space);
  desc.width = image.width;
  desc.height = image.height;
  desc.debug_name = "fxkit texture";
  std::vector<uint8_t> pixels = gpu_pixels(image);
  return upload(ctx, desc, pixels.data(), pixels.size(), sink);
}

std::optional<Texture> Texture::solid(const Context& ctx, const std::array<uint8_t, 4>& rgba, ImageKind kind,
                                      bool array, DiagnosticSink& sink) {
  ImageDesc desc;
  desc.kind = kind;
  desc.array_view = array;
  desc.debug_name = "fxkit stand-in texture";
  const size_t layers = kind == ImageKind::cube ? 6 : 1;
  std::vector<uint8_t> texels;
  for (size_t i = 0; i < layers; ++i) texels.insert(texels.end(), rgba.begin(), rgba.end());
  return upload(ctx, desc, texels.data(), texels.size(), sink);
}

std::optional<Texture> Texture::solid_multisampled(const Context& ctx, const std::array<uint8_t, 4>& rgba, bool array,
                                                   DiagnosticSink& sink) {
  ImageDesc desc;
  desc.array_view = array;
  desc.debug_name = "fxkit multisampled stand-in texture";
  VkImageFormatProperties props{};
  if (vkGetPhysicalDeviceImageFormatProperties(ctx.physical_device(), desc.format, VK_IMAGE_TYPE_2D,
                                               VK_IMAGE_TILING_OPTIMAL, desc.usage, 0, &props) != VK_SUCCESS)
    props.sampleCounts = 0;
  // The shader's sample count (Texture2DMS<float4, N>) is not in SPIR-V; any count above one
  // is valid to bind, and a sample index past it reads undefined values, not invalid memory.
  for (VkSampleCountFlagBits count :
       {VK_SAMPLE_COUNT_4_BIT, VK_SAMPLE_COUNT_2_BIT, VK_SAMPLE_COUNT_8_BIT, VK_SAMPLE_COUNT_16_BIT})
    if (props.sampleCounts & count) {
      desc.samples = count;
      break;
    }
  if (desc.samples == VK_SAMPLE_COUNT_1_BIT) {
    sink.error("vk-format-unsupported", {},
               "device '" + ctx.info().name + "' cannot sample a multisampled RGBA8 image (Texture2DMS)");
    return std::nullopt;
  }
  std::optional<GpuImage> image = GpuImage::create(ctx, desc, sink);
  if (!image) return std::nullopt;
  GpuImage& img = *image;
  const bool ok = submit_and_wait(
      ctx,
      [&](VkCommandBuffer cmd) {
        img.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkClearColorValue colour{};
        for (int c = 0; c < 4; ++c) colour.float32[c] = float(rgba[c]) / 255.0f;
        const VkImageSubresourceRange range = img.full_range();
        vkCmdClearColorImage(cmd, img.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1, &range);
        img.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
      },
      sink);
  if (!ok) return std::nullopt;
  Texture t;
  t.owned_ = std::move(img);
  t.kind_ = ImageKind::image2d;
  return t;
}

VkFormat Texture::depth_stand_in_format(const Context& ctx) {
  if (ctx.supports_format(VK_FORMAT_D32_SFLOAT, VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) return VK_FORMAT_D32_SFLOAT;
  return VK_FORMAT_D16_UNORM;  // sampleable on every device
}

std::optional<Texture> Texture::solid_depth(const Context& ctx, float depth, ImageKind kind, bool array,
                                            DiagnosticSink& sink) {
  ImageDesc desc;
  desc.kind = kind;
  desc.array_view = array;
  desc.debug_name = "fxkit depth stand-in texture";
  desc.format = depth_stand_in_format(ctx);
  const size_t layers = kind == ImageKind::cube ? 6 : 1;
  depth = std::clamp(depth, 0.0f, 1.0f);  // what a depth attachment could hold
  const uint16_t unorm = static_cast<uint16_t>(depth * 65535.0f + 0.5f);
  const size_t texel = desc.format == VK_FORMAT_D32_SFLOAT ? sizeof depth : sizeof unorm;
  std::vector<uint8_t> texels(layers * texel);
  for (size_t i = 0; i < layers; ++i)
    std::memcpy(texels.data() + i * texel, texel == sizeof depth ? static_cast<const void*>(&depth) : &unorm, texel);
  return upload(ctx, desc, texels.data(), texels.size(), sink);
}

std::optional<Texture> Texture::cube_from_images(const Context& ctx, const std::array<const fx::Image*, 6>& faces,
                                                 ColorSpace space, DiagnosticSink& sink) {
  for (const fx::Image* f : faces) {
    if (!f || !check_image(*f, sink)) return std::nullopt;
    if (f->width != f->height || f->width != faces[0]->width || f->channels != faces[0]->channels) {
      sink.error("vk-texture-invalid", {}, "cube faces must be square and all the same size");
      return std::nullopt;
    }
  }
  ImageDesc desc;
  desc.kind = ImageKind::cube;
  desc.format = unorm_format(faces[0]->channels, space);
  desc.width = desc.height = faces[0]->width;
  desc.debug_name = "fxkit cube texture";
  std::vector<uint8_t> all;
  for (const fx::Image* f : faces) {
    std::vector<uint8_t> p = gpu_pixels(*f);
    all.insert(all.end(), p.begin(), p.end());
  }
  return upload(ctx, desc, all.data(), all.size(), sink);
}

std::optional<Texture> Texture::from_table(const Context& ctx, const fx::shading::Table& table, DiagnosticSink& sink) {
  if (table.width < 1 || table.height < 1 || table.depth < 1 || table.channels < 1 || table.channels > 4 ||
      table.value_count() == 0) {
    sink.error("vk-texture-invalid", {}, "lookup table has no texels");
    return std::nullopt;
  }
  if (table.cube && (table.depth != 6 || table.width != table.height)) {
    sink.error("vk-texture-invalid", {}, "a cube lookup table has six square faces");
    return std::nullopt;
  }
  ImageDesc desc;
  desc.kind = table.cube ? ImageKind::cube : table.depth > 1 ? ImageKind::image3d : ImageKind::image2d;
  desc.width = uint32_t(table.width);
  desc.height = uint32_t(table.height);
  desc.depth = table.cube ? 1u : uint32_t(table.depth);  // a cube's faces are its six layers, in order
  desc.debug_name = "fxkit lookup table";
  const uint32_t gpu_channels = table.channels == 3 ? 4 : uint32_t(table.channels);
  const size_t texels = size_t(table.width) * table.height * table.depth;
  const bool unorm = table.format == fx::shading::TableFormat::unorm8;
  const VkFormat float_formats[] = {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT,
                                    VK_FORMAT_R32G32B32A32_SFLOAT};
  desc.format = unorm ? unorm_format(gpu_channels, ColorSpace::linear) : float_formats[gpu_channels - 1];
  const size_t value_bytes = unorm ? 1 : 4;
  std::vector<uint8_t> bytes(texels * gpu_channels * value_bytes);
  for (size_t t = 0; t < texels; ++t)
    for (uint32_t c = 0; c < gpu_channels; ++c) {
      const bool real = c < uint32_t(table.channels);
      const size_t src = t * table.channels + c;
      uint8_t* dst = &bytes[(t * gpu_channels + c) * value_bytes];
      if (unorm) *dst = real ? table.unorm8[src] : 255;
      else {
        const float v = real ? table.float32[src] : 1.0f;
        std::memcpy(dst, &v, 4);
      }
    }
  return upload(ctx, desc, bytes.data(), bytes.size(), sink);
}

Texture Texture::wrap(VkImageView view, VkImageLayout layout, ImageKind kind) {
  Texture t;
  t.borrowed_view_ = view;
  t.layout_ = layout;
  t.kind_ = kind;
  return t;
}

}  // namespace fx::vk
