#include "flat_initializer.h"

#include <string_view>

namespace fx::detail {
namespace {

// Components of a vector type name (float4, half3, int2, uint4, bool2, double3); 0 otherwise.
uint32_t vector_components(std::string_view type) {
  for (std::string_view base : {"float", "half", "int", "uint", "bool", "double", "min16float", "min16int"})
    if (type.size() == base.size() + 1 && type.starts_with(base) && type.back() >= '2' && type.back() <= '4')
      return static_cast<uint32_t>(type.back() - '0');
  return 0;
}

}  // namespace

std::unordered_map<uint32_t, std::string> flat_initializer_spellings(const std::vector<Token>& toks) {
  std::unordered_map<uint32_t, std::string> out;
  const uint32_t n = static_cast<uint32_t>(toks.size());
  for (uint32_t i = 0; i + 6 < n; ++i) {
    // `T name [ N ] = {`
    const uint32_t components = toks[i].is(TokenKind::identifier) ? vector_components(toks[i].text()) : 0;
    if (!components || !toks[i + 1].is(TokenKind::identifier) || !toks[i + 2].is(TokenKind::l_square)) continue;
    uint32_t at = i + 3, size = 0;
    if (toks[at].is(TokenKind::integer)) {
      for (char c : toks[at].text()) {
        if (c < '0' || c > '9') break;
        size = size * 10 + static_cast<uint32_t>(c - '0');
      }
      ++at;
    }
    if (at + 2 >= n || !toks[at].is(TokenKind::r_square) || !toks[at + 1].is(TokenKind::equal) ||
        !toks[at + 2].is(TokenKind::l_brace))
      continue;
    const uint32_t open = at + 2;
    std::vector<uint32_t> commas;  // top-level commas
    uint32_t close = open + 1;
    bool nested = false;
    for (int depth = 0; close < n; ++close) {
      const Token& t = toks[close];
      if (t.is(TokenKind::l_brace)) nested = true;
      if (t.is(TokenKind::l_paren) || t.is(TokenKind::l_square)) ++depth;
      if (t.is(TokenKind::r_paren) || t.is(TokenKind::r_square)) --depth;
      if (depth == 0 && t.is(TokenKind::comma)) commas.push_back(close);
      if (depth == 0 && t.is(TokenKind::r_brace)) break;
      if (t.is(TokenKind::semi)) break;
    }
    if (nested || close >= n || !toks[close].is(TokenKind::r_brace) || close == open + 1) continue;
    const bool trailing = !commas.empty() && commas.back() + 1 == close;
    const uint32_t scalars = static_cast<uint32_t>(commas.size()) + (trailing ? 0 : 1);
    // Sized arrays only: in `float4 a[] = { u, v, w, x }` the elements may be vectors.
    if (!size || scalars != size * components) continue;
    const std::string type(toks[i].text());
    out[open] = "{ " + type + "(";
    for (uint32_t k = components - 1; k + 1 < scalars; k += components) out[commas[k]] = "), " + type + "(";
    if (trailing) out.insert_or_assign(commas.back(), std::string(" "));
    out.insert_or_assign(close, std::string(") }"));
    i = close;
  }
  return out;
}

}  // namespace fx::detail
