// DirectDraw Surface (.dds) textures: the container read into subresources (DX9 and DX10
// headers; 1D, 2D, cube, volume, arrays, mip chains), texel data kept in its DXGI format
// (block-compressed data stays compressed), and a CPU decoder of BC1-BC5 blocks for devices
// that cannot sample them.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/image.h"

namespace fx {

// The DXGI formats a DDS file may hold that fxkit uploads (values as in dxgiformat.h).
// DX9 files are mapped onto these by their FourCC or bit masks; formats a GPU has no
// equivalent of (24-bit RGB, luminance, BGRX, A8) are expanded to r8g8b8a8_unorm on read.
enum class DxgiFormat : uint32_t {
  r32g32b32a32_float = 2,
  r32g32b32a32_uint = 3,
  r32g32b32a32_sint = 4,
  r16g16b16a16_float = 10,
  r16g16b16a16_unorm = 11,
  r32g32_float = 16,
  r10g10b10a2_unorm = 24,
  r8g8b8a8_unorm = 28,
  r8g8b8a8_unorm_srgb = 29,
  r16g16_float = 34,
  r32_float = 41,
  r8g8_unorm = 49,
  r16_float = 54,
  r8_unorm = 61,
  bc1_unorm = 71,
  bc1_unorm_srgb = 72,
  bc2_unorm = 74,
  bc2_unorm_srgb = 75,
  bc3_unorm = 77,
  bc3_unorm_srgb = 78,
  bc4_unorm = 80,
  bc4_snorm = 81,
  bc5_unorm = 83,
  bc5_snorm = 84,
  b8g8r8a8_unorm = 87,
  b8g8r8a8_unorm_srgb = 91,
  bc6h_uf16 = 95,
  bc6h_sf16 = 96,
  bc7_unorm = 98,
  bc7_unorm_srgb = 99,
};

// How a format's data is laid out: 4x4 blocks of `block_bytes`, or single texels.
struct DxgiFormatInfo {
  bool block_compressed = false;
  uint32_t bytes = 0;  // per 4x4 block when block_compressed, else per texel
};
// Layout of `format`; nullopt for a value outside DxgiFormat.
std::optional<DxgiFormatInfo> dxgi_format_info(uint32_t format);
// Bytes of one width x height slice (block formats round up to whole blocks).
uint64_t dxgi_slice_bytes(DxgiFormatInfo info, uint32_t width, uint32_t height);

enum class DdsShape { texture1d, texture2d, cube, volume };

// One mip level of one array element (a cube has six elements per cube, in +X -X +Y -Y +Z -Z
// order): `depth` slices of `width` x `height`, `size` bytes at `offset` in DdsTexture::data.
struct DdsSubresource {
  uint32_t layer = 0, mip = 0;
  uint32_t width = 0, height = 0, depth = 0;
  uint64_t offset = 0, size = 0;
};

struct DdsTexture {
  DxgiFormat format = DxgiFormat::r8g8b8a8_unorm;
  DdsShape shape = DdsShape::texture2d;
  uint32_t width = 0, height = 0, depth = 1;
  uint32_t mip_levels = 1;
  uint32_t layers = 1;                       // array elements; for a cube, six per cube
  std::vector<DdsSubresource> subresources;  // layer-major, then mip
  std::vector<uint8_t> data;
};

// True when `bytes` start with the DDS magic ("DDS ").
bool is_dds(std::span<const uint8_t> bytes);
// Reads a DDS file from memory. `origin` names it in messages. Reports "image-decode-failed"
// on a truncated or inconsistent file and "image-format-unsupported" on a pixel format
// fxkit does not read.
std::optional<DdsTexture> decode_dds(std::span<const uint8_t> bytes, DiagnosticSink& sink,
                                     const std::string& origin = "");

// True when decode_bc_rgba8 can expand `format` (BC1, BC2, BC3, BC4 and BC5 unorm, and their
// sRGB variants, which decode to the same bytes).
bool bc_decodable(DxgiFormat format);
// Expands one subresource slice of block-compressed data (width x height texels) into RGBA8,
// as a device samples it: BC4 gives (r, 0, 0, 255), BC5 (r, g, 0, 255). `blocks` must hold
// dxgi_slice_bytes of the slice. Empty image for a format bc_decodable rejects.
Image decode_bc_rgba8(DxgiFormat format, std::span<const uint8_t> blocks, uint32_t width, uint32_t height);

}  // namespace fx
