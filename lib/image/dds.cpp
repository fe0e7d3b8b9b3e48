// The DDS container: DX9 and DX10 headers read into subresources in a DXGI format.
#include <algorithm>
#include <cstring>

#include "fx/dds.h"

namespace fx {
namespace {

constexpr uint32_t fourcc(char a, char b, char c, char d) {
  return uint32_t(uint8_t(a)) | uint32_t(uint8_t(b)) << 8 | uint32_t(uint8_t(c)) << 16 | uint32_t(uint8_t(d)) << 24;
}

// DDS_HEADER flags and caps (ddraw.h / dds.h).
constexpr uint32_t kPfAlphaPixels = 0x1, kPfAlpha = 0x2, kPfFourCC = 0x4, kPfRgb = 0x40, kPfLuminance = 0x20000;
constexpr uint32_t kCaps2Cubemap = 0x200, kCaps2Volume = 0x200000;
constexpr uint32_t kMiscTextureCube = 0x4;
constexpr uint32_t kDimension1d = 2, kDimension2d = 3, kDimension3d = 4;
constexpr size_t kHeaderBytes = 4 + 124, kDx10Bytes = 20;
constexpr uint32_t kMaxSize = 16384, kMaxLayers = 2048;

uint32_t u32(std::span<const uint8_t> b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

// The DX9 pixel format, as its masks and FourCC say.
struct LegacyFormat {
  uint32_t flags, fourcc, bits, r, g, b, a;
};

// How texels of a DX9 format without a DXGI twin become RGBA8.
enum class Expand { none, bgr24, bgrx32, luminance8, luminance_alpha16, alpha8 };

struct Mapped {
  DxgiFormat format;
  Expand expand = Expand::none;
};

std::optional<Mapped> map_legacy(const LegacyFormat& f) {
  if (f.flags & kPfFourCC) {
    switch (f.fourcc) {
      case fourcc('D', 'X', 'T', '1'): return Mapped{DxgiFormat::bc1_unorm};
      case fourcc('D', 'X', 'T', '2'):
      case fourcc('D', 'X', 'T', '3'): return Mapped{DxgiFormat::bc2_unorm};
      case fourcc('D', 'X', 'T', '4'):
      case fourcc('D', 'X', 'T', '5'): return Mapped{DxgiFormat::bc3_unorm};
      case fourcc('A', 'T', 'I', '1'):
      case fourcc('B', 'C', '4', 'U'): return Mapped{DxgiFormat::bc4_unorm};
      case fourcc('B', 'C', '4', 'S'): return Mapped{DxgiFormat::bc4_snorm};
      case fourcc('A', 'T', 'I', '2'):
      case fourcc('B', 'C', '5', 'U'): return Mapped{DxgiFormat::bc5_unorm};
      case fourcc('B', 'C', '5', 'S'): return Mapped{DxgiFormat::bc5_snorm};
      // D3DFORMAT values stored as a FourCC.
      case 36: return Mapped{DxgiFormat::r16g16b16a16_unorm};
      case 111: return Mapped{DxgiFormat::r16_float};
      case 112: return Mapped{DxgiFormat::r16g16_float};
      case 113: return Mapped{DxgiFormat::r16g16b16a16_float};
      case 114: return Mapped{DxgiFormat::r32_float};
      case 115: return Mapped{DxgiFormat::r32g32_float};
      case 116: return Mapped{DxgiFormat::r32g32b32a32_float};
      default: return std::nullopt;
    }
  }
  const bool alpha = f.flags & kPfAlphaPixels;
  if (f.flags & kPfRgb) {
    if (f.bits == 32 && f.r == 0xff && f.g == 0xff00 && f.b == 0xff0000)
      return Mapped{DxgiFormat::r8g8b8a8_unorm, alpha ? Expand::none : Expand::bgrx32};
    if (f.bits == 32 && f.r == 0xff0000 && f.g == 0xff00 && f.b == 0xff)
      return alpha ? Mapped{DxgiFormat::b8g8r8a8_unorm} : Mapped{DxgiFormat::r8g8b8a8_unorm, Expand::bgrx32};
    if (f.bits == 32 && f.r == 0x3ff && f.g == 0xffc00 && f.b == 0x3ff00000)
      return Mapped{DxgiFormat::r10g10b10a2_unorm};
    if (f.bits == 24 && f.r == 0xff0000 && f.g == 0xff00 && f.b == 0xff)
      return Mapped{DxgiFormat::r8g8b8a8_unorm, Expand::bgr24};
    return std::nullopt;
  }
  if ((f.flags & kPfLuminance) && f.bits == 8) return Mapped{DxgiFormat::r8g8b8a8_unorm, Expand::luminance8};
  if ((f.flags & kPfLuminance) && f.bits == 16 && f.r == 0xff)
    return Mapped{DxgiFormat::r8g8b8a8_unorm, Expand::luminance_alpha16};
  if ((f.flags & kPfAlpha) && f.bits == 8) return Mapped{DxgiFormat::r8g8b8a8_unorm, Expand::alpha8};
  return std::nullopt;
}

uint32_t source_texel_bytes(Expand e) {
  switch (e) {
    case Expand::bgr24: return 3;
    case Expand::luminance8:
    case Expand::alpha8: return 1;
    case Expand::luminance_alpha16: return 2;
    default: return 4;
  }
}

// One texel of a legacy layout as RGBA8. BGRX's first byte is blue only when the red mask is
// 0xff0000; the RGBX order (red mask 0xff) keeps its byte order.
void expand_texel(Expand e, bool bgr_order, const uint8_t* in, uint8_t* out) {
  switch (e) {
    case Expand::bgr24: out[0] = in[2], out[1] = in[1], out[2] = in[0], out[3] = 255; return;
    case Expand::bgrx32:
      out[0] = bgr_order ? in[2] : in[0], out[1] = in[1], out[2] = bgr_order ? in[0] : in[2], out[3] = 255;
      return;
    case Expand::luminance8: out[0] = out[1] = out[2] = in[0], out[3] = 255; return;
    case Expand::luminance_alpha16: out[0] = out[1] = out[2] = in[0], out[3] = in[1]; return;
    case Expand::alpha8: out[0] = out[1] = out[2] = 0, out[3] = in[0]; return;
    case Expand::none: std::memcpy(out, in, 4); return;
  }
}

uint32_t mip_extent(uint32_t size, uint32_t mip) { return std::max(1u, size >> mip); }

}  // namespace

std::optional<DxgiFormatInfo> dxgi_format_info(uint32_t format) {
  switch (DxgiFormat(format)) {
    case DxgiFormat::r32g32b32a32_float:
    case DxgiFormat::r32g32b32a32_uint:
    case DxgiFormat::r32g32b32a32_sint: return DxgiFormatInfo{false, 16};
    case DxgiFormat::r16g16b16a16_float:
    case DxgiFormat::r16g16b16a16_unorm:
    case DxgiFormat::r32g32_float: return DxgiFormatInfo{false, 8};
    case DxgiFormat::r10g10b10a2_unorm:
    case DxgiFormat::r8g8b8a8_unorm:
    case DxgiFormat::r8g8b8a8_unorm_srgb:
    case DxgiFormat::r16g16_float:
    case DxgiFormat::r32_float:
    case DxgiFormat::b8g8r8a8_unorm:
    case DxgiFormat::b8g8r8a8_unorm_srgb: return DxgiFormatInfo{false, 4};
    case DxgiFormat::r8g8_unorm:
    case DxgiFormat::r16_float: return DxgiFormatInfo{false, 2};
    case DxgiFormat::r8_unorm: return DxgiFormatInfo{false, 1};
    case DxgiFormat::bc1_unorm:
    case DxgiFormat::bc1_unorm_srgb:
    case DxgiFormat::bc4_unorm:
    case DxgiFormat::bc4_snorm: return DxgiFormatInfo{true, 8};
    case DxgiFormat::bc2_unorm:
    case DxgiFormat::bc2_unorm_srgb:
    case DxgiFormat::bc3_unorm:
    case DxgiFormat::bc3_unorm_srgb:
    case DxgiFormat::bc5_unorm:
    case DxgiFormat::bc5_snorm:
    case DxgiFormat::bc6h_uf16:
    case DxgiFormat::bc6h_sf16:
    case DxgiFormat::bc7_unorm:
    case DxgiFormat::bc7_unorm_srgb: return DxgiFormatInfo{true, 16};
  }
  return std::nullopt;
}

uint64_t dxgi_slice_bytes(DxgiFormatInfo info, uint32_t width, uint32_t height) {
  if (info.block_compressed) return uint64_t((width + 3) / 4) * ((height + 3) / 4) * info.bytes;
  return uint64_t(width) * height * info.bytes;
}

bool is_dds(std::span<const uint8_t> bytes) { return bytes.size() >= 4 && u32(bytes, 0) == fourcc('D', 'D', 'S', ' '); }

std::optional<DdsTexture> decode_dds(std::span<const uint8_t> bytes, DiagnosticSink& sink, const std::string& origin) {
  const std::string from = origin.empty() ? "DDS data" : "DDS file '" + origin + "'";
  auto fail = [&](const std::string& why) {
    sink.error("image-decode-failed", {}, from + ": " + why);
    return std::nullopt;
  };
  if (!is_dds(bytes)) return fail("no DDS magic");
  if (bytes.size() < kHeaderBytes) return fail("truncated header");
  if (u32(bytes, 4) != 124 || u32(bytes, 4 + 72) != 32) return fail("header sizes are not 124 and 32");
  DdsTexture t;
  t.height = u32(bytes, 4 + 8);
  t.width = u32(bytes, 4 + 12);
  const uint32_t depth = u32(bytes, 4 + 20);
  t.mip_levels = std::max(1u, u32(bytes, 4 + 24));
  const LegacyFormat legacy{u32(bytes, 4 + 76), u32(bytes, 4 + 80), u32(bytes, 4 + 84), u32(bytes, 4 + 88),
                            u32(bytes, 4 + 92), u32(bytes, 4 + 96), u32(bytes, 4 + 100)};
  const uint32_t caps2 = u32(bytes, 4 + 108);
  size_t data_at = kHeaderBytes;
  Expand expand = Expand::none;
  const bool bgr_order = legacy.r == 0xff0000;
  if ((legacy.flags & kPfFourCC) && legacy.fourcc == fourcc('D', 'X', '1', '0')) {
    if (bytes.size() < kHeaderBytes + kDx10Bytes) return fail("truncated DX10 header");
    const uint32_t format = u32(bytes, kHeaderBytes), dimension = u32(bytes, kHeaderBytes + 4);
    const uint32_t misc = u32(bytes, kHeaderBytes + 8), array_size = u32(bytes, kHeaderBytes + 12);
    data_at += kDx10Bytes;
    if (!dxgi_format_info(format)) {
      sink.error("image-format-unsupported", {}, from + ": DXGI format " + std::to_string(format) + " is not read");
      return std::nullopt;
    }
    t.format = DxgiFormat(format);
    t.layers = std::max(1u, array_size);
    if (dimension == kDimension1d) t.shape = DdsShape::texture1d;
    else if (dimension == kDimension3d) t.shape = DdsShape::volume;
    else if (dimension == kDimension2d) t.shape = (misc & kMiscTextureCube) ? DdsShape::cube : DdsShape::texture2d;
    else return fail("resource dimension " + std::to_string(dimension) + " is not a texture");
    if (t.shape == DdsShape::cube) {
      if (t.layers > kMaxLayers / 6) return fail("too many array elements");
      t.layers *= 6;
    }
  } else {
    std::optional<Mapped> mapped = map_legacy(legacy);
    if (!mapped) {
      sink.error("image-format-unsupported", {},
                 from + ": pixel format (flags " + std::to_string(legacy.flags) + ", FourCC " +
                     std::to_string(legacy.fourcc) + ", " + std::to_string(legacy.bits) + " bits) is not read");
      return std::nullopt;
    }
    t.format = mapped->format;
    expand = mapped->expand;
    if (caps2 & kCaps2Cubemap) {
      // A DX9 cube holds only the faces its caps name; fxkit reads complete cubes.
      if ((caps2 & 0xfc00) != 0xfc00) return fail("a cube map without all six faces");
      t.shape = DdsShape::cube;
      t.layers = 6;
    } else if (caps2 & kCaps2Volume) {
      t.shape = DdsShape::volume;
    }
  }
  if (t.shape == DdsShape::volume) {
    t.depth = std::max(1u, depth);
    if (t.layers != 1) return fail("an array of volumes");
  }
  if (t.shape == DdsShape::texture1d) t.height = 1;
  if (t.width == 0 || t.height == 0 || t.width > kMaxSize || t.height > kMaxSize || t.depth > kMaxSize / 8)
    return fail("size " + std::to_string(t.width) + "x" + std::to_string(t.height) + "x" + std::to_string(t.depth) +
                " is empty or too large");
  if (t.layers > kMaxLayers) return fail("too many array elements");
  if (t.shape == DdsShape::cube && t.width != t.height) return fail("cube faces are not square");
  uint32_t full_chain = 1;
  while ((std::max({t.width, t.height, t.depth}) >> full_chain) != 0) ++full_chain;
  if (t.mip_levels > full_chain)
    return fail(std::to_string(t.mip_levels) + " mip levels; the size has at most " + std::to_string(full_chain));

  const DxgiFormatInfo info = *dxgi_format_info(uint32_t(t.format));
  const uint32_t in_texel = source_texel_bytes(expand);
  uint64_t at = data_at;
  for (uint32_t layer = 0; layer < t.layers; ++layer)
    for (uint32_t mip = 0; mip < t.mip_levels; ++mip) {
      DdsSubresource s;
      s.layer = layer, s.mip = mip;
      s.width = mip_extent(t.width, mip), s.height = mip_extent(t.height, mip), s.depth = mip_extent(t.depth, mip);
      const uint64_t texels = uint64_t(s.width) * s.height * s.depth;
      const uint64_t in_size =
          expand == Expand::none ? dxgi_slice_bytes(info, s.width, s.height) * s.depth : texels * in_texel;
      if (at + in_size > bytes.size())
        return fail("truncated data (layer " + std::to_string(layer) + ", mip " + std::to_string(mip) + ")");
      s.offset = t.data.size();
      if (expand == Expand::none) {
        s.size = in_size;
        t.data.insert(t.data.end(), bytes.begin() + at, bytes.begin() + at + in_size);
      } else {
        s.size = texels * 4;
        t.data.resize(t.data.size() + s.size);
        for (uint64_t i = 0; i < texels; ++i)
          expand_texel(expand, bgr_order, bytes.data() + at + i * in_texel, t.data.data() + s.offset + i * 4);
      }
      at += in_size;
      t.subresources.push_back(s);
    }
  return t;
}

}  // namespace fx
