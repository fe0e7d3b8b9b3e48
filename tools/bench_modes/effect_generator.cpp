#include "effect_generator.h"

#include <string>

namespace fx::tools {
namespace {

// One module: `id` keeps every name unique across modules.
std::string module_text(int id, std::string& shader_code) {
  std::string n = std::to_string(id);
  std::string params = "shared float4x4 WorldViewProj" + n +
                       " : WORLDVIEWPROJECTION;\n"
                       "float3 LightDir" +
                       n + " < string UIName = \"Light " + n +
                       "\"; float UIMin = -1; float UIMax = 1; > = {0.577, -0.577, 0.577};\n"
                       "float4 Diffuse" +
                       n +
                       " : DIFFUSE < string UIWidget = \"Color\"; > = float4(0.8, 0.7, 0.6, 1.0);\n"
                       "float Shininess" +
                       n + " < float UIMin = 1; float UIMax = 128; > = 32.0;\n";
  std::string samplers = "texture DiffuseMap" + n +
                         " < string ResourceName = \"default_color.dds\"; >;\n"
                         "sampler2D DiffuseSampler" +
                         n +
                         " = sampler_state {\n"
                         "  Texture = <DiffuseMap" +
                         n +
                         ">; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear;\n"
                         "  AddressU = Wrap; AddressV = Wrap;\n};\n";
  std::string code = "struct VSIn" + n +
                     " { float4 pos : POSITION; float3 normal : NORMAL; float2 uv : TEXCOORD0; };\n"
                     "struct VSOut" +
                     n +
                     " { float4 pos : POSITION; float3 normal : TEXCOORD1; float2 uv : TEXCOORD0; };\n"
                     "VSOut" +
                     n + " VS" + n + "(VSIn" + n +
                     " i)\n{\n"
                     "  VSOut" +
                     n +
                     " o;\n"
                     "  o.pos = mul(i.pos, WorldViewProj" +
                     n +
                     ");\n"
                     "  o.normal = normalize(i.normal);\n"
                     "  o.uv = i.uv * SCALE(1.0);\n"
                     "  return o;\n}\n"
                     "float4 PS" +
                     n + "(VSOut" + n +
                     " i, uniform bool specular) : COLOR0\n{\n"
                     "  float3 n = normalize(i.normal);\n"
                     "  float3 l = -LightDir" +
                     n +
                     ";\n"
                     "  float ndl = saturate(dot(n, l));\n"
                     "  float3 h = normalize(l + float3(0, 0, 1));\n"
                     "  float spec = specular ? pow(saturate(dot(n, h)), Shininess" +
                     n +
                     ") : 0.0;\n"
                     "  float4 albedo = tex2D(DiffuseSampler" +
                     n +
                     ", i.uv);\n"
                     "  return albedo * Diffuse" +
                     n + " * ndl + spec;\n}\n";
  std::string techniques = "technique Lit" + n +
                           " < string Scheme = \"quality\"; float MaxDistance = 50; >\n{\n"
                           "  pass P0\n  {\n"
                           "    VertexShader = compile vs_2_0 VS" +
                           n +
                           "();\n"
                           "    PixelShader = compile ps_2_0 PS" +
                           n +
                           "(true);\n"
                           "    ZEnable = true; ZWriteEnable = true; CullMode = CCW;\n"
                           "    AlphaBlendEnable = false; SrcBlend = SrcAlpha; DestBlend = InvSrcAlpha;\n"
                           "  }\n  pass P1\n  {\n"
                           "    PixelShader = compile ps_2_0 PS" +
                           n +
                           "(false);\n"
                           "    AlphaBlendEnable = true; ZWriteEnable = false;\n"
                           "  }\n}\n";
  shader_code += params;
  shader_code += "sampler2D DiffuseSampler" + n + ";\n";
  shader_code += code;
  return "// Generated module " + n + "\n" + params + samplers + code + techniques;
}

}  // namespace

GeneratedEffect generate_effect(size_t min_bytes) {
  GeneratedEffect g;
  g.main_name = "bench_main.fx";
  g.shader_code = "#define SCALE(x) ((x) * 1.0)\n";
  std::string main = "// Generated benchmark effect\n#define SCALE(x) ((x) * 1.0)\n";
  size_t total = main.size();
  for (int m = 0; total < min_bytes; ++m) {
    std::string name = "module" + std::to_string(m) + ".fxh";
    std::string text;
    for (int k = 0; text.size() < 64 * 1024; ++k) text += module_text(m * 1000 + k, g.shader_code);
    main += "#include \"" + name + "\"\n";
    total += text.size() + name.size() + 12;
    g.files[name] = std::move(text);
  }
  g.files[g.main_name] = main;
  g.effect_bytes = 0;
  for (const auto& [name, text] : g.files) g.effect_bytes += text.size();
  return g;
}

}  // namespace fx::tools
