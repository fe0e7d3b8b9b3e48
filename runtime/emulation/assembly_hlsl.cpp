// Translation of parsed shader model 1 assembly into HLSL (see assembly.h): registers become
// float4 locals, each instruction one computed float4 that the instruction modifiers scale
// and saturate and the write mask stores; co-issued pairs read before either writes.
#include <algorithm>
#include <set>

#include "fx/emulation/assembly.h"
#include "fx/emulation/stage_texture.h"
#include "hlsl_literal.h"

namespace fx::emulation {
namespace {

const char kComponents[] = "xyzw";

std::string mask_suffix(uint8_t mask) {
  std::string s;
  for (int k = 0; k < 4; ++k)
    if (mask & (1 << k)) s.push_back(kComponents[k]);
  return s;
}

class Translator {
 public:
  Translator(const AsmProgram& p, const AssemblyBindings& b, const AssemblyOptions& o, DiagnosticSink& sink)
      : p_(p), b_(b), o_(o), sink_(sink), pixel_(p.version.pixel) {}

  std::optional<AssemblyTranslation> run() {
    scan();
    std::string body;
    for (size_t i = 0; i < p_.instructions.size(); ++i) {
      const AsmInstruction& ins = p_.instructions[i];
      const bool paired = i + 1 < p_.instructions.size() && p_.instructions[i + 1].coissue;
      std::string compute_a, write_a;
      if (!instruction(ins, "fx_a", compute_a, write_a)) return fail();
      if (paired) {
        std::string compute_b, write_b;
        if (!instruction(p_.instructions[i + 1], "fx_b", compute_b, write_b)) return fail();
        body += "  {\n" + compute_a + compute_b + write_a + write_b + "  }\n";
        ++i;
      } else if (!compute_a.empty() || !write_a.empty()) {
        body += "  {\n" + compute_a + write_a + "  }\n";
      }
    }
    if (failed_) return fail();
    AssemblyTranslation t;
    t.profile = pixel_ ? "ps_3_0" : "vs_3_0";
    t.emulation = p_.version.spelled() + " assembly translated to HLSL";
    t.stages.assign(stages_.begin(), stages_.end());
    t.hlsl = "// " + t.emulation + " (fxkit legacy)\n";
    for (const std::string& d : b_.declarations) t.hlsl += d + "\n";
    for (uint32_t s : stages_) t.hlsl += sampler_type(s) + " " + stage_sampler_name(s) + ";\n";
    if (pixel_) t.hlsl += pixel_shell(body);
    else t.hlsl += vertex_shell(body);
    return t;
  }

 private:
  std::optional<AssemblyTranslation> fail() { return std::nullopt; }

  bool error(SourceRange r, std::string message) {
    sink_.error("asm-translate", r, std::move(message));
    failed_ = true;
    return false;
  }

  // Which registers, constants, stages and outputs the program uses.
  void scan() {
    for (const AsmInstruction& ins : p_.instructions) {
      if (ins.op == "def") defined_[ins.dest.index] = ins.literal;
      for (const AsmSource& s : ins.sources) {
        if (s.file == RegisterFile::constant) {
          if (s.relative) relative_ = true;
          else constants_.insert(s.index);
        }
        if (s.file == RegisterFile::temp) temps_ = std::max(temps_, s.index + 1);
        if (s.file == RegisterFile::texture) textures_ = std::max(textures_, s.index + 1);
        if (s.file == RegisterFile::input && pixel_) colors_.insert(s.index);
      }
      if (ins.op == "texm3x3spec" && ins.sources.size() > 1) constants_.insert(ins.sources[1].index);
      // Matrix macros read their matrix from consecutive registers.
      if (ins.op.size() == 4 && ins.op[0] == 'm' && ins.op[2] == 'x' && ins.sources.size() == 2 &&
          ins.sources[1].file == RegisterFile::constant && !ins.sources[1].relative)
        for (uint32_t k = 1; k < uint32_t(ins.op[3] - '0'); ++k) constants_.insert(ins.sources[1].index + k);
      if (!ins.has_dest || ins.op == "def" || ins.op == "dcl") continue;
      const AsmDest& d = ins.dest;
      if (d.file == RegisterFile::temp) temps_ = std::max(temps_, d.index + 1);
      if (d.file == RegisterFile::texture) textures_ = std::max(textures_, d.index + 1);
      if (d.file == RegisterFile::out_fog) fog_ = true;
      if (d.file == RegisterFile::out_point_size) point_size_ = true;
      if (pixel_ && is_sampling(ins.op)) stages_.insert(d.index);
    }
    for (const auto& [reg, value] : defined_) constants_.insert(reg);
    temps_ = std::max<uint32_t>(temps_, pixel_ ? (p_.version.minor == 4 ? 6 : 2) : 12);
  }

