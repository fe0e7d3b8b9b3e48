// Parsing of shader model 1 assembly from an effect's tokens (see assembly_program.h): one
// instruction per line (or per `;`), opcode modifiers split off the opcode, operands with
// their register, modifiers, swizzle and mask, each located at its token.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <span>

#include "assembly_ops.h"
#include "fx/ascii_case.h"
#include "fx/emulation/assembly_program.h"

namespace fx::emulation {
namespace {

using Tokens = std::span<const Token>;

SourceRange span_range(Tokens t) {
  if (t.empty()) return {};
  return {t.front().loc, t.back().range().end};
}

// "v0_bx2" -> {"v0", {"bx2"}}.
std::vector<std::string> split_underscores(std::string_view word) {
  std::vector<std::string> parts;
  size_t from = 0;
  while (true) {
    size_t at = word.find('_', from);
    parts.emplace_back(word.substr(from, at == std::string_view::npos ? std::string_view::npos : at - from));
    if (at == std::string_view::npos) break;
    from = at + 1;
  }
  return parts;
}

class LineParser {
 public:
  LineParser(Tokens line, const AsmVersion& version, DiagnosticSink& sink)
      : line_(line), version_(version), sink_(sink) {}

  bool error(SourceRange r, std::string message) {
    sink_.error("asm-syntax", r, std::move(message));
    return false;
  }

  // "r0", "oPos", "c" (for c[...]) -> file and index.
  bool register_name(std::string_view name, SourceRange r, RegisterFile& file, uint32_t& index, bool& bare_c) {
    bare_c = false;
    std::string lower = ascii_lower(name);
    auto number = [&](size_t at) {
      uint32_t n = 0;
      auto [end, ec] = std::from_chars(lower.data() + at, lower.data() + lower.size(), n);
      if (ec != std::errc() || end != lower.data() + lower.size()) return false;
      index = n;
      return true;
    };
    if (lower == "opos") return file = RegisterFile::out_position, index = 0, true;
    if (lower == "ofog") return file = RegisterFile::out_fog, index = 0, true;
    if (lower == "opts") return file = RegisterFile::out_point_size, index = 0, true;
    if (lower == "c") return file = RegisterFile::constant, index = 0, bare_c = true, true;
    if (lower.starts_with("od") && number(2)) return file = RegisterFile::out_color, true;
    if (lower.starts_with("ot") && number(2)) return file = RegisterFile::out_texcoord, true;
    if (!lower.empty() && number(1)) {
      switch (lower[0]) {
        case 'r': file = RegisterFile::temp; return true;
        case 'v': file = RegisterFile::input; return true;
        case 'c': file = RegisterFile::constant; return true;
        case 't': file = RegisterFile::texture; return true;
        case 'a': file = RegisterFile::address; return true;
        default: break;
      }
    }
    return error(r, std::string(1, '\'').append(name) + "' is not a " + version_.spelled() + " register");
  }

  // ".xyz", ".rgba", ".a" -> components; false on other letters.
  static bool components(std::string_view s, std::vector<uint8_t>& out) {
    for (char c : s) {
      switch (std::tolower(static_cast<unsigned char>(c))) {
        case 'x':
        case 'r': out.push_back(0); break;
        case 'y':
        case 'g': out.push_back(1); break;
        case 'z':
        case 'b': out.push_back(2); break;
        case 'w':
        case 'a': out.push_back(3); break;
        default: return false;
      }
    }
    return !out.empty() && out.size() <= 4;
  }

  bool modifier(std::string_view m, AsmSource& s, SourceRange r) {
    std::string l = ascii_lower(m);
    if (l == "bias") s.bias = true;
    else if (l == "bx2") s.bx2 = true;
    else if (l == "x2") s.x2 = true;
    else if (l == "dz" || l == "db") s.divide = 3;
    else if (l == "dw" || l == "da") s.divide = 4;
    else return error(r, "unknown source modifier '_" + std::string(m) + "'");
    return true;
  }

