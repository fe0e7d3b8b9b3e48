#include "lvalue_constructor.h"

#include <map>
#include <optional>
#include <string_view>

namespace fx::detail {
namespace {

// Components of a scalar or vector type name: float, half2, int3, uint4, bool, double2...
std::optional<uint32_t> components(std::string_view type) {
  for (std::string_view base : {"float", "half", "int", "uint", "bool", "double", "min16float", "min16int"})
    if (type.substr(0, base.size()) == base) {
      std::string_view rest = type.substr(base.size());
      if (rest.empty()) return 1;
      if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') return static_cast<uint32_t>(rest[0] - '0');
      return std::nullopt;
    }
  return std::nullopt;
}

}  // namespace

std::vector<LvalueConstructor> find_lvalue_constructors(const std::vector<Token>& toks, ast::TokenSpan body) {
  std::vector<LvalueConstructor> out;
  std::map<std::string_view, uint32_t> sizes;  // declared so far: name -> components
  uint32_t declaring = 0;                      // components of the declaration being read (0: none)
  int depth = 0, declaring_depth = 0;
  const uint32_t last = std::min<uint32_t>(body.last, static_cast<uint32_t>(toks.size()));
  for (uint32_t i = body.first; i < last; ++i) {
    const Token& t = toks[i];
    if (t.is(TokenKind::l_paren) || t.is(TokenKind::l_square) || t.is(TokenKind::l_brace)) ++depth;
    if (t.is(TokenKind::r_paren) || t.is(TokenKind::r_square) || t.is(TokenKind::r_brace)) --depth;
    if (t.is(TokenKind::semi) || depth < declaring_depth) declaring = 0;
    if (!t.is(TokenKind::identifier) || i + 1 >= last) continue;
    const Token& next = toks[i + 1];
    std::optional<uint32_t> n = components(t.text());
    // `float2 a`, `float2 a, b`: a declaration (parameters too).
    if (n && next.is(TokenKind::identifier)) {
      sizes[next.text()] = *n;
      declaring = *n;
      declaring_depth = depth;
      continue;
    }
    if (declaring && i > body.first && toks[i - 1].is(TokenKind::comma) && depth == declaring_depth)
      sizes[t.text()] = declaring;
    // `float4 ( a , b ) =` at the start of a statement.
    const bool statement_start = i == body.first || toks[i - 1].is(TokenKind::semi) ||
                                 toks[i - 1].is(TokenKind::l_brace) || toks[i - 1].is(TokenKind::r_brace);
    if (!n || !next.is(TokenKind::l_paren) || !statement_start) continue;
    std::vector<std::pair<std::string_view, uint32_t>> parts;
    uint32_t j = i + 2, total = 0;
    bool ok = true;
    for (; j + 1 < last && ok; j += 2) {
      auto size = toks[j].is(TokenKind::identifier) ? sizes.find(toks[j].text()) : sizes.end();
      ok = size != sizes.end();
      if (!ok) break;
      parts.emplace_back(size->first, size->second);
      total += size->second;
      if (toks[j + 1].is(TokenKind::r_paren)) break;
      ok = toks[j + 1].is(TokenKind::comma);
    }
    if (!ok || j + 2 >= last || !toks[j + 1].is(TokenKind::r_paren) || !toks[j + 2].is(TokenKind::equal) || total != *n)
      continue;
    uint32_t semi = j + 3;
    for (int d = 0; semi < last; ++semi) {
      const Token& s = toks[semi];
      if (s.is(TokenKind::l_paren) || s.is(TokenKind::l_square) || s.is(TokenKind::l_brace)) ++d;
      if (s.is(TokenKind::r_paren) || s.is(TokenKind::r_square) || s.is(TokenKind::r_brace)) --d;
      if (d == 0 && s.is(TokenKind::semi)) break;
    }
    if (semi >= last) continue;
    LvalueConstructor c;
    c.type = i;
    c.equal = j + 2;
    c.semi = semi;
    c.temporary = "fx_lvalue" + std::to_string(out.size());
    uint32_t offset = 0;
    for (auto [name, size] : parts) {
      c.assignments.append(" ").append(name).append(" = ").append(c.temporary).append(".");
      c.assignments.append(std::string_view("xyzw").substr(offset, size)).append(";");
      offset += size;
    }
    out.push_back(std::move(c));
    i = semi;
    declaring = 0;
  }
  return out;
}

}  // namespace fx::detail
