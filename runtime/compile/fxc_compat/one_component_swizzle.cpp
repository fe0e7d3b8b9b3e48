// The `.x` of a one-component vector written as `[0]` (see one_component_swizzle.h).
#include "one_component_swizzle.h"

#include <string_view>
#include <unordered_map>

#include "numeric_type.h"

namespace fx::detail {

std::unordered_map<uint32_t, std::string> one_component_swizzle_spellings(const std::vector<Token>& toks) {
  std::unordered_map<uint32_t, std::string> out;
  // Declared names (`T name`, `T a, name`): whether any declaration is of a one-component
  // vector, and whether every one is of a vector type (on which `[0]` means `.x`).
  struct Declared {
    bool one_component = false, vectors_only = true;
  };
  std::unordered_map<std::string_view, Declared> names;
  const auto vector_components = [](std::string_view type) {
    const uint32_t n = numeric_components(type);
    return n && type.back() == static_cast<char>('0' + n) ? n : 0;
  };
  std::string_view type;  // the type of the declaration being read, until its `;` or `)`
  int depth = 0, type_depth = 0;
  for (size_t i = 0; i + 1 < toks.size(); ++i) {
    const Token& t = toks[i];
    if (t.is(TokenKind::l_paren) || t.is(TokenKind::l_brace)) ++depth;
    if (t.is(TokenKind::r_paren) || t.is(TokenKind::r_brace)) --depth;
    if (t.is(TokenKind::semi) || depth < type_depth) type = {};
    if (!t.is(TokenKind::identifier)) continue;
    const bool member = i > 0 && (toks[i - 1].is(TokenKind::period) || toks[i - 1].is(TokenKind::arrow));
    std::string_view declared;
    // `T name`; `return t`, `else t.x = 1` are statements.
    const bool statement = t.text() == "return" || t.text() == "else" || t.text() == "case" || t.text() == "do";
    if (!member && !statement && toks[i + 1].is(TokenKind::identifier)) {
      type = t.text();
      type_depth = depth;
      declared = toks[i + 1].text();
    } else if (!type.empty() && depth == type_depth && i > 0 && toks[i - 1].is(TokenKind::comma)) {  // `T a, name`
      declared = t.text();
    }
    if (declared.empty()) continue;
    Declared& d = names[declared];
    const uint32_t n = vector_components(type);
    d.one_component = d.one_component || n == 1;
    d.vectors_only = d.vectors_only && n != 0;
  }
  for (size_t i = 1; i + 1 < toks.size(); ++i) {
    if (!toks[i].is(TokenKind::period) || !toks[i - 1].is(TokenKind::identifier) ||
        !(toks[i + 1].is_identifier("x") || toks[i + 1].is_identifier("r")))
      continue;
    auto d = names.find(toks[i - 1].text());
    if (d == names.end() || !d->second.one_component || !d->second.vectors_only) continue;
    out[static_cast<uint32_t>(i)] = "[";
    out[static_cast<uint32_t>(i + 1)] = "0]";
  }
  return out;
}

}  // namespace fx::detail
