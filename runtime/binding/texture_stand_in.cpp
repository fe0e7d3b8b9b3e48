// Texture stand-ins: which one a parameter gets, and the texels of the preview ones.
#include "fx/binding/texture_stand_in.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

namespace fx::vk {
namespace {

bool contains(std::string_view text, std::string_view word) {
  return std::search(text.begin(), text.end(), word.begin(), word.end(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
         }) != text.end();
}

bool iequals(std::string_view a, std::string_view b) { return a.size() == b.size() && contains(a, b); }

using Rgb = std::array<float, 3>;

// A saturated hue, h in [0, 1).
Rgb hue(float h) {
  Rgb c;
  for (int i = 0; i < 3; ++i) {
    const float k = std::fmod(float(5 - 2 * i) + h * 6.0f, 6.0f);
    c[i] = 1.0f - std::clamp(std::min(k, 4.0f - k), 0.0f, 1.0f);
  }
  return c;
}

Rgb mix(const Rgb& a, const Rgb& b, float t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

void put(std::vector<uint8_t>& data, const Rgb& c) {
  for (float v : c) data.push_back(uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)));
  data.push_back(255);
}

// Texel (x, y, z) of a size^3 (or smaller) test pattern.
Rgb pattern(uint32_t x, uint32_t y, uint32_t z, uint32_t width, uint32_t height, uint32_t depth) {
  if (x % 16 == 8 || y % 16 == 8) return {0.1f, 0.1f, 0.1f};
  Rgb c = hue(float(x) / float(width));
  const float shade = 1.0f - 0.6f * float(y) / float(std::max(height - 1, 1u));
  for (float& v : c) v *= shade;
  return mix(c, {1, 1, 1}, 0.5f * float(z) / float(std::max(depth, 1u)));
}

// The direction through texel (x, y) of cube face `face` (+X -X +Y -Y +Z -Z), normalised.
std::array<float, 3> cube_direction(uint32_t face, uint32_t x, uint32_t y, uint32_t size) {
  const float s = 2.0f * (float(x) + 0.5f) / float(size) - 1.0f, t = 2.0f * (float(y) + 0.5f) / float(size) - 1.0f;
  std::array<float, 3> d;
  switch (face) {
    case 0: d = {1, -t, -s}; break;
    case 1: d = {-1, -t, s}; break;
    case 2: d = {s, 1, t}; break;
    case 3: d = {s, -1, -t}; break;
    case 4: d = {s, -t, 1}; break;
    default: d = {-s, -t, -1}; break;
  }
  const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (float& v : d) v /= len;
  return d;
}

Rgb environment(const std::array<float, 3>& d) {
  const Rgb sky{0.25f, 0.45f, 0.9f}, horizon{0.95f, 0.85f, 0.7f}, ground{0.3f, 0.22f, 0.15f};
  const Rgb base = d[1] >= 0 ? mix(horizon, sky, std::sqrt(d[1])) : mix(horizon, ground, std::sqrt(-d[1]));
  const float compass = std::atan2(d[2], d[0]) / (2.0f * 3.14159265f) + 0.5f;
  return mix(base, hue(compass), 0.25f * (1.0f - std::abs(d[1])));  // none at the poles
}

// One texel (a face each for a cube) of four 32-bit zeros, in the shape `dim`.
fx::DdsTexture integer_zeros(fx::DxgiFormat format, ImageDim dim) {
  fx::DdsTexture t;
  t.format = format;
  t.width = t.height = t.depth = 1;
  t.shape = dim == ImageDim::dim_1d   ? fx::DdsShape::texture1d
            : dim == ImageDim::dim_3d ? fx::DdsShape::volume
            : dim == ImageDim::cube   ? fx::DdsShape::cube
                                      : fx::DdsShape::texture2d;
  if (dim == ImageDim::cube) t.layers = 6;
  constexpr uint64_t kTexel = 16;
  t.data.assign(kTexel * t.layers, 0);
  for (uint32_t layer = 0; layer < t.layers; ++layer)
    t.subresources.push_back({layer, 0, 1, 1, 1, layer * kTexel, kTexel});
  return t;
}

}  // namespace

StandIn texture_stand_in(const Parameter* param, ImageDim dim, bool preview) {
  std::string_view name = param ? std::string_view(param->name) : std::string_view();
  auto named = [&](std::string_view word) {
    if (contains(name, word)) return true;
    for (const char* annotation : {"UIName", "ResourceName"})
      if (const Annotation* a = param ? find_annotation(param->annotations, annotation) : nullptr)
        if (a->value.is_string() && contains(a->value.text, word)) return true;
    return false;
  };
  const std::string_view semantic = param ? std::string_view(param->semantic) : std::string_view();
  if (iequals(semantic, "NORMALMAP") || iequals(semantic, "NORMAL") || named("normal") || named("bump"))
    return StandIn::flat_normal;
  if (named("shadow") || !preview) return StandIn::white;
  if (named("depth") || contains(semantic, "DEPTH")) return StandIn::depth_ramp;
  return dim == ImageDim::cube ? StandIn::environment : StandIn::test_pattern;
}

const char* stand_in_name(StandIn kind) {
  switch (kind) {
    case StandIn::flat_normal: return "flat normal";
    case StandIn::depth: return "depth of 1.0";
    case StandIn::multisampled: return "white multisampled texture";
    case StandIn::test_pattern: return "colour test pattern";
    case StandIn::depth_ramp: return "ramp of depths";
    case StandIn::environment: return "sky-and-ground environment";
    case StandIn::signed_zero: return "zero signed-integer texture";
    case StandIn::unsigned_zero: return "zero unsigned-integer texture";
    default: return "white texture";
  }
}

fx::DdsTexture stand_in_texels(StandIn kind, ImageDim dim) {
  if (kind == StandIn::signed_zero) return integer_zeros(fx::DxgiFormat::r32g32b32a32_sint, dim);
  if (kind == StandIn::unsigned_zero) return integer_zeros(fx::DxgiFormat::r32g32b32a32_uint, dim);
  fx::DdsTexture t;
  if (kind != StandIn::test_pattern && kind != StandIn::depth_ramp && kind != StandIn::environment) return t;
  t.format = fx::DxgiFormat::r8g8b8a8_unorm;
  switch (dim) {
    case ImageDim::dim_1d: t.shape = fx::DdsShape::texture1d, t.width = 64, t.height = 1; break;
    case ImageDim::dim_3d: t.shape = fx::DdsShape::volume, t.width = t.height = t.depth = 16; break;
    case ImageDim::cube: t.shape = fx::DdsShape::cube, t.width = t.height = 32, t.layers = 6; break;
    default: t.shape = fx::DdsShape::texture2d, t.width = t.height = 64; break;
  }
  for (uint32_t layer = 0; layer < t.layers; ++layer) {
    const uint64_t offset = t.data.size();
    for (uint32_t z = 0; z < t.depth; ++z)
      for (uint32_t y = 0; y < t.height; ++y)
        for (uint32_t x = 0; x < t.width; ++x) {
          if (kind == StandIn::depth_ramp) {
            const float v = float(x + y) / float(std::max(t.width + t.height - 2, 1u));
            put(t.data, {v, v, v});
          } else if (kind == StandIn::environment && t.shape == fx::DdsShape::cube)
            put(t.data, environment(cube_direction(layer, x, y, t.width)));
          else put(t.data, pattern(x, y, z, t.width, t.height, t.depth));
        }
    t.subresources.push_back({layer, 0, t.width, t.height, t.depth, offset, t.data.size() - offset});
  }
  return t;
}

}  // namespace fx::vk
