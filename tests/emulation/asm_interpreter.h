// A CPU interpreter of shader model 1 assembly in double precision, written from the
// DirectX 8.1 instruction reference, independent of the HLSL translation: the tests run a
// program here and on the GPU (translated) and compare. With `hardware_precision` it models
// ps.1.x registers the same way AssemblyOptions does ([-1,1] or [-8,8], 8-bit fractions).
#pragma once
#include <array>
#include <functional>
#include <optional>

#include "fx/emulation/assembly.h"
#include "fx/emulation/assembly_program.h"

namespace fx::emulation::testing {

using Vec4 = std::array<double, 4>;

struct AsmMachine {
  std::array<Vec4, 96> c{};        // constant registers (def overrides)
  std::array<Vec4, 16> v{};        // vertex inputs, or pixel colour inputs v0/v1
  std::array<Vec4, 8> texcoord{};  // pixel shaders: interpolated TEXCOORDn
  std::array<BumpEnvironment, 8> bump{};
  // Texture stage `stage` sampled at `coords` (xyz; 2D textures read xy).
  std::function<Vec4(uint32_t stage, const Vec4& coords)> sample;
  bool hardware_precision = false;

  // Outputs after run(): pixel shaders r0; vertex shaders the o registers.
  Vec4 r0{}, pos{};
  std::array<Vec4, 2> color{};
  std::array<Vec4, 8> out_texcoord{};
  bool killed = false;
  // texdepth / texm3x2depth: the depth the pixel writes (z / w, 1 when w is 0, clamped to [0, 1]).
  std::optional<double> depth;

  void run(const AsmProgram& program);
};

}  // namespace fx::emulation::testing
