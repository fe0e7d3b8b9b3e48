#include "untyped_sampler.h"

#include <string_view>

namespace fx::detail {

namespace {

// The sampler type an intrinsic named `name` reads, or "" when it is not a D3D9 sampler
// intrinsic; tex2D* reads "sampler2D".
std::string_view sampler_type_read_by(std::string_view name) {
  static constexpr std::pair<std::string_view, std::string_view> kinds[] = {
      {"tex1D", "sampler1D"}, {"tex2D", "sampler2D"}, {"tex3D", "sampler3D"}, {"texCUBE", "samplerCUBE"}};
  for (auto [prefix, type] : kinds)
    if (name.starts_with(prefix)) {
      std::string_view suffix = name.substr(prefix.size());
      if (suffix.empty() || suffix == "lod" || suffix == "bias" || suffix == "grad" || suffix == "proj") return type;
    }
  return {};
}

}  // namespace

std::unordered_map<uint32_t, std::string> untyped_sampler_spellings(const std::vector<Token>& toks) {
  const uint32_t n = static_cast<uint32_t>(toks.size());
  // What each sampler name is read as: a type, or "" once two calls disagree.
  std::unordered_map<std::string_view, std::string_view> read_as;
  for (uint32_t i = 0; i + 2 < n; ++i) {
    if (!toks[i].is(TokenKind::identifier) || !toks[i + 1].is(TokenKind::l_paren) ||
        !toks[i + 2].is(TokenKind::identifier))
      continue;
    std::string_view type = sampler_type_read_by(toks[i].text());
    if (type.empty()) continue;
    auto [at, inserted] = read_as.emplace(toks[i + 2].text(), type);
    if (!inserted && at->second != type) at->second = {};
  }
  std::unordered_map<uint32_t, std::string> out;
  for (uint32_t i = 0; i + 1 < n; ++i) {
    if (!toks[i].is_identifier("sampler") || !toks[i + 1].is(TokenKind::identifier)) continue;
    if (i > 0 && (toks[i - 1].is(TokenKind::period) || toks[i - 1].is(TokenKind::arrow))) continue;
    auto read = read_as.find(toks[i + 1].text());
    if (read != read_as.end() && !read->second.empty() && read->second != "sampler2D")
      out[i] = std::string(read->second);
  }
  return out;
}

}  // namespace fx::detail
