// Writes small DDS files for the texture tests: a DX9 header (FourCC or RGBA masks, cube
// caps) or a DX10 header, followed by the data as given (layer-major, then mip).
#pragma once
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace fx::testing {

struct DdsHeader {
  uint32_t width = 1, height = 1, depth = 0, mips = 1;
  uint32_t fourcc = 0;       // DX9 FourCC ("DXT5", ...); 0 = 32-bit RGBA masks
  bool cube = false;         // DX9 cube caps (all six faces)
  uint32_t dxgi_format = 0;  // non-zero: a DX10 header with this format
  uint32_t dimension = 3;    // DX10: 2 = 1D, 3 = 2D, 4 = 3D
  uint32_t array_size = 1;   // DX10
  bool dx10_cube = false;    // DX10 TEXTURECUBE flag
};

constexpr uint32_t dds_fourcc(const char (&s)[5]) {
  return uint32_t(uint8_t(s[0])) | uint32_t(uint8_t(s[1])) << 8 | uint32_t(uint8_t(s[2])) << 16 |
         uint32_t(uint8_t(s[3])) << 24;
}

inline std::vector<uint8_t> dds_bytes(const DdsHeader& h, const std::vector<uint8_t>& data) {
  std::vector<uint32_t> w(32, 0);  // magic + 124-byte header
  w[0] = dds_fourcc("DDS ");
  w[1] = 124;
  w[2] = 0x1 | 0x2 | 0x4 | 0x1000 | (h.mips > 1 ? 0x20000 : 0) | (h.depth > 1 ? 0x800000 : 0);
  w[3] = h.height;
  w[4] = h.width;
  w[6] = h.depth;
  w[7] = h.mips;
  w[19] = 32;  // pixel format size
  if (h.dxgi_format) {
    w[20] = 0x4, w[21] = dds_fourcc("DX10");
  } else if (h.fourcc) {
    w[20] = 0x4, w[21] = h.fourcc;
  } else {
    w[20] = 0x41, w[22] = 32, w[23] = 0xff, w[24] = 0xff00, w[25] = 0xff0000, w[26] = 0xff000000;
  }
  w[27] = 0x1000 | (h.cube || h.mips > 1 ? 0x8 : 0);
  w[28] = h.cube ? 0x200 | 0xfc00 : h.depth > 1 ? 0x200000 : 0;
  if (h.dxgi_format) {
    const uint32_t dx10[5] = {h.dxgi_format, h.dimension, h.dx10_cube ? 0x4u : 0u, h.array_size, 0};
    w.insert(w.end(), dx10, dx10 + 5);
  }
  std::vector<uint8_t> out(w.size() * 4);
  std::memcpy(out.data(), w.data(), out.size());
  out.insert(out.end(), data.begin(), data.end());
  return out;
}

inline void write_dds(const std::filesystem::path& path, const DdsHeader& h, const std::vector<uint8_t>& data) {
  const std::vector<uint8_t> bytes = dds_bytes(h, data);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// One BC3 block of one colour (RGB565 `colour`) and one alpha: every index selects endpoint 0.
inline std::vector<uint8_t> bc3_solid_block(uint16_t colour, uint8_t alpha) {
  return {alpha, 0, 0, 0, 0, 0, 0, 0, uint8_t(colour & 0xff), uint8_t(colour >> 8), 0, 0, 0, 0, 0, 0};
}

}  // namespace fx::testing
