// Shader model 1 assembly (vs.1.0/1.1, ps.1.0-1.4) translated into HLSL source that the
// HLSL path compiles like any other stage: vertex inputs and outputs carry D3D semantics
// (POSITION, NORMAL, COLOR0, TEXCOORDn), constant registers read the effect parameters that
// the pass's VertexShaderConstant[n]/PixelShaderConstant[n] states name (so they update like
// any parameter), `def` and literal constants become literals, and texture stage n is the
// sampler `fx_stage<n>` (stage_texture.h says how the runtime binds it).
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fx/ast.h"
#include "fx/diagnostic.h"
#include "fx/emulation/assembly_program.h"

namespace fx::emulation {

// What a texture stage samples: the shape of the texture bound to it.
enum class StageShape : uint8_t { flat, cube, volume };

// Bump-environment matrix and luminance of one stage (BumpEnvMat00..11, LScale, LOffset).
struct BumpEnvironment {
  std::array<double, 4> matrix{0, 0, 0, 0};  // 00, 01, 10, 11
  double scale = 0, offset = 0;
};

// What a pass gives a shader besides its code.
struct AssemblyBindings {
  std::map<uint32_t, std::string> constants;  // register -> float4 HLSL expression
  std::vector<std::string> declarations;      // uniform declarations the expressions read
  std::array<StageShape, 8> shapes{};         // by stage (Texture[n]'s type)
  std::array<BumpEnvironment, 8> bump{};
};

// The pass states of `pass` that feed a `pixel` (or vertex) shader: its shader constants
// (VertexShaderConstant[n] / PixelShaderConstant[n] and the F and 1-4 forms; a parameter
// spans as many registers as D3DX uploads, column by column for a column-major matrix),
// Texture[n] shapes and the bump-environment states. `variables` are the effect's
// parameters. Problems (an unknown parameter, a non-constant literal) are errors in `sink`.
AssemblyBindings bind_pass_states(const ast::Pass& pass, bool pixel, std::span<const ast::Variable* const> variables,
                                  DiagnosticSink& sink);

struct AssemblyOptions {
  // Models ps.1.x hardware arithmetic: every register write (and the colour inputs and
  // constants) clamped to [-1,1] for ps.1.0-1.3, [-8,8] for ps.1.4, and rounded to 8-bit
  // fractions (multiples of 1/255). Off: float arithmetic. Vertex shaders ignore it.
  bool hardware_precision = false;
};

struct AssemblyTranslation {
  std::string hlsl;  // declarations, input/output structs and the entry
  std::string entry_point = "fx_main";
  std::string profile;           // what glslang compiles it as: "vs_3_0" / "ps_3_0"
  std::string emulation;         // "vs.1.1 assembly translated to HLSL"
  std::vector<uint32_t> stages;  // texture stages a pixel shader samples
};

// The HLSL for `program`. Instructions the translation does not cover are errors at the
// instruction; nullopt then.
std::optional<AssemblyTranslation> translate_assembly(const AsmProgram& program, const AssemblyBindings& bindings,
                                                      const AssemblyOptions& options, DiagnosticSink& sink);

}  // namespace fx::emulation