  static bool is_sampling(const std::string& op) {
    return op == "tex" || op == "texbem" || op == "texbeml" || op == "texreg2ar" || op == "texreg2gb" ||
           op == "texreg2rgb" || op == "texm3x2tex" || op == "texm3x3tex" || op == "texm3x3spec" ||
           op == "texm3x3vspec" || op == "texdp3tex" || op == "texld";
  }

  std::string sampler_type(uint32_t stage) const {
    switch (b_.shapes[stage]) {
      case StageShape::cube: return "samplerCUBE";
      case StageShape::volume: return "sampler3D";
      default: return "sampler2D";
    }
  }

  // A sample of stage `stage` at float4 coordinates `coords`.
  std::string sample(uint32_t stage, const std::string& coords) const {
    const std::string s = stage_sampler_name(stage);
    switch (b_.shapes[stage]) {
      case StageShape::cube: return "texCUBE(" + s + ", (" + coords + ").xyz)";
      case StageShape::volume: return "tex3D(" + s + ", (" + coords + ").xyz)";
      default: return "tex2D(" + s + ", (" + coords + ").xy)";
    }
  }

  // The hardware register model: [-1,1] (ps.1.0-1.3) or [-8,8] (ps.1.4), 8-bit fractions.
  std::string quantize(const std::string& v) const {
    if (!pixel_ || !o_.hardware_precision) return v;
    return "fx_precision(" + v + ")";
  }

  std::string register_name(RegisterFile f, uint32_t i) const {
    switch (f) {
      case RegisterFile::temp: return "r" + std::to_string(i);
      case RegisterFile::input: return "v" + std::to_string(i);
      case RegisterFile::constant: return "c" + std::to_string(i);
      case RegisterFile::texture: return (pixel_ && p_.version.minor == 4 ? "fx_tc" : "t") + std::to_string(i);
      case RegisterFile::address: return "a0";
      case RegisterFile::out_position: return "oPos";
      case RegisterFile::out_color: return "oD" + std::to_string(i);
      case RegisterFile::out_texcoord: return "oT" + std::to_string(i);
      case RegisterFile::out_fog: return "oFog";
      case RegisterFile::out_point_size: return "oPts";
    }
    return "?";
  }

  // A source operand's value: register, swizzle, then _bias/_bx2/_x2, 1-, negation.
  std::string read(const AsmSource& s, uint32_t offset = 0) const {
    std::string v;
    if (s.relative)
      v = "fx_c[clamp(int(a0.x) + " + std::to_string(s.index + offset) + ", 0, " +
          std::to_string(kRelativeConstants - 1) + ")]";
    else v = register_name(s.file, s.index + offset);
    if (s.swizzle != std::array<uint8_t, 4>{0, 1, 2, 3}) {
      v += ".";
      for (uint8_t c : s.swizzle) v.push_back(kComponents[c]);
    }
    if (s.bias) v = "(" + v + " - 0.5)";
    if (s.bx2) v = "(2.0 * (" + v + " - 0.5))";
    if (s.x2) v = "(2.0 * " + v + ")";
    if (s.invert) v = "(1.0 - " + v + ")";
    if (s.negate) v = "(-" + v + ")";
    return v;
  }

  // The scalar a vertex shader's rcp/rsq/exp/log reads: the replicated component, .w if none.
  std::string scalar(const AsmSource& s) const {
    AsmSource c = s;
    const bool plain = s.swizzle == std::array<uint8_t, 4>{0, 1, 2, 3};
    c.swizzle = {plain ? uint8_t(3) : s.swizzle[0], 0, 0, 0};
    std::string v = "(";  // appended: GCC 12's -Wrestrict misreads "(" + std::string here
    v += read(c);
    v += ").x";
    return v;
  }