  // One source operand from its tokens.
  bool source(Tokens t, AsmSource& s) {
    s.range = span_range(t);
    size_t i = 0;
    if (i < t.size() && t[i].is(TokenKind::minus)) s.negate = true, ++i;
    if (i + 1 < t.size() && t[i].is(TokenKind::integer) && t[i].text() == "1" && t[i + 1].is(TokenKind::minus))
      s.invert = true, i += 2;
    if (i < t.size() && t[i].is(TokenKind::minus)) s.negate = !s.negate, ++i;
    if (i >= t.size() || !t[i].is(TokenKind::identifier)) return error(s.range, "expected a source register");
    std::vector<std::string> parts = split_underscores(t[i].text());
    bool bare_c = false;
    if (!register_name(parts[0], t[i].range(), s.file, s.index, bare_c)) return false;
    for (size_t m = 1; m < parts.size(); ++m)
      if (!modifier(parts[m], s, t[i].range())) return false;
    ++i;
    if (i < t.size() && t[i].is(TokenKind::l_square)) {  // c[a0.x + n]
      if (s.file != RegisterFile::constant) return error(t[i].range(), "only constant registers are indexed");
      size_t close = i;
      while (close < t.size() && !t[close].is(TokenKind::r_square)) ++close;
      if (close == t.size()) return error(t[i].range(), "expected ']'");
      s.index = 0;
      for (size_t k = i + 1; k < close; ++k) {
        if (t[k].is(TokenKind::integer))
          s.index += uint32_t(std::strtoul(std::string(t[k].text()).c_str(), nullptr, 0));
        else if (t[k].is(TokenKind::identifier) && iequals(t[k].text(), "a0")) s.relative = true;
        else if (!t[k].is(TokenKind::plus) && !t[k].is(TokenKind::period) && !t[k].is_identifier("x"))
          return error(t[k].range(), "expected a0.x + n inside c[...]");
      }
      i = close + 1;
    } else if (bare_c) {
      return error(t[i - 1].range(), "expected c<n> or c[a0.x + n]");
    }
    if (i < t.size() && t[i].is(TokenKind::period)) {
      if (i + 1 >= t.size() || !t[i + 1].is(TokenKind::identifier)) return error(t[i].range(), "expected a swizzle");
      std::vector<std::string> sw = split_underscores(t[i + 1].text());
      std::vector<uint8_t> c;
      if (!components(sw[0], c)) return error(t[i + 1].range(), "'" + sw[0] + "' is not a swizzle");
      for (size_t k = 0; k < 4; ++k) s.swizzle[k] = c[std::min(k, c.size() - 1)];
      for (size_t m = 1; m < sw.size(); ++m)
        if (!modifier(sw[m], s, t[i + 1].range())) return false;
      i += 2;
    }
    if (i != t.size()) return error(t[i].range(), "unexpected '" + std::string(t[i].text()) + "' in a source operand");
    return true;
  }

  bool dest(Tokens t, AsmDest& d) {
    d.range = span_range(t);
    if (t.empty() || !t[0].is(TokenKind::identifier)) return error(d.range, "expected a destination register");
    bool bare_c = false;
    if (!register_name(t[0].text(), t[0].range(), d.file, d.index, bare_c)) return false;
    if (bare_c) return error(t[0].range(), "a constant register is not a destination");
    if (t.size() == 1) return true;
    std::vector<uint8_t> c;
    if (t.size() != 3 || !t[1].is(TokenKind::period) || !t[2].is(TokenKind::identifier) || !components(t[2].text(), c))
      return error(d.range, "expected a write mask such as .xyz or .rgb");
    d.mask = 0;
    for (uint8_t k : c) d.mask |= uint8_t(1u << k);
    return true;
  }

