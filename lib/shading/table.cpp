#include "fx/shading/table.h"

#include <cmath>

namespace fx::shading {

Table Table::make(int width, int height, int depth, int channels, TableFormat format) {
  Table t;
  t.width = width > 0 ? width : 1;
  t.height = height > 0 ? height : 1;
  t.depth = depth > 0 ? depth : 1;
  t.channels = channels < 1 ? 1 : channels > 4 ? 4 : channels;
  t.format = format;
  if (format == TableFormat::unorm8) t.unorm8.assign(t.value_count(), 0);
  else t.float32.assign(t.value_count(), 0.0f);
  return t;
}

size_t Table::value_count() const { return size_t(width) * size_t(height) * size_t(depth) * size_t(channels); }

size_t Table::index(int x, int y, int z, int c) const {
  return ((size_t(z) * size_t(height) + size_t(y)) * size_t(width) + size_t(x)) * size_t(channels) + size_t(c);
}

void Table::store(int x, int y, int z, int c, double v) {
  size_t i = index(x, y, z, c);
  if (format == TableFormat::unorm8) {
    double s = v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;  // NaN -> 0
    unorm8[i] = uint8_t(std::lround(s * 255.0));
  } else {
    float32[i] = float(v);
  }
}

float Table::fetch(int x, int y, int z, int c) const {
  size_t i = index(x, y, z, c);
  return format == TableFormat::unorm8 ? float(unorm8[i]) / 255.0f : float32[i];
}

glm::dvec3 cube_direction(int face, double s, double t) {
  const double a = 2.0 * s - 1.0, b = 2.0 * t - 1.0;
  switch (face) {
    case 0: return {1.0, -b, -a};
    case 1: return {-1.0, -b, a};
    case 2: return {a, 1.0, b};
    case 3: return {a, -1.0, -b};
    case 4: return {a, -b, 1.0};
    default: return {-a, -b, -1.0};
  }
}

namespace {

// Texel index and weight along one axis of n texels for normalized coordinate s.
struct AxisTaps {
  int i0 = 0, i1 = 0;
  float w1 = 0;  // weight of i1
};

int wrap_index(long i, int n) {
  long m = i % n;
  return int(m < 0 ? m + n : m);
}

AxisTaps axis_taps(float s, int n, AddressMode address) {
  AxisTaps a;
  if (n <= 1 || !std::isfinite(s)) return a;
  float x = s * float(n) - 0.5f;
  if (address == AddressMode::wrap) {
    // Reduce first so huge coordinates do not overflow the integer conversion.
    x = x - float(n) * std::floor(x / float(n));
    float f = std::floor(x);
    a.w1 = x - f;
    a.i0 = wrap_index(long(f), n);
    a.i1 = wrap_index(long(f) + 1, n);
    return a;
  }
  float lo = 0.0f, hi = float(n - 1);
  x = x < lo ? lo : x > hi ? hi : x;
  float f = std::floor(x);
  a.i0 = int(f);
  a.i1 = a.i0 + 1 < n ? a.i0 + 1 : n - 1;
  a.w1 = x - f;
  return a;
}

}  // namespace

glm::vec4 sample_linear(const Table& table, const glm::vec3& coord, AddressMode address) {
  glm::vec4 out(0.0f);
  if (table.value_count() == 0 ||
      (table.format == TableFormat::unorm8 ? table.unorm8.size() : table.float32.size()) != table.value_count())
    return out;
  AxisTaps ax = axis_taps(coord.x, table.width, address);
  AxisTaps ay = axis_taps(coord.y, table.height, address);
  AxisTaps az = axis_taps(coord.z, table.depth, address);
  for (int c = 0; c < table.channels && c < 4; ++c) {
    float v = 0.0f;
    for (int k = 0; k < 2; ++k) {
      float wz = k ? az.w1 : 1.0f - az.w1;
      if (wz == 0.0f) continue;
      int z = k ? az.i1 : az.i0;
      for (int j = 0; j < 2; ++j) {
        float wy = j ? ay.w1 : 1.0f - ay.w1;
        if (wy == 0.0f) continue;
        int y = j ? ay.i1 : ay.i0;
        float row = (1.0f - ax.w1) * table.fetch(ax.i0, y, z, c) + ax.w1 * table.fetch(ax.i1, y, z, c);
        v += wz * wy * row;
      }
    }
    out[c] = v;
  }
  return out;
}

}  // namespace fx::shading