  // Texture coordinates of stage n (the interpolated TEXCOORDn), float4.
  static std::string texcoord(uint32_t n) { return "fx_tc" + std::to_string(n); }

  std::string bump_matrix(uint32_t stage, const std::string& src) const {
    const BumpEnvironment& e = b_.bump[stage];
    return "float2(" + hlsl_number(e.matrix[0]) + " * " + src + ".x + " + hlsl_number(e.matrix[2]) + " * " + src +
           ".y, " + hlsl_number(e.matrix[1]) + " * " + src + ".x + " + hlsl_number(e.matrix[3]) + " * " + src + ".y)";
  }

  // Emits `compute` (which defines float4 `name` when the instruction writes a register)
  // and `write` (which stores it). Returns false after reporting an error.
  bool instruction(const AsmInstruction& ins, const std::string& name, std::string& compute, std::string& write) {
    const std::string& op = ins.op;
    if (op == "def" || op == "dcl" || op == "phase" || op == "nop") return true;
    if (!pixel_ && ins.has_dest &&
        (ins.dest.file == RegisterFile::input || ins.dest.file == RegisterFile::constant ||
         ins.dest.file == RegisterFile::texture))
      return error(ins.dest.range, "a vertex shader writes r#, a0 and the o registers only");
    auto src = [&](size_t i) { return read(ins.sources[i]); };
    std::string value;
    uint8_t produced = 0xF;  // components the instruction computes
    const uint32_t n = ins.dest.index;
    if (op == "mov") value = src(0);
    else if (op == "add") value = src(0) + " + " + src(1);
    else if (op == "sub") value = src(0) + " - " + src(1);
    else if (op == "mul") value = src(0) + " * " + src(1);
    else if (op == "mad") value = src(0) + " * " + src(1) + " + " + src(2);
    else if (op == "dp3") value = "dot((" + src(0) + ").xyz, (" + src(1) + ").xyz).xxxx";
    else if (op == "dp4") value = "dot(" + src(0) + ", " + src(1) + ").xxxx";
    else if (op == "lrp") value = "lerp(" + src(2) + ", " + src(1) + ", " + src(0) + ")";
    else if (op == "cnd") value = "lerp(" + src(2) + ", " + src(1) + ", (float4)(" + src(0) + " > 0.5))";
    else if (op == "cmp") value = "lerp(" + src(2) + ", " + src(1) + ", (float4)(" + src(0) + " >= 0.0))";
    else if (op == "min") value = "min(" + src(0) + ", " + src(1) + ")";
    else if (op == "max") value = "max(" + src(0) + ", " + src(1) + ")";
    else if (op == "slt") value = "(float4)(" + src(0) + " < " + src(1) + ")";
    else if (op == "sge") value = "(float4)(" + src(0) + " >= " + src(1) + ")";
    else if (op == "frc") value = src(0) + " - floor(" + src(0) + ")";
    else if (op == "rcp") value = "(1.0 / " + scalar(ins.sources[0]) + ").xxxx";
    else if (op == "rsq") value = "rsqrt(abs(" + scalar(ins.sources[0]) + ")).xxxx";
    else if (op == "exp") value = "exp2(" + scalar(ins.sources[0]) + ").xxxx";
    else if (op == "log") value = "log2(abs(" + scalar(ins.sources[0]) + ")).xxxx";
    else if (op == "expp") {
      const std::string f = scalar(ins.sources[0]);
      value = "float4(exp2(floor(" + f + ")), " + f + " - floor(" + f + "), exp2(" + f + "), 1.0)";
    } else if (op == "logp") {
      const std::string f = "abs(" + scalar(ins.sources[0]) + ")";
      value = "float4(floor(log2(" + f + ")), " + f + " / exp2(floor(log2(" + f + "))), log2(" + f + "), 1.0)";
    } else if (op == "lit") {
      const std::string s = src(0);
      value = "float4(1.0, max(" + s + ".x, 0.0), (" + s + ".x > 0.0 && " + s + ".y > 0.0) ? pow(" + s + ".y, clamp(" +
              s + ".w, -128.0, 128.0)) : 0.0, 1.0)";
    } else if (op == "dst") {
      value = "float4(1.0, " + src(0) + ".y * " + src(1) + ".y, " + src(0) + ".z, " + src(1) + ".w)";
    } else if (op[0] == 'm' && op.size() == 4 && op[2] == 'x') {  // m4x4 m4x3 m3x4 m3x3 m3x2
      const int width = op[1] - '0', rows = op[3] - '0';
      std::string parts;
      for (int r = 0; r < 4; ++r) {
        if (r) parts += ", ";
        if (r >= rows) {
          parts += "0.0";
          continue;
        }
        const std::string a = src(0), b = read(ins.sources[1], uint32_t(r));
        parts += width == 4 ? "dot(" + a + ", " + b + ")" : "dot((" + a + ").xyz, (" + b + ").xyz)";
      }
      value = "float4(" + parts + ")";
      produced = uint8_t((1u << rows) - 1);
      if (ins.sources[1].file != RegisterFile::constant && ins.sources[1].file != RegisterFile::temp)
        return error(ins.sources[1].range, "'" + op + "' reads its matrix from consecutive registers");
    } else if (op == "bem") {
      value = "float4((" + src(0) + ").xy + " + bump_matrix(n, "(" + src(1) + ")") + ", 0.0, 0.0)";
      produced = 0x3;
    } else if (!texture_instruction(ins, name, compute, write)) {
      return false;
    } else {
      return true;
    }
    if (!ins.has_dest) return true;
    if (ins.scale > 0) value = "(" + value + ") * " + hlsl_number(double(1 << ins.scale));
    if (ins.scale < 0) value = "(" + value + ") / " + hlsl_number(double(1 << -ins.scale));
    if (ins.saturate) value = "saturate(" + value + ")";
    compute += "    float4 " + name + " = " + quantize(value) + ";\n";
    store(ins.dest, name, produced, write);
    return true;
  }

