// Shader model 1 assembly as effect files write it (vs.1.0/1.1, ps.1.0-1.4), parsed from the
// effect's tokens into instructions with located operands: what the HLSL translation
// (assembly.h) and the tests' CPU interpreter both read.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fx/ast.h"
#include "fx/diagnostic.h"

namespace fx::emulation {

// The version line: vs.1.1, ps.1.4 (or vs_1_1).
struct AsmVersion {
  bool pixel = false;
  int major = 1, minor = 1;
  std::string spelled() const;  // "ps.1.4"
};

// A register file. Output files are the vertex shader's (oPos, oD#, oT#, oFog, oPts).
enum class RegisterFile : uint8_t {
  temp,
  input,
  constant,
  texture,
  address,
  out_position,
  out_color,
  out_texcoord,
  out_fog,
  out_point_size
};

// One source operand: `-r1.zxyw`, `1-t0`, `v0_bx2`, `c[a0.x + 4]`, `r0.a`.
struct AsmSource {
  RegisterFile file = RegisterFile::temp;
  uint32_t index = 0;
  bool relative = false;  // c[a0.x + index]
  std::array<uint8_t, 4> swizzle{0, 1, 2, 3};
  bool negate = false, invert = false;         // `-x`, `1-x`
  bool bias = false, bx2 = false, x2 = false;  // _bias, _bx2, _x2 (ps.1.4)
  uint8_t divide = 0;                          // ps.1.4 _dz/_db (3: by z), _dw/_da (4: by w)
  SourceRange range;
};

// The destination: register and write mask (bit 0 = x/r ... bit 3 = w/a).
struct AsmDest {
  RegisterFile file = RegisterFile::temp;
  uint32_t index = 0;
  uint8_t mask = 0xF;
  SourceRange range;
};

struct AsmInstruction {
  std::string op;         // base opcode, lower case: "dp3", "texm3x2pad", "def", "phase"
  int scale = 0;          // result scaled by 2^scale: _x2 1, _x4 2, _x8 3, _d2 -1, _d4 -2, _d8 -3
  bool saturate = false;  // _sat
  bool coissue = false;   // `+` in front: runs alongside the previous instruction
  bool has_dest = false;
  AsmDest dest;
  std::vector<AsmSource> sources;
  std::array<double, 4> literal{0, 0, 0, 0};  // def c#, x, y, z, w
  std::string usage;                          // vs dcl_<usage><n>: "position", "texcoord"
  uint32_t usage_index = 0;
  uint32_t phase = 0;  // ps.1.4: 1 after `phase`
  SourceRange range;
};

// A vertex input register and the mesh semantic it reads.
struct AsmInput {
  uint32_t reg = 0;
  std::string semantic;  // "POSITION", "NORMAL", "TEXCOORD0", "TANGENT"
};

struct AsmProgram {
  AsmVersion version;
  std::vector<AsmInstruction> instructions;  // `def`, `dcl` and `phase` included, in order
  std::vector<AsmInput> inputs;              // vertex shaders: every v# read, with its semantic
  SourceRange range;                         // the version token
};

// Parses `code` (and a vertex shader's `decl { }` in `decl`, possibly empty) of `effect`.
// Errors are reported at the instruction's token; nullopt when any was.
std::optional<AsmProgram> parse_assembly(const ast::Effect& effect, ast::TokenSpan code, ast::TokenSpan decl,
                                         DiagnosticSink& sink);

// The version on the first line of `code` (any shader model: ps_2_0 asm is D3D9 too), or
// nullopt when there is none.
std::optional<AsmVersion> assembly_version(const ast::Effect& effect, ast::TokenSpan code);

// The mesh semantic of vertex input register v`reg` with no `dcl`: DirectX 8's D3DVSDE
// numbering (v0 POSITION, v3 NORMAL, v5/v6 COLOR0/1, v7 TEXCOORD0), except that v8
// (D3DVSDE_TEXCOORD1) reads TANGENT: every DirectX 8 bump-mapping listing, the seeds
// included, stores its tangent there.
std::string dx8_input_semantic(uint32_t reg);

}  // namespace fx::emulation
