// The compute unit that runs a D3DX texture shader (fx/model/texture_shader.h): one thread
// per texel calls the effect's function with the texel's centre and size and stores the
// colour it returns, as RGBA8 (D3DX fills A8R8G8B8 textures: saturated, rounded to 8 bits),
// into a storage buffer the Vulkan binding copies into the texture.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

#include "fx/compile/effect_units.h"
#include "fx/model/texture_shader.h"
#include "fx/source_manager.h"

namespace fx {

// The unit's entry point, its workgroup's edge (numthreads(8, 8, 1)) and the storage buffer it
// writes: one uint per texel (R in the low byte), row after row, layer after layer (a 3D
// texture's slices; a cube's faces in +X, -X, +Y, -Y, +Z, -Z order).
inline constexpr std::string_view kTextureFillEntry = "texture_fill__fx";
inline constexpr uint32_t kTextureFillGroup = 8;
inline constexpr std::string_view kTextureFillTexels = "texture_fill__texels";

// The layers the texels come in: a 3D texture's depth, a cube's 6 faces, 1 for 2D.
uint32_t texture_fill_layers(const TextureShader& shader);

// The unit: what the function reaches in the effect, then the entry point, whose #line names
// the function annotation. nullopt when the effect has no such function (EffectUnits::compute_unit).
std::optional<TranslationUnit> texture_fill_unit(const EffectUnits& units, const TextureShader& shader,
                                                 const SourceManager& sm);

}  // namespace fx
