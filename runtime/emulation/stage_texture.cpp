// Stage textures: the fx_stage<n> sampler names and what they bind (see stage_texture.h).
#include "fx/emulation/stage_texture.h"

#include <charconv>

namespace fx::emulation {

namespace {
constexpr std::string_view kPrefix = "fx_stage";
}

std::string stage_sampler_name(uint32_t stage) { return std::string(kPrefix) + std::to_string(stage); }

std::optional<uint32_t> stage_of_sampler(std::string_view name) {
  if (!name.starts_with(kPrefix) || name.size() == kPrefix.size()) return std::nullopt;
  uint32_t n = 0;
  const char* end = name.data() + name.size();
  auto [at, ec] = std::from_chars(name.data() + kPrefix.size(), end, n);
  if (ec != std::errc() || at != end || n >= 16) return std::nullopt;
  return n;
}

StageTexture stage_texture(const PassInfo& pass, uint32_t stage) {
  StageTexture t;
  t.sampler = pass.stage_sampler(stage, t.texture);
  return t;
}

}  // namespace fx::emulation