  void store(const AsmDest& d, const std::string& name, uint8_t produced, std::string& write) {
    const uint8_t mask = d.mask & produced;
    if (!mask) return;
    std::string target = register_name(d.file, d.index);
    std::string value = name;
    if (d.file == RegisterFile::address) value = "floor(" + name + ")";  // vs.1.1 rounds a0 down
    if (mask == 0xF) write += "    " + target + " = " + value + ";\n";
    else write += "    " + target + "." + mask_suffix(mask) + " = " + value + "." + mask_suffix(mask) + ";\n";
  }

  // ps.1.x texture instructions: sample, coordinate and kill. Fills compute/write.
  bool texture_instruction(const AsmInstruction& ins, const std::string& name, std::string& compute,
                           std::string& write) {
    const std::string& op = ins.op;
    const uint32_t n = ins.dest.index;
    std::string value;
    auto src = [&](size_t i) { return read(ins.sources[i]); };
    if (n >= 8) return error(ins.dest.range, "texture stages are numbered 0 to 7");
    if (op == "texld" || op == "texcrd") {
      const AsmSource& s = ins.sources[0];
      std::string c = read(s);
      if (s.divide == 3) c = "float4((" + c + ").xy / (" + c + ").z, 0.0, 1.0)";
      if (s.divide == 4) c = "float4((" + c + ").xy / (" + c + ").w, 0.0, 1.0)";
      value = op == "texld" ? sample(n, c) : "float4((" + c + ").xyz, 1.0)";
    } else if (op == "texkill") {
      std::string reg = ins.dest.file == RegisterFile::texture ? texcoord(n) : register_name(ins.dest.file, n);
      compute += "    clip((" + reg + ").xyz);\n";
      return true;
    } else if (op == "tex") {
      value = sample(n, texcoord(n));
    } else if (op == "texcoord") {
      value = "float4(saturate(" + texcoord(n) + ".xyz), 1.0)";
    } else if (op == "texbem" || op == "texbeml") {
      value = sample(n, "float4(" + texcoord(n) + ".xy + " + bump_matrix(n, "(" + src(0) + ")") + ", 0.0, 1.0)");
      if (op == "texbeml")
        value = "(" + value + ") * ((" + src(0) + ").z * " + hlsl_number(b_.bump[n].scale) + " + " +
                hlsl_number(b_.bump[n].offset) + ")";
    } else if (op == "texreg2ar") {
      value = sample(n, "float4((" + src(0) + ").wx, 0.0, 1.0)");
    } else if (op == "texreg2gb") {
      value = sample(n, "float4((" + src(0) + ").yz, 0.0, 1.0)");
    } else if (op == "texreg2rgb") {
      value = sample(n, "float4((" + src(0) + ").xyz, 1.0)");
    } else if (op == "texm3x2pad" || op == "texm3x3pad") {
      compute += "    fx_m." + std::string(1, kComponents[pad_row_]) + " = dot(" + texcoord(n) + ".xyz, (" + src(0) +
                 ").xyz);\n";
      ++pad_row_;
      return true;
    } else if (op == "texm3x2tex" || op == "texm3x2depth" || op == "texm3x3tex" || op == "texm3x3" ||
               op == "texm3x3spec" || op == "texm3x3vspec") {
      const bool three = op.rfind("texm3x3", 0) == 0;
      if (pad_row_ != (three ? 2u : 1u))
        return error(ins.range,
                     "'" + op + "' must follow " + (three ? "two texm3x3pad" : "one texm3x2pad") + " instructions");
      compute += "    fx_m." + std::string(1, kComponents[pad_row_]) + " = dot(" + texcoord(n) + ".xyz, (" + src(0) +
                 ").xyz);\n";
      pad_row_ = 0;
      if (op == "texm3x2depth") {
        // z / w from the two rows (1 when w is 0), the pixel's depth; t(m+1) holds it too.
        compute += "    fx_depth = " + depth("fx_m.x", "fx_m.y") + ";\n";
        value = "fx_depth.xxxx";
      } else if (op == "texm3x2tex") value = sample(n, "float4(fx_m.xy, 0.0, 1.0)");
      else if (op == "texm3x3") value = "float4(fx_m.xyz, 1.0)";
      else if (op == "texm3x3tex") value = sample(n, "float4(fx_m.xyz, 1.0)");
      else {
        const std::string eye =
            op == "texm3x3spec" ? "(" + read(ins.sources[1]) + ").xyz"
                                : "float3(" + texcoord(n - 2) + ".w, " + texcoord(n - 1) + ".w, " + texcoord(n) + ".w)";
        compute += "    float3 fx_e = " + eye + ";\n";
        value = sample(n, "float4(2.0 * fx_m.xyz * dot(fx_m.xyz, fx_e) / dot(fx_m.xyz, fx_m.xyz) - fx_e, 1.0)");
      }
    } else if (op == "texdp3tex") {
      value = sample(n, "float4(dot(" + texcoord(n) + ".xyz, (" + src(0) + ").xyz), 0.0, 0.0, 1.0)");
    } else if (op == "texdp3") {
      value = "dot(" + texcoord(n) + ".xyz, (" + src(0) + ").xyz).xxxx";
    } else if (op == "texdepth") {
      // r5.r / r5.g (1 when r5.g is 0) is the pixel's depth; r5 is left as it is.
      if (ins.dest.file != RegisterFile::temp || n != 5) return error(ins.dest.range, "'texdepth' writes r5 only");
      compute += "    fx_depth = " + depth("r5.x", "r5.y") + ";\n";
      return true;
    } else {
      return error(ins.range, "'" + op + "' is not translated");
    }
    if (ins.scale > 0) value = "(" + value + ") * " + hlsl_number(double(1 << ins.scale));
    if (ins.scale < 0) value = "(" + value + ") / " + hlsl_number(double(1 << -ins.scale));
    if (ins.saturate) value = "saturate(" + value + ")";
    compute += "    float4 " + name + " = " + quantize(value) + ";\n";
    store(ins.dest, name, 0xF, write);
    return true;
  }

