// A baked lookup table (1D/2D/3D texture contents) and a software sampler that filters it
// the way a GPU does (linear filtering, texel centres at (i + 0.5) / N, clamp or wrap).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace fx::shading {

enum class TableFormat { unorm8, float32 };

// Texel data, x fastest, then y, then z; channels interleaved.
struct Table {
  int width = 0, height = 1, depth = 1;
  int channels = 1;
  TableFormat format = TableFormat::float32;
  // A cube map: depth 6 holds the faces +X, -X, +Y, -Y, +Z, -Z (cube_direction gives the
  // direction of each texel); sample_linear does not read cube tables.
  bool cube = false;
  std::vector<uint8_t> unorm8;  // used when format == unorm8
  std::vector<float> float32;   // used when format == float32

  // An all-zero table of the given shape (sizes must be >= 1, channels 1..4).
  static Table make(int width, int height, int depth, int channels, TableFormat format);
  // Number of stored values (texels times channels).
  size_t value_count() const;
  // Index of (x, y, z, c) in the data vector; coordinates must be in range.
  size_t index(int x, int y, int z, int c) const;
  // Stores v; unorm8 rounds saturate(v) * 255 to nearest (NaN -> 0).
  void store(int x, int y, int z, int c, double v);
  // The stored value as float (unorm8 -> [0, 1]).
  float fetch(int x, int y, int z, int c) const;
};

// The (unnormalised) direction a cube-map lookup maps to face `face` (0..5: +X, -X, +Y,
// -Y, +Z, -Z) at face coordinates (s, t) in [0, 1]: the face selection table of the
// Vulkan specification, which Direct3D's cube maps share (s right, t down on each face).
glm::dvec3 cube_direction(int face, double s, double t);

enum class AddressMode { clamp, wrap };

// Linear filtering at normalized coordinate `coord` (x, y, z used per the table's
// dimensionality), float arithmetic as in a texture unit (without its 8-bit sub-texel
// weight rounding). Channels past table.channels read as 0. Non-finite coordinates
// sample texel 0.
glm::vec4 sample_linear(const Table& table, const glm::vec3& coord, AddressMode address);

}  // namespace fx::shading
