// Stage textures: how generated shaders (translated assembly, fixed-function stages) sample
// D3D9 texture stage n. The HLSL declares a sampler named stage_sampler_name(n)
// (`sampler2D fx_stage0;`, samplerCUBE/sampler3D by the texture's shape); the runtime binds
// to it the texture the pass's Texture[n] state names, with that stage's sampler states
// (AddressU[n], MinFilter[n] ...) over D3D9's defaults: PassInfo::stage_sampler(n).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "fx/model/effect_model.h"

namespace fx::emulation {

// "fx_stage<n>": the sampler generated code declares for texture stage n.
std::string stage_sampler_name(uint32_t stage);
// The stage a sampler name stands for ("fx_stage3" -> 3), nullopt for other names.
std::optional<uint32_t> stage_of_sampler(std::string_view name);

// What stage `stage` of `pass` samples: the texture parameter (kNoIndex when the pass sets
// no Texture[stage]) and the sampler description.
struct StageTexture {
  uint32_t texture = kNoIndex;
  SamplerDesc sampler;
};
StageTexture stage_texture(const PassInfo& pass, uint32_t stage);

}  // namespace fx::emulation
