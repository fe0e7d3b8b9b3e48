// In-memory images and PNG I/O. 8-bit images are what render targets read back into and
// what golden tests compare; the float variant carries reference results and HDR data.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include "fx/diagnostic.h"

namespace fx {

// Tightly packed 8-bit image, rows top to bottom, `channels` interleaved bytes per pixel.
struct Image {
  uint32_t width = 0, height = 0, channels = 0;
  std::vector<uint8_t> pixels;  // width * height * channels bytes

  // An image of the given size with every byte zero.
  static Image blank(uint32_t width, uint32_t height, uint32_t channels);
  bool empty() const { return width == 0 || height == 0; }
  // True when every pixel equals the first: a render that drew nothing, or one flat colour.
  bool constant() const;
  // The colour of the drawn object when it is one flat colour: every pixel that differs from
  // `background` (by more than `tolerance` in a channel) is within `tolerance` of the first
  // such pixel. Nullopt when the drawn pixels vary, or when none is drawn (see constant()).
  // `background` has `channels` bytes.
  std::optional<std::vector<uint8_t>> flat_over(std::span<const uint8_t> background, int tolerance) const;
  size_t row_bytes() const { return size_t(width) * channels; }
  // Pointer to the first channel of pixel (x, y); no bounds check.
  uint8_t* at(uint32_t x, uint32_t y) { return pixels.data() + (size_t(y) * width + x) * channels; }
  const uint8_t* at(uint32_t x, uint32_t y) const { return pixels.data() + (size_t(y) * width + x) * channels; }
};

// Tightly packed float image (linear values, not clamped).
struct ImageF {
  uint32_t width = 0, height = 0, channels = 0;
  std::vector<float> pixels;

  static ImageF blank(uint32_t width, uint32_t height, uint32_t channels);
  bool empty() const { return width == 0 || height == 0; }
  float* at(uint32_t x, uint32_t y) { return pixels.data() + (size_t(y) * width + x) * channels; }
  const float* at(uint32_t x, uint32_t y) const { return pixels.data() + (size_t(y) * width + x) * channels; }
};

// The bytes of an image file; "image-open-failed" on error.
std::optional<std::vector<uint8_t>> read_image_bytes(const std::filesystem::path& path, DiagnosticSink& sink);
// Decodes PNG (or any format stb_image reads) from memory. `want_channels` 0 keeps the
// file's channel count, 1..4 converts. Reports "image-decode-failed" on error.
std::optional<Image> decode_image(std::span<const uint8_t> bytes, DiagnosticSink& sink, uint32_t want_channels = 0);
// Reads an image file; "image-open-failed" / "image-decode-failed" on error.
std::optional<Image> read_png(const std::filesystem::path& path, DiagnosticSink& sink, uint32_t want_channels = 0);
// Reads an image file as floats (.hdr keeps its range; 8-bit formats map to [0,1]).
std::optional<ImageF> read_image_float(const std::filesystem::path& path, DiagnosticSink& sink,
                                       uint32_t want_channels = 0);

// Encodes as PNG; empty vector (and "image-encode-failed") on error.
std::vector<uint8_t> encode_png(const Image& image, DiagnosticSink& sink);
// Writes a PNG file; false (and a diagnostic) on error.
bool write_png(const std::filesystem::path& path, const Image& image, DiagnosticSink& sink);

// Bytes -> floats in [0,1].
ImageF to_float(const Image& image);
// Floats -> bytes: clamps to [0,1], rounds to nearest (NaN becomes 0).
Image to_unorm8(const ImageF& image);

// How two images of the same shape differ; `comparable` is false if shapes differ.
struct ImageDiff {
  bool comparable = false;
  uint32_t max_abs = 0;               // largest per-channel difference, in LSB
  size_t channels_over = 0;           // channels differing by more than the tolerance
  uint32_t first_x = 0, first_y = 0;  // first pixel over the tolerance (if any)
};
// Compares channel by channel, counting differences above `tolerance` LSB.
ImageDiff compare(const Image& a, const Image& b, uint32_t tolerance = 0);

}  // namespace fx
