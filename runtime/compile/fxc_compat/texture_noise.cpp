// tx_1_0's noise() spelled as fxkit's own gradient noise (see texture_noise.h).
#include "texture_noise.h"

namespace fx::detail {

std::unordered_map<uint32_t, std::string> texture_noise_spellings(const std::vector<Token>& toks,
                                                                  const std::vector<const ast::Function*>& functions) {
  std::unordered_map<uint32_t, std::string> out;
  for (const ast::Function* f : functions)
    if (f->name == "noise") return out;
  for (size_t i = 0; i + 1 < toks.size(); ++i)
    if (toks[i].is_identifier("noise") && toks[i + 1].is(TokenKind::l_paren) &&
        !(i > 0 && toks[i - 1].is(TokenKind::period)))
      out[uint32_t(i)] = std::string(kTextureNoise);
  return out;
}

const std::string& texture_noise_definition() {
  static const std::string text = [] {
    const std::string n(kTextureNoise);
    std::string s;
    s += "float " + n + "_gradient(float3 cell, float3 f) {\n";
    s += "  int3 c = int3(cell) & 255;\n";
    s += "  uint h = (uint(c.x) * 73856093u) ^ (uint(c.y) * 19349663u) ^ (uint(c.z) * 83492791u);\n";
    s += "  h ^= h >> 13; h *= 1274126177u; h ^= h >> 16;\n";
    s += "  uint g = h & 15u;\n";
    s += "  float u = g < 8u ? f.x : f.y;\n";
    s += "  float v = g < 4u ? f.y : (g == 12u || g == 14u ? f.x : f.z);\n";
    s += "  return ((g & 1u) != 0u ? -u : u) + ((g & 2u) != 0u ? -v : v);\n";
    s += "}\n";
    s += "float " + n + "(float3 p) {\n";
    s += "  float3 i = floor(p), f = p - i;\n";
    s += "  float3 w = f * f * f * (f * (f * 6 - 15) + 10);\n";
    s += "  float x00 = lerp(" + n + "_gradient(i, f), " + n +
         "_gradient(i + float3(1, 0, 0), f - float3(1, 0, 0)), w.x);\n";
    s += "  float x10 = lerp(" + n + "_gradient(i + float3(0, 1, 0), f - float3(0, 1, 0)), " + n +
         "_gradient(i + float3(1, 1, 0), f - float3(1, 1, 0)), w.x);\n";
    s += "  float x01 = lerp(" + n + "_gradient(i + float3(0, 0, 1), f - float3(0, 0, 1)), " + n +
         "_gradient(i + float3(1, 0, 1), f - float3(1, 0, 1)), w.x);\n";
    s += "  float x11 = lerp(" + n + "_gradient(i + float3(0, 1, 1), f - float3(0, 1, 1)), " + n +
         "_gradient(i + float3(1, 1, 1), f - float3(1, 1, 1)), w.x);\n";
    s += "  return lerp(lerp(x00, x10, w.y), lerp(x01, x11, w.y), w.z);\n";
    s += "}\n";
    s += "float " + n + "(float x) { return " + n + "(float3(x, 0, 0)); }\n";
    s += "float " + n + "(float2 p) { return " + n + "(float3(p, 0)); }\n";
    s += "float " + n + "(float4 p) { return " + n + "(p.xyz + p.w * float3(0.618034, 0.414214, 0.732051)); }\n";
    return s;
  }();
  return text;
}

}  // namespace fx::detail