  // The depth D3D computes as z / w (1 when w is 0), clamped to the depth range [0, 1].
  std::string depth(const std::string& z, const std::string& w) {
    depth_ = true;
    return "saturate(" + w + " == 0.0 ? 1.0 : " + z + " / " + w + ")";
  }

  // The constant registers as locals (and as an array for c[a0.x + n]).
  std::string constant_locals() const {
    std::string out;
    auto value_of = [&](uint32_t reg) -> std::string {
      if (auto d = defined_.find(reg); d != defined_.end())
        return "float4(" + hlsl_number(d->second[0]) + ", " + hlsl_number(d->second[1]) + ", " +
               hlsl_number(d->second[2]) + ", " + hlsl_number(d->second[3]) + ")";
      if (auto c = b_.constants.find(reg); c != b_.constants.end()) return c->second;
      return "float4(0.0, 0.0, 0.0, 0.0)";
    };
    for (uint32_t reg : constants_) {
      std::string v = value_of(reg);
      if (pixel_ && o_.hardware_precision) v = "fx_precision(" + v + ")";
      out += "  float4 c" + std::to_string(reg) + " = " + v + ";\n";
    }
    if (relative_) {
      out += "  float4 fx_c[" + std::to_string(kRelativeConstants) + "];\n";
      out += "  for (int fx_i = 0; fx_i < " + std::to_string(kRelativeConstants) +
             "; ++fx_i) fx_c[fx_i] = float4(0.0, 0.0, 0.0, 0.0);\n";
      std::set<uint32_t> all;
      for (const auto& [reg, e] : b_.constants) all.insert(reg);
      for (const auto& [reg, e] : defined_) all.insert(reg);
      for (uint32_t reg : all)
        if (reg < kRelativeConstants) out += "  fx_c[" + std::to_string(reg) + "] = " + value_of(reg) + ";\n";
    }
    return out;
  }

