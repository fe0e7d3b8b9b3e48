// Texture::from_dds: a DDS file's subresources uploaded, compressed where the device samples them.
#include <vector>

#include "fx/vulkan/texture.h"

namespace fx::vk {
namespace {

VkFormat vk_format(DxgiFormat f) {
  switch (f) {
    case DxgiFormat::r32g32b32a32_float: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case DxgiFormat::r32g32b32a32_uint: return VK_FORMAT_R32G32B32A32_UINT;
    case DxgiFormat::r32g32b32a32_sint: return VK_FORMAT_R32G32B32A32_SINT;
    case DxgiFormat::r16g16b16a16_float: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case DxgiFormat::r16g16b16a16_unorm: return VK_FORMAT_R16G16B16A16_UNORM;
    case DxgiFormat::r32g32_float: return VK_FORMAT_R32G32_SFLOAT;
    case DxgiFormat::r10g10b10a2_unorm: return VK_FORMAT_A2B10G10R10_UNORM_PACK32;
    case DxgiFormat::r8g8b8a8_unorm: return VK_FORMAT_R8G8B8A8_UNORM;
    case DxgiFormat::r8g8b8a8_unorm_srgb: return VK_FORMAT_R8G8B8A8_SRGB;
    case DxgiFormat::r16g16_float: return VK_FORMAT_R16G16_SFLOAT;
    case DxgiFormat::r32_float: return VK_FORMAT_R32_SFLOAT;
    case DxgiFormat::r8g8_unorm: return VK_FORMAT_R8G8_UNORM;
    case DxgiFormat::r16_float: return VK_FORMAT_R16_SFLOAT;
    case DxgiFormat::r8_unorm: return VK_FORMAT_R8_UNORM;
    case DxgiFormat::bc1_unorm: return VK_FORMAT_BC1_RGBA_UNORM_BLOCK;
    case DxgiFormat::bc1_unorm_srgb: return VK_FORMAT_BC1_RGBA_SRGB_BLOCK;
    case DxgiFormat::bc2_unorm: return VK_FORMAT_BC2_UNORM_BLOCK;
    case DxgiFormat::bc2_unorm_srgb: return VK_FORMAT_BC2_SRGB_BLOCK;
    case DxgiFormat::bc3_unorm: return VK_FORMAT_BC3_UNORM_BLOCK;
    case DxgiFormat::bc3_unorm_srgb: return VK_FORMAT_BC3_SRGB_BLOCK;
    case DxgiFormat::bc4_unorm: return VK_FORMAT_BC4_UNORM_BLOCK;
    case DxgiFormat::bc4_snorm: return VK_FORMAT_BC4_SNORM_BLOCK;
    case DxgiFormat::bc5_unorm: return VK_FORMAT_BC5_UNORM_BLOCK;
    case DxgiFormat::bc5_snorm: return VK_FORMAT_BC5_SNORM_BLOCK;
    case DxgiFormat::b8g8r8a8_unorm: return VK_FORMAT_B8G8R8A8_UNORM;
    case DxgiFormat::b8g8r8a8_unorm_srgb: return VK_FORMAT_B8G8R8A8_SRGB;
    case DxgiFormat::bc6h_uf16: return VK_FORMAT_BC6H_UFLOAT_BLOCK;
    case DxgiFormat::bc6h_sf16: return VK_FORMAT_BC6H_SFLOAT_BLOCK;
    case DxgiFormat::bc7_unorm: return VK_FORMAT_BC7_UNORM_BLOCK;
    case DxgiFormat::bc7_unorm_srgb: return VK_FORMAT_BC7_SRGB_BLOCK;
  }
  return VK_FORMAT_UNDEFINED;
}

bool srgb(DxgiFormat f) {
  return f == DxgiFormat::bc1_unorm_srgb || f == DxgiFormat::bc2_unorm_srgb || f == DxgiFormat::bc3_unorm_srgb;
}

ImageKind image_kind(DdsShape shape) {
  switch (shape) {
    case DdsShape::texture1d: return ImageKind::image1d;
    case DdsShape::cube: return ImageKind::cube;
    case DdsShape::volume: return ImageKind::image3d;
    default: return ImageKind::image2d;
  }
}

constexpr VkFormatFeatureFlags kSampled =
    VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;

}  // namespace

bool Texture::can_sample_dds(const Context& ctx, const fx::DdsTexture& dds) {
  return ctx.supports_format(vk_format(dds.format), kSampled) || fx::bc_decodable(dds.format);
}

std::optional<Texture> Texture::from_dds(const Context& ctx, const fx::DdsTexture& dds, bool array_view,
                                         DiagnosticSink& sink) {
  ImageDesc desc;
  desc.kind = image_kind(dds.shape);
  desc.format = vk_format(dds.format);
  desc.width = dds.width;
  desc.height = dds.height;
  desc.depth = dds.depth;
  desc.mip_levels = dds.mip_levels;
  desc.array_layers = dds.shape == DdsShape::cube ? dds.layers / 6 : dds.layers;
  desc.array_view = array_view;
  desc.debug_name = "fxkit DDS texture";
  // Compressed where the device samples the format; BC1-BC5 decoded where it does not.
  const bool decode = !ctx.supports_format(desc.format, kSampled) && fx::bc_decodable(dds.format);
  std::vector<uint8_t> decoded;
  std::vector<VkBufferImageCopy> regions;
  for (const fx::DdsSubresource& s : dds.subresources) {
    VkBufferImageCopy copy{};
    copy.bufferOffset = decode ? decoded.size() : s.offset;
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, s.mip, s.layer, 1};
    copy.imageExtent = {s.width, s.height, s.depth};
    regions.push_back(copy);
    if (!decode) continue;
    const uint64_t slice = s.size / s.depth;
    for (uint32_t z = 0; z < s.depth; ++z) {
      const fx::Image texels = fx::decode_bc_rgba8(
          dds.format, std::span<const uint8_t>(dds.data).subspan(s.offset + z * slice, slice), s.width, s.height);
      decoded.insert(decoded.end(), texels.pixels.begin(), texels.pixels.end());
    }
  }
  if (decode) desc.format = srgb(dds.format) ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  const std::vector<uint8_t>& bytes = decode ? decoded : dds.data;
  return upload(ctx, desc, bytes.data(), bytes.size(), sink, regions);
}

}  // namespace fx::vk
