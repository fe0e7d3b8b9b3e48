#include "flat_initializer.h"

#include "numeric_type.h"

#include <string_view>

namespace fx::detail {
namespace {

// The value of a decimal integer literal (`3`, `3u`), 0 when it is not one.
uint32_t literal_size(const Token& t) {
  if (!t.is(TokenKind::integer)) return 0;
  uint32_t size = 0;
  std::string_view text = t.text();
  if (text.size() > 1 && text[0] == '0') return 0;  // octal or hex: not worth the trouble
  for (char c : text) {
    if (c < '0' || c > '9') break;
    size = size * 10 + static_cast<uint32_t>(c - '0');
    if (size > (1u << 20)) return 0;
  }
  return size;
}

}  // namespace

std::unordered_map<uint32_t, std::string> flat_initializer_spellings(const std::vector<Token>& toks) {
  std::unordered_map<uint32_t, std::string> out;
  const uint32_t n = static_cast<uint32_t>(toks.size());
  for (uint32_t i = 0; i + 6 < n; ++i) {
    // `T name [ N ] ... = {`
    const uint32_t components = toks[i].is(TokenKind::identifier) ? numeric_components(toks[i].text()) : 0;
    if (!components || !toks[i + 1].is(TokenKind::identifier) || !toks[i + 2].is(TokenKind::l_square)) continue;
    uint32_t at = i + 2;
    std::vector<uint32_t> dims;  // 0 for an unsized dimension
    while (at < n && toks[at].is(TokenKind::l_square)) {
      uint32_t size = 0;
      if (at + 1 < n && !toks[at + 1].is(TokenKind::r_square)) size = literal_size(toks[++at]);
      dims.push_back(size);
      if (++at >= n || !toks[at].is(TokenKind::r_square)) break;
      ++at;
    }
    if (at + 1 >= n || !toks[at].is(TokenKind::equal) || !toks[at + 1].is(TokenKind::l_brace)) continue;
    // A one-dimensional array of scalars is already what glslang reads.
    if (components == 1 && dims.size() == 1) continue;
    const uint32_t open = at + 1;
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
    // blocks[l]: the scalars in one element of dimension l (the innermost is a vector's).
    std::vector<uint64_t> blocks(dims.size());
    uint64_t total = components;
    for (size_t l = dims.size(); l-- > 0;) {
      blocks[l] = total;
      total *= dims[l];
    }
    if (!total || scalars != total) continue;
    const bool vector = components > 1;
    const std::string type(toks[i].text());
    const std::string element_open = vector ? type + "(" : "";
    const std::string element_close = vector ? ")" : "";
    // Braces around each element of every dimension but the innermost, whose elements are
    // the scalars or vectors themselves.
    const size_t levels = dims.size() - 1;
    out[open] = "{ " + std::string(levels, '{') + element_open;
    for (uint32_t k = 0; k + 1 < scalars; ++k) {
      const uint64_t next = k + 1;
      if (next % components) continue;
      size_t closed = 0;
      for (size_t l = 0; l < levels; ++l) closed += next % blocks[l] == 0;
      out[commas[k]] = element_close + std::string(closed, '}') + ", " + std::string(closed, '{') + element_open;
    }
    if (trailing) out.insert_or_assign(commas.back(), std::string(" "));
    out.insert_or_assign(close, element_close + std::string(levels, '}') + " }");
    i = close;
  }
  return out;
}

}  // namespace fx::detail
