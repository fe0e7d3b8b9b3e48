// BC1-BC5 blocks expanded to RGBA8 on the CPU, for devices that cannot sample them.
#include <array>
#include <cstring>

#include "fx/dds.h"

namespace fx {
namespace {

using Rgba = std::array<uint8_t, 4>;

Rgba from_565(uint16_t c) {
  const uint8_t r = (c >> 11) & 31, g = (c >> 5) & 63, b = c & 31;
  return {uint8_t(r << 3 | r >> 2), uint8_t(g << 2 | g >> 4), uint8_t(b << 3 | b >> 2), 255};
}

uint8_t mix(uint8_t a, uint8_t b, int wa, int wb) { return uint8_t((wa * a + wb * b + (wa + wb) / 2) / (wa + wb)); }

// A BC1 colour block into 16 texels. `four_colour` forces the opaque four-colour mode BC2 and
// BC3 always use.
void colour_block(const uint8_t* block, bool four_colour, Rgba* out) {
  uint16_t c0, c1;
  uint32_t indices;
  std::memcpy(&c0, block, 2);
  std::memcpy(&c1, block + 2, 2);
  std::memcpy(&indices, block + 4, 4);
  std::array<Rgba, 4> palette{from_565(c0), from_565(c1), {}, {}};
  for (int c = 0; c < 3; ++c) {
    if (four_colour || c0 > c1) {
      palette[2][c] = mix(palette[0][c], palette[1][c], 2, 1);
      palette[3][c] = mix(palette[0][c], palette[1][c], 1, 2);
    } else {
      palette[2][c] = mix(palette[0][c], palette[1][c], 1, 1);
      palette[3][c] = 0;
    }
  }
  palette[2][3] = 255;
  palette[3][3] = (four_colour || c0 > c1) ? 255 : 0;
  for (int i = 0; i < 16; ++i) out[i] = palette[(indices >> (2 * i)) & 3];
}

// A BC3 alpha / BC4 channel block into 16 values.
void channel_block(const uint8_t* block, uint8_t* out) {
  const uint8_t a0 = block[0], a1 = block[1];
  std::array<uint8_t, 8> v{a0, a1};
  if (a0 > a1) {
    for (int i = 1; i < 7; ++i) v[size_t(i + 1)] = mix(a0, a1, 7 - i, i);
  } else {
    for (int i = 1; i < 5; ++i) v[size_t(i + 1)] = mix(a0, a1, 5 - i, i);
    v[6] = 0, v[7] = 255;
  }
  uint64_t bits = 0;
  for (int i = 0; i < 6; ++i) bits |= uint64_t(block[2 + i]) << (8 * i);
  for (int i = 0; i < 16; ++i) out[i] = v[(bits >> (3 * i)) & 7];
}

}  // namespace

bool bc_decodable(DxgiFormat format) {
  switch (format) {
    case DxgiFormat::bc1_unorm:
    case DxgiFormat::bc1_unorm_srgb:
    case DxgiFormat::bc2_unorm:
    case DxgiFormat::bc2_unorm_srgb:
    case DxgiFormat::bc3_unorm:
    case DxgiFormat::bc3_unorm_srgb:
    case DxgiFormat::bc4_unorm:
    case DxgiFormat::bc5_unorm: return true;
    default: return false;
  }
}

Image decode_bc_rgba8(DxgiFormat format, std::span<const uint8_t> blocks, uint32_t width, uint32_t height) {
  const std::optional<DxgiFormatInfo> info = dxgi_format_info(uint32_t(format));
  if (!bc_decodable(format) || !info || blocks.size() < dxgi_slice_bytes(*info, width, height)) return {};
  Image image = Image::blank(width, height, 4);
  const uint32_t blocks_x = (width + 3) / 4, blocks_y = (height + 3) / 4;
  for (uint32_t by = 0; by < blocks_y; ++by)
    for (uint32_t bx = 0; bx < blocks_x; ++bx) {
      const uint8_t* block = blocks.data() + (size_t(by) * blocks_x + bx) * info->bytes;
      std::array<Rgba, 16> texels{};
      std::array<uint8_t, 16> channel{};
      switch (format) {
        case DxgiFormat::bc1_unorm:
        case DxgiFormat::bc1_unorm_srgb: colour_block(block, false, texels.data()); break;
        case DxgiFormat::bc2_unorm:
        case DxgiFormat::bc2_unorm_srgb:
          colour_block(block + 8, true, texels.data());
          for (int i = 0; i < 16; ++i) texels[size_t(i)][3] = uint8_t(((block[i / 2] >> (4 * (i & 1))) & 15) * 17);
          break;
        case DxgiFormat::bc3_unorm:
        case DxgiFormat::bc3_unorm_srgb:
          colour_block(block + 8, true, texels.data());
          channel_block(block, channel.data());
          for (int i = 0; i < 16; ++i) texels[size_t(i)][3] = channel[size_t(i)];
          break;
        case DxgiFormat::bc4_unorm:
          channel_block(block, channel.data());
          for (int i = 0; i < 16; ++i) texels[size_t(i)] = {channel[size_t(i)], 0, 0, 255};
          break;
        default:  // bc5_unorm
          channel_block(block, channel.data());
          for (int i = 0; i < 16; ++i) texels[size_t(i)] = {channel[size_t(i)], 0, 0, 255};
          channel_block(block + 8, channel.data());
          for (int i = 0; i < 16; ++i) texels[size_t(i)][1] = channel[size_t(i)];
          break;
      }
      for (uint32_t y = 0; y < 4 && by * 4 + y < height; ++y)
        for (uint32_t x = 0; x < 4 && bx * 4 + x < width; ++x)
          std::memcpy(image.at(bx * 4 + x, by * 4 + y), texels[y * 4 + x].data(), 4);
    }
  return image;
}

}  // namespace fx