  // A signed number for def.
  bool number(Tokens t, double& v) {
    size_t i = 0;
    bool negative = false;
    if (i < t.size() && (t[i].is(TokenKind::minus) || t[i].is(TokenKind::plus)))
      negative = t[i].is(TokenKind::minus), ++i;
    if (i + 1 != t.size() || !(t[i].is(TokenKind::integer) || t[i].is(TokenKind::floating)))
      return error(span_range(t), "expected a number");
    std::string s(t[i].text());
    while (!s.empty() && (s.back() == 'f' || s.back() == 'F' || s.back() == 'h' || s.back() == 'H')) s.pop_back();
    v = std::strtod(s.c_str(), nullptr);
    if (negative) v = -v;
    return true;
  }

  bool parse(AsmInstruction& ins) {
    size_t i = 0;
    if (line_[i].is(TokenKind::plus)) ins.coissue = true, ++i;
    if (i >= line_.size() || !line_[i].is(TokenKind::identifier))
      return error(span_range(line_), "expected an instruction");
    const Token& op_token = line_[i++];
    ins.range = span_range(line_.subspan(ins.coissue ? 1 : 0));
    std::vector<std::string> parts = split_underscores(op_token.text());
    ins.op = ascii_lower(parts[0]);
    const OpInfo* info = find_op(ins.op);
    if (ins.op == "dcl" && parts.size() >= 2) {
      std::string usage = ascii_lower(parts[1]);
      size_t digits = usage.find_first_of("0123456789");
      if (digits != std::string::npos)
        ins.usage_index = uint32_t(std::atoi(usage.c_str() + digits)), usage.resize(digits);
      ins.usage = usage;
      parts.resize(1);
    }
    if (!info || !(version_.pixel ? info->pixel(version_) : info->vertex))
      return error(op_token.range(), "'" + ins.op + "' is not a " + version_.spelled() + " instruction");
    for (size_t m = 1; m < parts.size(); ++m) {
      std::string mod = ascii_lower(parts[m]);
      if (mod == "sat") ins.saturate = true;
      else if (mod == "x2") ins.scale = 1;
      else if (mod == "x4") ins.scale = 2;
      else if (mod == "x8") ins.scale = 3;
      else if (mod == "d2") ins.scale = -1;
      else if (mod == "d4") ins.scale = -2;
      else if (mod == "d8") ins.scale = -3;
      else return error(op_token.range(), "unknown instruction modifier '_" + parts[m] + "'");
    }
    if ((ins.saturate || ins.scale) && !version_.pixel)
      return error(op_token.range(), "vertex shader instructions take no modifiers");
    // Operands: comma-separated groups up to the end of the line.
    std::vector<Tokens> operands;
    size_t from = i;
    for (size_t k = i; k <= line_.size(); ++k)
      if (k == line_.size() || line_[k].is(TokenKind::comma)) {
        if (k > from || k < line_.size()) operands.push_back(line_.subspan(from, k - from));
        from = k + 1;
      }
    if (ins.op == "def") {
      if (operands.size() != 5) return error(ins.range, "def takes a register and four numbers");
      if (!dest(operands[0], ins.dest) || ins.dest.file != RegisterFile::constant)
        return error(ins.range, "def defines a constant register c#");
      ins.has_dest = true;
      for (size_t k = 0; k < 4; ++k)
        if (!number(operands[k + 1], ins.literal[k])) return false;
      return true;
    }
    const size_t want = info->sources + (info->dest ? 1 : 0);
    const size_t given = operands.size();
    bool optional_source = info->optional_last && given + 1 == want;
    if (given != want && !optional_source)
      return error(ins.range, "'" + ins.op + "' takes " + std::to_string(want) + " operand(s), " +
                                  std::to_string(given) + " given");
    size_t k = 0;
    if (info->dest) {
      if (operands[0].empty() || !dest(operands[0], ins.dest))
        return operands[0].empty() ? error(ins.range, "missing destination") : false;
      ins.has_dest = true;
      k = 1;
    }
    for (; k < given; ++k) {
      if (operands[k].empty()) return error(ins.range, "missing operand");
      AsmSource s;
      if (!source(operands[k], s)) return false;
      ins.sources.push_back(s);
    }
    return true;
  }

