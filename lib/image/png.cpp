// PNG decode/encode through stb. This is the one translation unit holding the stb
// implementations; they are compiled static so another copy elsewhere cannot clash.
#include <cstdio>
#include <cstring>
#include <string>

#include "fx/image.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#endif
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO  // file access goes through our own reader so paths and errors are ours
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace fx {
namespace {

bool valid_channels(uint32_t c) { return c >= 1 && c <= 4; }

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  auto* p = static_cast<const uint8_t*>(data);
  out->insert(out->end(), p, p + size);
}

// `origin` names the data in messages ("" for memory).
std::optional<Image> decode(std::span<const uint8_t> bytes, DiagnosticSink& sink, uint32_t want_channels,
                            const std::string& origin) {
  std::string from = origin.empty() ? "" : " '" + origin + "'";
  if (want_channels > 4) {
    sink.error("image-decode-failed", {},
               "requested " + std::to_string(want_channels) + " channels from image" + from + "; images have 1 to 4");
    return std::nullopt;
  }
  if (bytes.size() > size_t(INT32_MAX)) {
    sink.error("image-decode-failed", {}, "image" + from + " larger than 2 GiB");
    return std::nullopt;
  }
  int w = 0, h = 0, file_channels = 0;
  stbi_uc* data = stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &file_channels, int(want_channels));
  if (!data) {
    sink.error("image-decode-failed", {}, "cannot decode image" + from + ": " + stbi_failure_reason());
    return std::nullopt;
  }
  Image image;
  image.width = uint32_t(w);
  image.height = uint32_t(h);
  image.channels = want_channels ? want_channels : uint32_t(file_channels);
  image.pixels.assign(data, data + size_t(w) * size_t(h) * image.channels);
  stbi_image_free(data);
  return image;
}

}  // namespace

std::optional<std::vector<uint8_t>> read_image_bytes(const std::filesystem::path& path, DiagnosticSink& sink) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    sink.error("image-open-failed", {}, "cannot open image '" + path.string() + "'");
    return std::nullopt;
  }
  std::vector<uint8_t> bytes;
  uint8_t chunk[1 << 16];
  size_t n;
  while ((n = std::fread(chunk, 1, sizeof chunk, f)) > 0) bytes.insert(bytes.end(), chunk, chunk + n);
  bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) {
    sink.error("image-open-failed", {}, "error reading image '" + path.string() + "'");
    return std::nullopt;
  }
  return bytes;
}

std::optional<Image> decode_image(std::span<const uint8_t> bytes, DiagnosticSink& sink, uint32_t want_channels) {
  return decode(bytes, sink, want_channels, "");
}

std::optional<Image> read_png(const std::filesystem::path& path, DiagnosticSink& sink, uint32_t want_channels) {
  auto bytes = read_image_bytes(path, sink);
  if (!bytes) return std::nullopt;
  return decode(*bytes, sink, want_channels, path.string());
}

std::optional<ImageF> read_image_float(const std::filesystem::path& path, DiagnosticSink& sink,
                                       uint32_t want_channels) {
  if (want_channels > 4) {
    sink.error("image-decode-failed", {}, "requested more than 4 channels");
    return std::nullopt;
  }
  auto bytes = read_image_bytes(path, sink);
  if (!bytes) return std::nullopt;
  if (bytes->size() > size_t(INT32_MAX)) {
    sink.error("image-decode-failed", {}, "image '" + path.string() + "' larger than 2 GiB");
    return std::nullopt;
  }
  // stbi_loadf would apply a gamma to 8-bit data; keep 8-bit images as plain unorm instead.
  if (!stbi_is_hdr_from_memory(bytes->data(), int(bytes->size()))) {
    auto image = decode(*bytes, sink, want_channels, path.string());
    if (!image) return std::nullopt;
    return to_float(*image);
  }
  int w = 0, h = 0, file_channels = 0;
  float* data = stbi_loadf_from_memory(bytes->data(), int(bytes->size()), &w, &h, &file_channels, int(want_channels));
  if (!data) {
    sink.error("image-decode-failed", {}, "cannot decode '" + path.string() + "': " + stbi_failure_reason());
    return std::nullopt;
  }
  ImageF image;
  image.width = uint32_t(w);
  image.height = uint32_t(h);
  image.channels = want_channels ? want_channels : uint32_t(file_channels);
  image.pixels.assign(data, data + size_t(w) * size_t(h) * image.channels);
  stbi_image_free(data);
  return image;
}

std::vector<uint8_t> encode_png(const Image& image, DiagnosticSink& sink) {
  std::vector<uint8_t> out;
  if (image.empty() || !valid_channels(image.channels) ||
      image.pixels.size() != size_t(image.width) * image.height * image.channels ||
      image.row_bytes() > size_t(INT32_MAX)) {
    sink.error("image-encode-failed", {},
               "cannot encode a " + std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
                   std::to_string(image.channels) + " image holding " + std::to_string(image.pixels.size()) +
                   " bytes as PNG");
    return out;
  }
  int ok = stbi_write_png_to_func(append_bytes, &out, int(image.width), int(image.height), int(image.channels),
                                  image.pixels.data(), int(image.row_bytes()));
  if (!ok) {
    sink.error("image-encode-failed", {}, "PNG encoder failed");
    out.clear();
  }
  return out;
}

bool write_png(const std::filesystem::path& path, const Image& image, DiagnosticSink& sink) {
  std::vector<uint8_t> bytes = encode_png(image, sink);
  if (bytes.empty()) return false;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    sink.error("image-write-failed", {}, "cannot create '" + path.string() + "'");
    return false;
  }
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  ok = (std::fclose(f) == 0) && ok;
  if (!ok) sink.error("image-write-failed", {}, "error writing '" + path.string() + "'");
  return ok;
}

}  // namespace fx
