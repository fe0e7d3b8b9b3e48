// Helpers shared by the shader compilation tests: spirv-val and small shader sources.
#pragma once
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fx/compile/shader_compiler.h"

namespace fx::test {

// Runs the spirv-val CLI on `words` for Vulkan 1.1; returns its output, "" when valid.
inline std::string spirv_val(const std::vector<uint32_t>& words, const std::string& env = "vulkan1.1") {
  static int counter = 0;
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "fxkit_spirv_val";
  std::filesystem::create_directories(dir);
  std::string stem = (dir / (std::to_string(::getpid()) + "_" + std::to_string(counter++))).string();
  std::ofstream(stem + ".spv", std::ios::binary)
      .write(reinterpret_cast<const char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
  std::string cmd = "spirv-val --target-env " + env + " " + stem + ".spv > " + stem + ".log 2>&1";
  int rc = std::system(cmd.c_str());
  std::ifstream log(stem + ".log");
  std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  std::filesystem::remove(stem + ".spv");
  std::filesystem::remove(stem + ".log");
  return rc == 0 ? std::string() : (text.empty() ? "spirv-val failed" : text);
}

// spirv-dis's text of `words` ("" when it fails).
inline std::string spirv_dis(const std::vector<uint32_t>& words) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "fxkit_spirv_val";
  std::filesystem::create_directories(dir);
  std::string stem = (dir / (std::to_string(::getpid()) + "_dis")).string();
  std::ofstream(stem + ".spv", std::ios::binary)
      .write(reinterpret_cast<const char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
  std::string cmd = "spirv-dis " + stem + ".spv > " + stem + ".txt 2>&1";
  std::string out;
  if (std::system(cmd.c_str()) == 0) {
    std::ifstream text(stem + ".txt");
    out.assign(std::istreambuf_iterator<char>(text), std::istreambuf_iterator<char>());
  }
  std::filesystem::remove(stem + ".spv");
  std::filesystem::remove(stem + ".txt");
  return out;
}

// Variable name -> Binding decoration, read from spirv-dis: what the module itself says,
// whatever reflection says.
inline std::map<std::string, uint32_t> spirv_bindings(const std::vector<uint32_t>& words) {
  std::map<std::string, uint32_t> out;
  std::istringstream text(spirv_dis(words));
  std::string op, name, decoration;
  for (std::string line; std::getline(text, line);) {
    std::istringstream in(line);
    uint32_t binding = 0;
    if (in >> op >> name >> decoration >> binding && op == "OpDecorate" && decoration == "Binding") out[name] = binding;
  }
  return out;
}

inline std::string messages_of(const CompiledShader& s) {
  std::string out;
  for (const ShaderMessage& m : s.messages)
    out += m.file + ":" + std::to_string(m.line) + ":" + std::to_string(m.column) + ": " + m.text + "\n";
  return out;
}

// D3D9-style effect shader code (what the effect compiler hands over once techniques,
// textures and sampler_state blocks are removed), with #line naming the .fx file.
inline const char* kD3D9Effect = R"(#line 3 "d3d9.fx"
float4x4 mWorldViewProj;
float3 LightDir;
float Gloss;
sampler2D DiffuseSampler;

struct VS_INPUT {
  float4 Position : POSITION;
  float3 Normal   : NORMAL;
  float2 Tex      : TEXCOORD0;
};
struct VS_OUTPUT {
  float4 Position : POSITION;
  float4 Diffuse  : COLOR0;
  float2 Tex      : TEXCOORD0;
};

VS_OUTPUT VS(VS_INPUT i) {
  VS_OUTPUT o;
  o.Position = mul(i.Position, mWorldViewProj);
  o.Diffuse = float4(saturate(dot(i.Normal, LightDir)) * Gloss.xxx, 1);
  o.Tex = i.Tex;
  return o;
}

float4 PS(float2 tex : TEXCOORD0, float4 diffuse : COLOR0) : COLOR0 {
  return tex2D(DiffuseSampler, tex) * diffuse * Gloss;
}
)";

// D3D10-style: cbuffer, Texture2D + SamplerState, SV_Position / SV_Target.
inline const char* kD3D10Effect = R"(#line 1 "d3d10.fx"
cbuffer PerObject {
  float4x4 World;
  float4x4 ViewProj;
};
cbuffer PerFrame {
  float3 EyePos;
  float Time;
};
Texture2D Albedo;
SamplerState Linear;

struct VSIn { float3 pos : POSITION; float2 uv : TEXCOORD0; };
struct PSIn { float4 pos : SV_Position; float2 uv : TEXCOORD0; float fog : FOG; };

PSIn VS(VSIn v) {
  PSIn o;
  float4 w = mul(float4(v.pos, 1), World);
  o.pos = mul(w, ViewProj);
  o.uv = v.uv;
  o.fog = length(w.xyz - EyePos);
  return o;
}

float4 PS(PSIn i) : SV_Target {
  return Albedo.Sample(Linear, i.uv) * (1.0 - i.fog * 0.01) + Time * 0.0;
}
)";

inline TranslationUnit unit(const char* source, ShaderStage stage, const char* entry, const char* profile,
                            ShaderLanguage language = ShaderLanguage::hlsl) {
  TranslationUnit u;
  u.source = source;
  u.stage = stage;
  u.language = language;
  u.entry_point = entry;
  u.profile = profile;
  return u;
}

}  // namespace fx::test