  std::string temp_locals() const {
    std::string out;
    for (uint32_t i = 0; i < temps_; ++i) out += "  float4 r" + std::to_string(i) + " = float4(0.0, 0.0, 0.0, 0.0);\n";
    return out;
  }

  std::string vertex_shell(const std::string& body) const {
    std::string s = "struct fx_vs_in {\n";
    for (const AsmInput& in : p_.inputs) s += "  float4 v" + std::to_string(in.reg) + " : " + in.semantic + ";\n";
    if (p_.inputs.empty()) s += "  float4 v0 : POSITION;\n";
    s += "};\nstruct fx_vs_out {\n  float4 oPos : POSITION;\n  float4 oD0 : COLOR0;\n  float4 oD1 : COLOR1;\n";
    for (int t = 0; t < 8; ++t) s += "  float4 oT" + std::to_string(t) + " : TEXCOORD" + std::to_string(t) + ";\n";
    if (fog_) s += "  float oFog : FOG;\n";
    if (point_size_) s += "  float oPts : PSIZE;\n";
    s += "};\nfx_vs_out fx_main(fx_vs_in fx_in) {\n";
    for (const AsmInput& in : p_.inputs)
      s += "  float4 v" + std::to_string(in.reg) + " = fx_in.v" + std::to_string(in.reg) + ";\n";
    s += constant_locals() + temp_locals();
    s += "  float4 a0 = float4(0.0, 0.0, 0.0, 0.0);\n";
    s += "  float4 oPos = float4(0.0, 0.0, 0.0, 1.0), oD0 = float4(0.0, 0.0, 0.0, 0.0), oD1 = oD0, oFog = oD0, oPts = "
         "oD0;\n";
    for (int t = 0; t < 8; ++t) s += "  float4 oT" + std::to_string(t) + " = float4(0.0, 0.0, 0.0, 0.0);\n";
    s += body;
    // Colour outputs are clamped to [0,1] on their way to the rasterizer, as in D3D.
    s += "  fx_vs_out fx_out;\n  fx_out.oPos = oPos;\n  fx_out.oD0 = saturate(oD0);\n  fx_out.oD1 = saturate(oD1);\n";
    for (int t = 0; t < 8; ++t) s += "  fx_out.oT" + std::to_string(t) + " = oT" + std::to_string(t) + ";\n";
    if (fog_) s += "  fx_out.oFog = oFog.x;\n";
    if (point_size_) s += "  fx_out.oPts = oPts.x;\n";
    s += "  return fx_out;\n}\n";
    return s;
  }

