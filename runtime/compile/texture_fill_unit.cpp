// texture_fill_unit: the compute entry point that runs a texture shader once per texel.
#include "fx/compile/texture_fill_unit.h"

#include <string>

#include "effect_shader_text.h"

namespace fx {
namespace {

// `value` narrowed to the components a parameter declares (past the texture's dimensions, 0).
std::string swizzled(const char* value, uint8_t components) {
  static const char* masks[] = {"", ".x", ".xy", ".xyz", ""};
  return std::string(value) + masks[components < 5 ? components : 4];
}

}  // namespace

uint32_t texture_fill_layers(const TextureShader& shader) {
  if (shader.shape == TextureShape::cube) return 6;
  return shader.shape == TextureShape::tex3d ? shader.depth : 1;
}

std::optional<TranslationUnit> texture_fill_unit(const EffectUnits& units, const TextureShader& shader,
                                                 const SourceManager& sm) {
  const std::string w = std::to_string(shader.width), h = std::to_string(shader.height);
  const std::string layers = std::to_string(texture_fill_layers(shader));
  std::string text = "\n";
  if (PresumedLocation at = sm.presumed(shader.range.begin); at.valid())
    text += detail::line_directive(at.line, at.file) + "\n";
  // One line: what the compiler says of the entry lands on the annotation's line.
  text += "RWStructuredBuffer<uint> " + std::string(kTextureFillTexels) + "; ";
  text += "[numthreads(" + std::to_string(kTextureFillGroup) + ", " + std::to_string(kTextureFillGroup) + ", 1)] ";
  text += "void " + std::string(kTextureFillEntry) + "(uint3 id : SV_DispatchThreadID) { ";
  text += "if (id.x >= " + w + " || id.y >= " + h + " || id.z >= " + layers + ") return; ";
  // The texel's centre in 0..1 per axis, and one texel's size (LPD3DXFILL2D/3D's pTexCoord,
  // pTexelSize); a cube's face spans -1..1, its texel is the direction through the centre.
  text += "float2 uv = (float2(id.xy) + 0.5) / float2(" + w + ", " + h + "); ";
  switch (shader.shape) {
    case TextureShape::tex3d:
      text += "float4 position = float4(uv, (id.z + 0.5) / " + layers + ".0, 0); ";
      text += "float4 texel_size = float4(1.0 / " + w + ", 1.0 / " + h + ", 1.0 / " + layers + ", 0); ";
      break;
    case TextureShape::cube:
      text += "float2 c = uv * 2 - 1; ";
      text += "float3 faces[6] = { float3(1, -c.y, -c.x), float3(-1, -c.y, c.x), float3(c.x, 1, c.y), ";
      text += "float3(c.x, -1, -c.y), float3(c.x, -c.y, 1), float3(-c.x, -c.y, -1) }; ";
      text += "float4 position = float4(faces[id.z], 0); ";
      text += "float4 texel_size = float4(2.0 / " + w + ", 2.0 / " + w + ", 0, 0); ";
      break;
    default:
      text += "float4 position = float4(uv, 0, 0); ";
      text += "float4 texel_size = float4(1.0 / " + w + ", 1.0 / " + h + ", 0, 0); ";
      break;
  }
  std::string call = shader.function + "(";
  for (size_t i = 0; i < shader.arguments.size(); ++i) {
    const TexelArgument& a = shader.arguments[i];
    call += (i ? ", " : "") + swizzled(a.input == TexelInput::position ? "position" : "texel_size", a.components);
  }
  call += ")";
  text += "uint4 b = uint4(saturate(" + call + ") * 255 + 0.5); ";
  text += std::string(kTextureFillTexels) + "[(id.z * " + h + " + id.y) * " + w +
          " + id.x] = b.x | (b.y << 8) | (b.z << 16) | (b.w << 24); }\n";
  return units.compute_unit(shader.function, kTextureFillEntry, text);
}

}  // namespace fx