 private:
  Tokens line_;
  const AsmVersion& version_;
  DiagnosticSink& sink_;
};

bool is_opcode(const Token& t) {
  if (!t.is(TokenKind::identifier)) return false;
  std::string_view w = t.text();
  return find_op(ascii_lower(w.substr(0, w.find('_')))) != nullptr;
}

// Whether token i begins an instruction written on the same line as the one before it
// (`vs.1.1 dcl_position v0 m4x4 oPos, v0, c0`): an opcode (or `+` and an opcode) that does
// not follow a separator or a swizzle's period.
bool starts_instruction(const std::vector<Token>& toks, uint32_t i, uint32_t begin) {
  if (i <= begin) return false;
  const Token& prev = toks[i - 1];
  if (prev.is(TokenKind::comma) || prev.is(TokenKind::period) || prev.is(TokenKind::plus) ||
      prev.is(TokenKind::minus) || prev.is(TokenKind::l_square))
    return false;
  if (toks[i].is(TokenKind::plus)) return i + 1 < toks.size() && is_opcode(toks[i + 1]);
  return is_opcode(toks[i]);
}

// The instructions of a token span: a token at a line start, after `;`, or an opcode after
// a complete instruction begins a new one.
std::vector<Tokens> split_lines(const ast::Effect& effect, ast::TokenSpan span) {
  std::vector<Tokens> lines;
  const uint32_t last = std::min<uint32_t>(span.last, uint32_t(effect.tokens.size()));
  uint32_t begin = span.first;
  for (uint32_t i = span.first; i <= last; ++i) {
    bool end = i == last || effect.tokens[i].is(TokenKind::semi) ||
               (i > begin && (effect.tokens[i].at_line_start() || starts_instruction(effect.tokens, i, begin)));
    if (!end) continue;
    if (i > begin) lines.emplace_back(effect.tokens.data() + begin, i - begin);
    begin = (i < last && effect.tokens[i].is(TokenKind::semi)) ? i + 1 : i;
  }
  return lines;
}

bool parse_version(Tokens line, AsmVersion& v) {
  std::string text;
  for (const Token& t : line) text += t.text();
  text = ascii_lower(text);
  if (text.size() != 6 || (text[0] != 'v' && text[0] != 'p') || text[1] != 's' || (text[2] != '.' && text[2] != '_') ||
      (text[4] != '.' && text[4] != '_') || !std::isdigit(static_cast<unsigned char>(text[3])) ||
      !std::isdigit(static_cast<unsigned char>(text[5])))
    return false;
  v.pixel = text[0] == 'p';
  v.major = text[3] - '0';
  v.minor = text[5] - '0';
  return true;
}

// `decl { stream 0; float v0[3]; ... }`: the v registers it declares (DirectX 8 numbering).
void parse_decl(const ast::Effect& effect, ast::TokenSpan decl, std::vector<uint32_t>& regs) {
  const uint32_t last = std::min<uint32_t>(decl.last, uint32_t(effect.tokens.size()));
  for (uint32_t i = decl.first; i < last; ++i) {
    std::string_view w = effect.tokens[i].text();
    if (effect.tokens[i].kind != TokenKind::identifier || w.size() < 2 || (w[0] != 'v' && w[0] != 'V')) continue;
    uint32_t n = 0;
    auto [end, ec] = std::from_chars(w.data() + 1, w.data() + w.size(), n);
    if (ec == std::errc() && end == w.data() + w.size()) regs.push_back(n);
  }
}

std::string usage_semantic(const std::string& usage, uint32_t index) {
  std::string s;
  for (char c : usage) s.push_back(char(std::toupper(static_cast<unsigned char>(c))));
  if (s == "COLOR" || s == "TEXCOORD" || index) s += std::to_string(index);
  return s;
}

}  // namespace

std::string AsmVersion::spelled() const {
  return std::string(pixel ? "ps." : "vs.") + std::to_string(major) + "." + std::to_string(minor);
}

std::optional<AsmVersion> assembly_version(const ast::Effect& effect, ast::TokenSpan code) {
  std::vector<Tokens> lines = split_lines(effect, code);
  AsmVersion v;
  if (lines.empty() || !parse_version(lines.front(), v)) return std::nullopt;
  return v;
}

std::string dx8_input_semantic(uint32_t reg) {
  switch (reg) {
    case 0: return "POSITION";
    case 1: return "BLENDWEIGHT";
    case 2: return "BLENDINDICES";
    case 3: return "NORMAL";
    case 4: return "PSIZE";
    case 5: return "COLOR0";
    case 6: return "COLOR1";
    case 7: return "TEXCOORD0";
    case 8: return "TANGENT";
    default: return "TEXCOORD" + std::to_string(reg - 7);
  }
}

std::optional<AsmProgram> parse_assembly(const ast::Effect& effect, ast::TokenSpan code, ast::TokenSpan decl,
                                         DiagnosticSink& sink) {
  std::vector<Tokens> lines = split_lines(effect, code);
  AsmProgram p;
  if (lines.empty() || !parse_version(lines.front(), p.version) || p.version.major != 1 ||
      (!p.version.pixel && p.version.minor > 1) || (p.version.pixel && p.version.minor > 4)) {
    SourceRange r = lines.empty() ? SourceRange{} : span_range(lines.front());
    sink.error("asm-version", r, "expected a version vs.1.0, vs.1.1 or ps.1.0 to ps.1.4 on the first line");
    return std::nullopt;
  }
  p.range = span_range(lines.front());
  bool ok = true;
  uint32_t phase = 0;
  std::vector<uint32_t> declared;
  parse_decl(effect, decl, declared);
  for (size_t l = 1; l < lines.size(); ++l) {
    AsmInstruction ins;
    LineParser parser(lines[l], p.version, sink);
    if (!parser.parse(ins)) {
      ok = false;
      continue;
    }
    if (ins.op == "phase") {
      if (phase) ok = parser.error(ins.range, "a shader has one 'phase'");
      phase = 1;
    }
    ins.phase = phase;
    if (ins.coissue && (p.instructions.empty() || p.instructions.back().coissue || !p.version.pixel))
      ok = parser.error(ins.range, "'+' co-issues a pixel shader instruction with the one before it");
    p.instructions.push_back(std::move(ins));
  }
  if (!ok) return std::nullopt;
  if (!p.version.pixel) {
    // Every input register read, with its semantic: dcl first, then the DirectX 8 numbering.
    std::vector<uint32_t> regs = declared;
    for (const AsmInstruction& ins : p.instructions)
      for (const AsmSource& s : ins.sources)
        if (s.file == RegisterFile::input) regs.push_back(s.index);
    for (const AsmInstruction& ins : p.instructions)
      if (ins.op == "dcl" && ins.has_dest && ins.dest.file == RegisterFile::input) regs.push_back(ins.dest.index);
    std::sort(regs.begin(), regs.end());
    regs.erase(std::unique(regs.begin(), regs.end()), regs.end());
    for (uint32_t r : regs) {
      std::string semantic = dx8_input_semantic(r);
      for (const AsmInstruction& ins : p.instructions)
        if (ins.op == "dcl" && ins.dest.file == RegisterFile::input && ins.dest.index == r)
          semantic = usage_semantic(ins.usage, ins.usage_index);
      p.inputs.push_back({r, semantic});
    }
  }
  return p;
}

}  // namespace fx::emulation
