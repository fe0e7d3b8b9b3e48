// The CPU interpreter of shader model 1 assembly (see asm_interpreter.h).
#include "asm_interpreter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fx::emulation::testing {
namespace {

Vec4 splat(double x) { return {x, x, x, x}; }

double dot3(const Vec4& a, const Vec4& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double dot4(const Vec4& a, const Vec4& b) { return dot3(a, b) + a[3] * b[3]; }

template <class F>
Vec4 each(const Vec4& a, F f) {
  return {f(a[0], 0), f(a[1], 1), f(a[2], 2), f(a[3], 3)};
}

struct Interpreter {
  AsmMachine& m;
  const AsmProgram& p;
  std::array<Vec4, 12> r{};
  std::array<Vec4, 8> t{};  // ps.1.0-1.3 texture registers
  std::array<Vec4, 8> out_t{};
  Vec4 a0{}, pos{0, 0, 0, 1}, fog{}, psize{};
  std::array<Vec4, 2> od{};
  Vec4 matrix_rows{};  // texm3x2pad/texm3x3pad dot products
  uint32_t pad = 0;

  static double depth(double z, double w) { return w == 0 ? 1.0 : std::clamp(z / w, 0.0, 1.0); }

  bool pixel() const { return p.version.pixel; }
  bool ps14() const { return pixel() && p.version.minor == 4; }

  double quantize(double x) const {
    if (!pixel() || !m.hardware_precision) return x;
    const double range = ps14() ? 8.0 : 1.0;
    return std::clamp(std::floor(x * 255.0 + 0.5) / 255.0, -range, range);
  }
  Vec4 quantize(const Vec4& x) const {
    return each(x, [&](double c, int) { return quantize(c); });
  }

  Vec4 reg(RegisterFile f, uint32_t i) const {
    switch (f) {
      case RegisterFile::temp: return r[i];
      case RegisterFile::input: return pixel() ? quantize(m.v[i]) : m.v[i];
      case RegisterFile::constant: return pixel() && m.hardware_precision ? quantize(m.c[i]) : m.c[i];
      case RegisterFile::texture: return ps14() ? m.texcoord[i] : t[i];
      case RegisterFile::address: return a0;
      default: return {};
    }
  }

  Vec4 read(const AsmSource& s, uint32_t offset = 0) const {
    uint32_t index = s.index + offset;
    if (s.relative) index = uint32_t(std::clamp<long>(long(a0[0]) + long(index), 0, 95));
    Vec4 raw = reg(s.file, index), v;
    for (int k = 0; k < 4; ++k) v[k] = raw[s.swizzle[k]];
    return each(v, [&](double x, int) {
      if (s.bias) x -= 0.5;
      if (s.bx2) x = 2.0 * (x - 0.5);
      if (s.x2) x = 2.0 * x;
      if (s.invert) x = 1.0 - x;
      if (s.negate) x = -x;
      return x;
    });
  }

  double scalar(const AsmSource& s) const {
    AsmSource c = s;
    const bool plain = s.swizzle == std::array<uint8_t, 4>{0, 1, 2, 3};
    c.swizzle = {plain ? uint8_t(3) : s.swizzle[0], 0, 0, 0};
    return read(c)[0];
  }

  Vec4* target(const AsmDest& d) {
    switch (d.file) {
      case RegisterFile::temp: return &r[d.index];
      case RegisterFile::texture: return &t[d.index];
      case RegisterFile::address: return &a0;
      case RegisterFile::out_position: return &pos;
      case RegisterFile::out_color: return &od[d.index];
      case RegisterFile::out_texcoord: return &out_t[d.index];
      case RegisterFile::out_fog: return &fog;
      case RegisterFile::out_point_size: return &psize;
      default: return nullptr;
    }
  }

  Vec4 finish(const AsmInstruction& ins, Vec4 v) const {
    return quantize(each(v, [&](double x, int) {
      x = std::ldexp(x, ins.scale);
      if (ins.saturate) x = std::clamp(x, 0.0, 1.0);
      return x;
    }));
  }

  void store(const AsmDest& d, const Vec4& v, uint8_t produced = 0xF) {
    Vec4* out = target(d);
    if (!out) return;
    for (int k = 0; k < 4; ++k)
      if (d.mask & produced & (1 << k)) (*out)[k] = d.file == RegisterFile::address ? std::floor(v[k]) : v[k];
  }

  Vec4 bump_offset(uint32_t stage, const Vec4& s) const {
    const BumpEnvironment& e = m.bump[stage];
    return {e.matrix[0] * s[0] + e.matrix[2] * s[1], e.matrix[1] * s[0] + e.matrix[3] * s[1], 0, 0};
  }

  // The value an arithmetic or texture instruction computes; `produced` its components.
  Vec4 compute(const AsmInstruction& ins, uint8_t& produced) {
    const std::string& op = ins.op;
    auto s = [&](size_t i) { return read(ins.sources[i]); };
    const uint32_t n = ins.dest.index;
    produced = 0xF;
    if (op == "mov") return s(0);
    if (op == "add") {
      Vec4 a = s(0), b = s(1);
      return each(a, [&](double x, int k) { return x + b[k]; });
    }
    if (op == "sub") {
      Vec4 a = s(0), b = s(1);
      return each(a, [&](double x, int k) { return x - b[k]; });
    }
    if (op == "mul") {
      Vec4 a = s(0), b = s(1);
      return each(a, [&](double x, int k) { return x * b[k]; });
    }
    if (op == "mad") {
      Vec4 a = s(0), b = s(1), c = s(2);
      return each(a, [&](double x, int k) { return x * b[k] + c[k]; });
    }
    if (op == "dp3") return splat(dot3(s(0), s(1)));
    if (op == "dp4") return splat(dot4(s(0), s(1)));
    if (op == "lrp") {
      Vec4 a = s(0), b = s(1), c = s(2);
      return each(a, [&](double x, int k) { return x * b[k] + (1.0 - x) * c[k]; });
    }
    if (op == "cnd") {
      Vec4 a = s(0), b = s(1), c = s(2);
      return each(a, [&](double x, int k) { return x > 0.5 ? b[k] : c[k]; });
    }
    if (op == "cmp") {
      Vec4 a = s(0), b = s(1), c = s(2);
      return each(a, [&](double x, int k) { return x >= 0.0 ? b[k] : c[k]; });
    }
    if (op == "min") {
      Vec4 a = s(0), b = s(1);
      return each(a, [&](double x, int k) { return std::min(x, b[k]); });
    }
    if (op == "max") {
      Vec4 a = s(0), b = s(1);
      return each(a, [&](double x, int k) { return std::max(x, b[k]); });
    }
    if (op == "slt") {
      Vec4 a = s(0), b = s(1);
      return each(a, [&](double x, int k) { return x < b[k] ? 1.0 : 0.0; });
    }
    if (op == "sge") {
      Vec4 a = s(0), b = s(1);
      return each(a, [&](double x, int k) { return x >= b[k] ? 1.0 : 0.0; });
    }
    if (op == "frc") return each(s(0), [](double x, int) { return x - std::floor(x); });
    if (op == "rcp") return splat(1.0 / scalar(ins.sources[0]));
    if (op == "rsq") return splat(1.0 / std::sqrt(std::abs(scalar(ins.sources[0]))));
    if (op == "exp") return splat(std::exp2(scalar(ins.sources[0])));
    if (op == "log") return splat(std::log2(std::abs(scalar(ins.sources[0]))));
    if (op == "expp") {
      double f = scalar(ins.sources[0]);
      return {std::exp2(std::floor(f)), f - std::floor(f), std::exp2(f), 1.0};
    }
    if (op == "logp") {
      double f = std::abs(scalar(ins.sources[0])), e = std::floor(std::log2(f));
      return {e, f / std::exp2(e), std::log2(f), 1.0};
    }
    if (op == "lit") {
      Vec4 a = s(0);
      double spec = a[0] > 0 && a[1] > 0 ? std::pow(a[1], std::clamp(a[3], -128.0, 128.0)) : 0.0;
      return {1.0, std::max(a[0], 0.0), spec, 1.0};
    }
    if (op == "dst") {
      Vec4 a = s(0), b = s(1);
      return {1.0, a[1] * b[1], a[2], b[3]};
    }
    if (op.size() == 4 && op[0] == 'm' && op[2] == 'x') {
      const int width = op[1] - '0', rows = op[3] - '0';
      Vec4 a = s(0), out{};
      for (int k = 0; k < rows; ++k) {
        Vec4 b = read(ins.sources[1], uint32_t(k));
        out[k] = width == 4 ? dot4(a, b) : dot3(a, b);
      }
      produced = uint8_t((1u << rows) - 1);
      return out;
    }
    if (op == "bem") {
      Vec4 a = s(0), o = bump_offset(n, s(1));
      produced = 0x3;
      return {a[0] + o[0], a[1] + o[1], 0, 0};
    }
    // Texture instructions.
    const Vec4 tc = m.texcoord[std::min<uint32_t>(n, 7)];
    if (op == "texld" || op == "texcrd") {
      Vec4 c = s(0);
      if (ins.sources[0].divide == 3) c = {c[0] / c[2], c[1] / c[2], 0, 1};
      if (ins.sources[0].divide == 4) c = {c[0] / c[3], c[1] / c[3], 0, 1};
      return op == "texld" ? m.sample(n, c) : Vec4{c[0], c[1], c[2], 1.0};
    }
    if (op == "tex") return m.sample(n, tc);
    if (op == "texcoord")
      return {std::clamp(tc[0], 0.0, 1.0), std::clamp(tc[1], 0.0, 1.0), std::clamp(tc[2], 0.0, 1.0), 1.0};
    if (op == "texbem" || op == "texbeml") {
      Vec4 src = s(0), o = bump_offset(n, src);
      Vec4 v = m.sample(n, {tc[0] + o[0], tc[1] + o[1], 0, 1});
      if (op == "texbeml") {
        double l = src[2] * m.bump[n].scale + m.bump[n].offset;
        v = each(v, [&](double x, int) { return x * l; });
      }
      return v;
    }
    if (op == "texreg2ar") {
      Vec4 a = s(0);
      return m.sample(n, {a[3], a[0], 0, 1});
    }
    if (op == "texreg2gb") {
      Vec4 a = s(0);
      return m.sample(n, {a[1], a[2], 0, 1});
    }
    if (op == "texreg2rgb") {
      Vec4 a = s(0);
      return m.sample(n, {a[0], a[1], a[2], 1});
    }
    if (op == "texdp3") return splat(dot3(tc, s(0)));
    if (op == "texdp3tex") return m.sample(n, {dot3(tc, s(0)), 0, 0, 1});
    if (op == "texdepth") {  // r5.r / r5.g; r5 unchanged
      m.depth = depth(r[5][0], r[5][1]);
      produced = 0;
      return r[5];
    }
    matrix_rows[pad++] = dot3(tc, s(0));
    Vec4 N = matrix_rows;
    if (op == "texm3x2depth") return pad = 0, m.depth = depth(N[0], N[1]), splat(*m.depth);
    if (op == "texm3x2tex") return pad = 0, m.sample(n, {N[0], N[1], 0, 1});
    if (op == "texm3x3") return pad = 0, Vec4{N[0], N[1], N[2], 1.0};
    if (op == "texm3x3tex") return pad = 0, m.sample(n, {N[0], N[1], N[2], 1});
    pad = 0;
    Vec4 e = op == "texm3x3spec" ? read(ins.sources[1])
                                 : Vec4{m.texcoord[n - 2][3], m.texcoord[n - 1][3], m.texcoord[n][3], 0};
    const double ne = dot3(N, e), nn = dot3(N, N);
    return m.sample(n, {2 * N[0] * ne / nn - e[0], 2 * N[1] * ne / nn - e[1], 2 * N[2] * ne / nn - e[2], 1});
  }

  void run() {
    for (const AsmInstruction& ins : p.instructions)
      if (ins.op == "def") m.c[ins.dest.index] = ins.literal;
    const auto& list = p.instructions;
    for (size_t i = 0; i < list.size(); ++i) {
      const AsmInstruction& ins = list[i];
      if (ins.op == "def" || ins.op == "dcl" || ins.op == "phase" || ins.op == "nop") continue;
      if (ins.op == "texkill") {
        Vec4 c = ins.dest.file == RegisterFile::texture ? m.texcoord[ins.dest.index] : r[ins.dest.index];
        m.killed = m.killed || c[0] < 0 || c[1] < 0 || c[2] < 0;
        continue;
      }
      if (ins.op == "texm3x2pad" || ins.op == "texm3x3pad") {
        matrix_rows[pad++] = dot3(m.texcoord[ins.dest.index], read(ins.sources[0]));
        continue;
      }
      uint8_t produced = 0xF;
      Vec4 a = finish(ins, compute(ins, produced));
      if (i + 1 < list.size() && list[i + 1].coissue) {  // both read before either writes
        uint8_t produced_b = 0xF;
        Vec4 b = finish(list[i + 1], compute(list[i + 1], produced_b));
        store(ins.dest, a, produced);
        store(list[i + 1].dest, b, produced_b);
        ++i;
        continue;
      }
      store(ins.dest, a, produced);
    }
    m.r0 = r[0];
    m.pos = pos;
    for (int k = 0; k < 2; ++k) m.color[k] = each(od[k], [](double x, int) { return std::clamp(x, 0.0, 1.0); });
    m.out_texcoord = out_t;
  }
};

}  // namespace

void AsmMachine::run(const AsmProgram& program) {
  Interpreter in{*this, program};
  in.run();
}

}  // namespace fx::emulation::testing