  std::string pixel_shell(const std::string& body) const {
    std::string s;
    if (o_.hardware_precision) {
      const char* range = p_.version.minor == 4 ? "8.0" : "1.0";
      s += std::string("float4 fx_precision(float4 x) { return clamp(floor(x * 255.0 + 0.5) / 255.0, -") + range +
           ", " + range + "); }\n";
    }
    // Texture coordinates: every stage a texture instruction names (t# in ps.1.0-1.3, the
    // t# sources of texld/texcrd in ps.1.4), plus vspec's neighbours.
    std::set<uint32_t> coords;
    for (const AsmInstruction& ins : p_.instructions) {
      if (p_.version.minor < 4 && ins.has_dest && ins.dest.file == RegisterFile::texture &&
          ins.op.rfind("tex", 0) == 0 && ins.op.rfind("texreg2", 0) != 0) {
        coords.insert(ins.dest.index);
        if (ins.op == "texm3x3vspec" && ins.dest.index >= 2) coords.insert({ins.dest.index - 1, ins.dest.index - 2});
      }
      for (const AsmSource& src : ins.sources)
        if (p_.version.minor == 4 && src.file == RegisterFile::texture) coords.insert(src.index);
      if (p_.version.minor == 4 && ins.op == "texkill" && ins.dest.file == RegisterFile::texture)
        coords.insert(ins.dest.index);
    }
    // Only the inputs the shader reads: glslang drops the semantic of an unread one, and
    // the stages are linked by semantic only when every input has one.
    const bool inputs = !colors_.empty() || !coords.empty();
    if (inputs) {
      s += "struct fx_ps_in {\n";
      for (uint32_t c : colors_) s += "  float4 v" + std::to_string(c) + " : COLOR" + std::to_string(c) + ";\n";
      for (uint32_t t : coords) s += "  float4 fx_tc" + std::to_string(t) + " : TEXCOORD" + std::to_string(t) + ";\n";
      s += "};\n";
    }
    // texdepth and texm3x2depth replace the pixel's depth: SV_Depth beside the colour.
    if (depth_) s += "struct fx_ps_out {\n  float4 color : COLOR0;\n  float depth : SV_Depth;\n};\n";
    s += std::string(depth_ ? "fx_ps_out" : "float4") + " fx_main(" + (inputs ? "fx_ps_in fx_in" : "") + ")" +
         (depth_ ? "" : " : COLOR0") + " {\n";
    for (uint32_t c : colors_)
      s += "  float4 v" + std::to_string(c) + " = " + quantize("fx_in.v" + std::to_string(c)) + ";\n";
    for (uint32_t t : coords) s += "  float4 fx_tc" + std::to_string(t) + " = fx_in.fx_tc" + std::to_string(t) + ";\n";
    s += constant_locals() + temp_locals();
    if (p_.version.minor < 4)
      for (uint32_t t = 0; t < textures_; ++t)
        s += "  float4 t" + std::to_string(t) + " = float4(0.0, 0.0, 0.0, 0.0);\n";
    s += "  float3 fx_m = float3(0.0, 0.0, 0.0);\n";
    if (depth_) s += "  float fx_depth = 0.0;\n";
    s += body;
    if (depth_) s += "  fx_ps_out fx_out;\n  fx_out.color = r0;\n  fx_out.depth = fx_depth;\n  return fx_out;\n}\n";
    else s += "  return r0;\n}\n";
    return s;
  }

  static constexpr uint32_t kRelativeConstants = 96;  // vs.1.1's constant registers
  const AsmProgram& p_;
  const AssemblyBindings& b_;
  const AssemblyOptions& o_;
  DiagnosticSink& sink_;
  const bool pixel_;
  bool failed_ = false, relative_ = false, fog_ = false, point_size_ = false, depth_ = false;
  uint32_t temps_ = 0, textures_ = 0;
  std::set<uint32_t> colors_;  // pixel shaders: the colour inputs v# read
  uint32_t pad_row_ = 0;       // texm3x2pad/texm3x3pad rows seen so far
  std::set<uint32_t> constants_, stages_;
  std::map<uint32_t, std::array<double, 4>> defined_;
};

}  // namespace

std::optional<AssemblyTranslation> translate_assembly(const AsmProgram& program, const AssemblyBindings& bindings,
                                                      const AssemblyOptions& options, DiagnosticSink& sink) {
  return Translator(program, bindings, options, sink).run();
}

}  // namespace fx::emulation
