// Tileable 3D lattice noise (value and gradient), deterministic from a seed: the volume
// texture the wood seed samples with sample3d(noise, PP).
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

namespace fx::shading {

enum class NoiseKind { value, gradient };

// What to evaluate: lattice period (cells per tile along each axis), seed, kind, octaves.
struct NoiseSpec {
  int period = 8;  // the noise repeats every `period` lattice cells
  uint32_t seed = 1;
  NoiseKind kind = NoiseKind::gradient;
  int octaves = 1;  // each octave doubles frequency (and period), halves amplitude
};

// Noise at p (lattice units) for one channel (channels use decorrelated hashes), in about
// [-1, 1]; periodic: noise(p) == noise(p + period * e_i) up to the rounding of p + period,
// for any octave count.
double lattice_noise(const NoiseSpec& spec, const glm::dvec3& p, int channel);

// 32-bit integer hash (lowbias32 by C. Wellons); the lattice's only source of randomness.
uint32_t hash32(uint32_t x);

}  // namespace fx::shading
