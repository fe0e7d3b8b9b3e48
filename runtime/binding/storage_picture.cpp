// Pictures of storage buffers and images: values scaled to 8-bit levels.
#include "fx/binding/storage_picture.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

namespace fx::vk {
namespace {

// A word as a number, read as `element` says (NaN for a non-finite float).
double word_value(uint32_t word, ScalarKind element) {
  switch (element) {
    case ScalarKind::float32: {
      const float f = std::bit_cast<float>(word);
      return std::isfinite(f) ? double(f) : std::numeric_limits<double>::quiet_NaN();
    }
    case ScalarKind::int32: return double(std::bit_cast<int32_t>(word));
    default: return double(word);
  }
}

// Maps values to levels from their smallest (0) to their largest (255); NaN is 0.
std::vector<uint8_t> scaled_levels(const std::vector<double>& values) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values)
    if (!std::isnan(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  std::vector<uint8_t> levels(values.size(), 0);
  if (!(hi > lo)) {
    std::fill(levels.begin(), levels.end(), uint8_t(hi == lo ? 128 : 0));
    return levels;
  }
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isnan(values[i])) levels[i] = uint8_t(std::lround((values[i] - lo) / (hi - lo) * 255.0));
  return levels;
}

}  // namespace

fx::Image buffer_picture(std::span<const uint32_t> words, ScalarKind element, uint32_t width) {
  width = std::max(1u, width);
  const uint32_t height = std::max(1u, uint32_t((words.size() + width - 1) / width));
  std::vector<double> values(size_t(width) * height);
  for (size_t i = 0; i < words.size(); ++i) values[i] = word_value(words[i], element);
  std::vector<uint8_t> levels = scaled_levels(std::vector<double>(values.begin(), values.begin() + words.size()));
  const uint8_t pad = levels.empty() ? 0 : *std::min_element(levels.begin(), levels.end());
  fx::Image image = fx::Image::blank(width, height, 4);
  for (size_t i = 0; i < values.size(); ++i) {
    const uint8_t g = i < levels.size() ? levels[i] : pad;
    uint8_t* p = &image.pixels[i * 4];
    p[0] = p[1] = p[2] = g;
    p[3] = 255;
  }
  return image;
}

fx::Image texel_picture(const StorageTexels& texels) {
  const uint32_t channels = std::max(1u, storage_format_channels(texels.format));
  const ScalarKind scalar = storage_format_scalar(texels.format);
  const size_t count = std::min(size_t(texels.width) * texels.height * channels, texels.words.size());
  std::vector<uint8_t> levels(count, 0);
  if (scalar == ScalarKind::float32) {
    for (size_t i = 0; i < count; ++i) {
      const double v = word_value(texels.words[i], scalar);
      levels[i] = std::isnan(v) ? 0 : uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    }
  } else {
    std::vector<double> values(count);
    for (size_t i = 0; i < count; ++i) values[i] = word_value(texels.words[i], scalar);
    levels = scaled_levels(values);
  }
  fx::Image image = fx::Image::blank(texels.width, texels.height, 4);
  for (size_t t = 0; t < size_t(texels.width) * texels.height && (t + 1) * channels <= count; ++t) {
    uint8_t* p = &image.pixels[t * 4];
    for (uint32_t c = 0; c < std::min(channels, 3u); ++c) p[c] = levels[t * channels + c];
    p[3] = 255;
  }
  return image;
}

}  // namespace fx::vk
