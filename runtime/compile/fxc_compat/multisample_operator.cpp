// The `sample` operator of multisampled textures written as Load (see multisample_operator.h).
#include "multisample_operator.h"

#include <string_view>
#include <unordered_set>

#include "effect_unit_builder.h"  // join_tokens

namespace fx::detail {
namespace {

// Names declared with a multisampled texture type: `Texture2DMS<float4, 4> name`.
std::unordered_set<std::string_view> multisampled_names(const std::vector<Token>& toks) {
  std::unordered_set<std::string_view> names;
  for (size_t i = 0; i < toks.size(); ++i) {
    if (!toks[i].is_identifier("Texture2DMS") && !toks[i].is_identifier("Texture2DMSArray")) continue;
    size_t j = i + 1;
    if (j < toks.size() && toks[j].is(TokenKind::less))  // skip the template arguments
      while (j < toks.size() && !toks[j].is(TokenKind::greater)) ++j;
    if (j < toks.size() && toks[j].is(TokenKind::greater)) ++j;
    if (j < toks.size() && toks[j].is(TokenKind::identifier)) names.insert(toks[j].text());
  }
  return names;
}

// The `]` closing the `[` at `open`, or 0.
size_t closing_square(const std::vector<Token>& toks, size_t open) {
  int depth = 0;
  for (size_t i = open; i < toks.size(); ++i) {
    if (toks[i].is(TokenKind::l_square)) ++depth;
    if (toks[i].is(TokenKind::r_square) && --depth == 0) return i;
    if (toks[i].is(TokenKind::semi)) return 0;
  }
  return 0;
}

}  // namespace

std::unordered_map<uint32_t, std::string> multisample_operator_spellings(const std::vector<Token>& toks) {
  std::unordered_map<uint32_t, std::string> out;
  const std::unordered_set<std::string_view> names = multisampled_names(toks);
  if (names.empty()) return out;
  for (size_t i = 2; i + 1 < toks.size(); ++i) {
    if (!toks[i].is_identifier("sample") || !toks[i - 1].is(TokenKind::period) ||
        !toks[i - 2].is(TokenKind::identifier) || !names.count(toks[i - 2].text()) ||
        !toks[i + 1].is(TokenKind::l_square))
      continue;
    const size_t close_sample = closing_square(toks, i + 1);
    if (!close_sample || close_sample + 1 >= toks.size() || !toks[close_sample + 1].is(TokenKind::l_square)) continue;
    const size_t close_pos = closing_square(toks, close_sample + 1);
    if (!close_pos) continue;
    out[uint32_t(i)] = "Load";
    out[uint32_t(i + 1)] = "(";
    for (size_t k = i + 2; k <= close_sample + 1; ++k) out[uint32_t(k)] = " ";
    out[uint32_t(close_pos)] = ", " + join_tokens(toks, {uint32_t(i + 2), uint32_t(close_sample)}) + ")";
  }
  return out;
}

}  // namespace fx::detail
