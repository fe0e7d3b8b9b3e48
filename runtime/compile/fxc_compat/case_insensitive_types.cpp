#include "case_insensitive_types.h"

#include <algorithm>
#include <string_view>

#include "fx/ascii_case.h"

namespace fx::detail {

std::unordered_map<uint32_t, std::string> case_insensitive_type_spellings(const std::vector<Token>& toks,
                                                                          const std::vector<std::string>& symbols) {
  std::unordered_map<uint32_t, std::string> out;
  const uint32_t n = static_cast<uint32_t>(toks.size());
  for (uint32_t i = 0; i + 1 < n; ++i) {
    const Token& t = toks[i];
    if (!t.is(TokenKind::identifier)) continue;
    const std::string lower = ascii_lower(t.text());
    if (lower == t.text() || (lower != "float" && lower != "matrix" && lower != "vector" && lower != "dword")) continue;
    if (std::binary_search(symbols.begin(), symbols.end(), t.text())) continue;
    if (i > 0 && (toks[i - 1].is(TokenKind::period) || toks[i - 1].is(TokenKind::arrow))) continue;
    const Token& next = toks[i + 1];
    const bool declares = next.is(TokenKind::identifier) || next.is(TokenKind::less);
    const bool casts = i > 0 && toks[i - 1].is(TokenKind::l_paren) && next.is(TokenKind::r_paren);
    if (declares || casts) out[i] = lower;
  }
  return out;
}

}  // namespace fx::detail
