// fx::TextureShader: a D3DX texture shader, a texture parameter whose `string function =
// "Fill";` annotation names an HLSL function of the effect evaluated once per texel into the
// texture (D3DXFillTextureTX, D3DXFillVolumeTextureTX, D3DXFillCubeTextureTX), with its
// shape, its size and how the function's parameters are fed. docs/effect-model.md
// "Texture shaders" gives the rules.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/model/type.h"
#include "fx/source_manager.h"

namespace fx {

struct EffectModel;
struct Parameter;

// What one parameter of a texture shader receives.
enum class TexelInput : uint8_t {
  position,    // `: POSITION`: the texel's centre, 0..1 per axis (a cube: its direction, -1..1)
  texel_size,  // `: PSIZE`: one texel's size in the same units
};

// One parameter of the function, in declaration order.
struct TexelArgument {
  TexelInput input = TexelInput::position;
  uint8_t components = 2;  // as declared; past the texture's dimensions they are 0
};

struct TextureShader {
  std::string function;                      // the function annotation's value
  SourceRange range;                         // the annotation's string
  std::string target;                        // `string target = "tx_1_0"` as written ("" if none)
  TextureShape shape = TextureShape::tex2d;  // tex2d, tex3d or cube
  uint32_t width = 64, height = 64;          // a cube's faces are width x width
  uint32_t depth = 1;                        // tex3d only
  std::vector<TexelArgument> arguments;
};

// Texture shaders' default edge, as the DirectX SDK's effect viewers create them when the
// effect names no size.
inline constexpr uint32_t kTextureShaderDefaultSize = 64;
// The largest edge, and texel count, fxkit fills.
inline constexpr uint32_t kTextureShaderMaxEdge = 4096;
inline constexpr uint64_t kTextureShaderMaxTexels = uint64_t(1) << 24;

// The texture shader of `texture` (a texture parameter of `model`), or nullopt when it has no
// `function` annotation or the function cannot fill it: `unknown-texture-function` (no such
// function, with a did-you-mean) and `bad-texture-function` (its parameters, its return type,
// the texture's shape or size), located at the annotation. `model` must have its samplers (a
// texture declared `texture` takes the shape of the sampler that reads it).
std::optional<TextureShader> texture_shader(const EffectModel& model, const Parameter& texture, DiagnosticSink& diags);

}  // namespace fx
