// Image construction, unorm <-> float conversion and comparison.
#include "fx/image.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace fx {

Image Image::blank(uint32_t width, uint32_t height, uint32_t channels) {
  Image image{width, height, channels, {}};
  image.pixels.assign(size_t(width) * height * channels, 0);
  return image;
}

bool Image::constant() const {
  for (size_t i = channels; i < pixels.size(); ++i)
    if (pixels[i] != pixels[i % channels]) return false;
  return true;
}

std::optional<std::vector<uint8_t>> Image::flat_over(std::span<const uint8_t> background, int tolerance) const {
  auto near = [&](const uint8_t* a, const uint8_t* b) {
    for (uint32_t c = 0; c < channels; ++c)
      if (std::abs(int(a[c]) - int(b[c])) > tolerance) return false;
    return true;
  };
  const uint8_t* first = nullptr;
  for (size_t i = 0; i + channels <= pixels.size(); i += channels) {
    const uint8_t* p = pixels.data() + i;
    if (near(p, background.data())) continue;
    if (!first) first = p;
    else if (!near(p, first)) return std::nullopt;
  }
  if (!first) return std::nullopt;
  return std::vector<uint8_t>(first, first + channels);
}

ImageF ImageF::blank(uint32_t width, uint32_t height, uint32_t channels) {
  ImageF image{width, height, channels, {}};
  image.pixels.assign(size_t(width) * height * channels, 0.0f);
  return image;
}

ImageF to_float(const Image& image) {
  ImageF out{image.width, image.height, image.channels, {}};
  out.pixels.resize(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), out.pixels.begin(),
                 [](uint8_t v) { return float(v) / 255.0f; });
  return out;
}

Image to_unorm8(const ImageF& image) {
  Image out{image.width, image.height, image.channels, {}};
  out.pixels.resize(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), out.pixels.begin(), [](float v) {
    if (!(v > 0.0f)) return uint8_t(0);  // also catches NaN
    if (v >= 1.0f) return uint8_t(255);
    return uint8_t(std::lround(v * 255.0f));
  });
  return out;
}

ImageDiff compare(const Image& a, const Image& b, uint32_t tolerance) {
  ImageDiff diff;
  if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.pixels.size() != b.pixels.size())
    return diff;
  diff.comparable = true;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    uint32_t d = uint32_t(std::abs(int(a.pixels[i]) - int(b.pixels[i])));
    diff.max_abs = std::max(diff.max_abs, d);
    if (d > tolerance) {
      if (diff.channels_over == 0 && a.channels) {
        size_t pixel = i / a.channels;
        diff.first_x = uint32_t(pixel % a.width);
        diff.first_y = uint32_t(pixel / a.width);
      }
      ++diff.channels_over;
    }
  }
  return diff;
}

}  // namespace fx
