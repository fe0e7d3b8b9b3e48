#include "array_cast.h"

#include <algorithm>
#include <string_view>

namespace fx::detail {
namespace {

// Element types fxc splits a vector into (a vector of that type and N components exists).
constexpr std::string_view kScalars[] = {"float",  "half",       "int",      "uint",     "bool",
                                         "double", "min16float", "min16int", "min16uint"};

}  // namespace

std::vector<ArrayCast> find_array_casts(const std::vector<Token>& toks, ast::TokenSpan body) {
  std::vector<ArrayCast> out;
  const uint32_t last = std::min<uint32_t>(body.last, static_cast<uint32_t>(toks.size()));
  for (uint32_t i = body.first + 1; i + 6 < last; ++i) {
    // `= ( T [ N ] ) operand`
    if (!toks[i - 1].is(TokenKind::equal) || !toks[i].is(TokenKind::l_paren) ||
        !toks[i + 1].is(TokenKind::identifier) || !toks[i + 2].is(TokenKind::l_square) ||
        !toks[i + 3].is(TokenKind::integer) || !toks[i + 4].is(TokenKind::r_square) ||
        !toks[i + 5].is(TokenKind::r_paren))
      continue;
    const std::string_view type = toks[i + 1].text(), count = toks[i + 3].text();
    const bool scalar = std::find(std::begin(kScalars), std::end(kScalars), type) != std::end(kScalars);
    if (!scalar || count.size() != 1 || count[0] < '1' || count[0] > '4') continue;
    uint32_t end = i + 6;
    for (int depth = 0; end < last; ++end) {
      const Token& t = toks[end];
      if (t.is(TokenKind::l_paren) || t.is(TokenKind::l_square) || t.is(TokenKind::l_brace)) ++depth;
      if (t.is(TokenKind::r_paren) || t.is(TokenKind::r_square) || t.is(TokenKind::r_brace)) --depth;
      if (depth < 0 || (depth == 0 && (t.is(TokenKind::semi) || t.is(TokenKind::comma)))) break;
    }
    if (end >= last || end == i + 6 || !(toks[end].is(TokenKind::semi) || toks[end].is(TokenKind::comma))) continue;
    ArrayCast c;
    c.open = i;
    c.operand = i + 6;
    c.end = end;
    c.count = static_cast<uint32_t>(count[0] - '0');
    c.vector = std::string(type) + std::string(count);
    out.push_back(std::move(c));
    i = end;
  }
  return out;
}

std::string array_cast_initializer(const ArrayCast& cast, const std::string& operand) {
  std::string out = "{";
  for (uint32_t k = 0; k < cast.count; ++k)
    out += (k ? ", ((" : " ((") + cast.vector + ")(" + operand + "))[" + std::to_string(k) + "]";
  return out + " }";
}

}  // namespace fx::detail
