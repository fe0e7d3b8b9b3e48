// What the shader compiler consumes: one stage of one pass as text plus how to read it.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fx {

// Pipeline stage a translation unit is compiled for.
enum class ShaderStage : uint8_t { vertex, tess_control, tess_evaluation, geometry, fragment, compute };
// Front end that reads the source text.
enum class ShaderLanguage : uint8_t { hlsl, glsl };

const char* to_string(ShaderStage stage);
const char* to_string(ShaderLanguage language);

// A parsed profile string ("vs_2_0", "ps_4_0", "gs_4_0", "cs_5_0", "glsl", "450").
struct ShaderProfile {
  ShaderLanguage language = ShaderLanguage::hlsl;
  std::optional<ShaderStage> stage;  // implied by an HLSL profile; none for GLSL profiles
  int major = 0, minor = 0;          // shader model (HLSL) or 4/5 for "450" (GLSL)
  // D3D9 shader models (1.x-3.0) get glslang's DX9 compatibility mode.
  bool dx9() const { return language == ShaderLanguage::hlsl && major <= 3; }
};

// Parses a profile string; nullopt when it is not one fxkit knows. "vs_4_0_level_9_1"
// style suffixes are accepted and ignored.
std::optional<ShaderProfile> parse_profile(std::string_view profile);

// A preprocessor definition prepended to the source (`#define name value`).
struct ShaderDefine {
  std::string name;
  std::string value;
};

// One stage's source, already containing #line directives that name the .fx file.
struct TranslationUnit {
  std::string source;
  ShaderStage stage = ShaderStage::vertex;
  ShaderLanguage language = ShaderLanguage::hlsl;
  std::string entry_point = "main";  // the function in `source`; kept as the SPIR-V entry name
  std::string profile;               // "vs_2_0" ... "ps_5_0", "gs_4_0", "cs_5_0", "glsl", "450"
  std::vector<ShaderDefine> defines;
  std::string name = "<shader>";  // file name glslang reports before the first #line
};

// Vulkan version the SPIR-V is produced for: 1.0 -> SPIR-V 1.0, 1.1+ -> SPIR-V 1.3.
enum class VulkanTarget : uint8_t { vulkan_1_0, vulkan_1_1, vulkan_1_2, vulkan_1_3 };

// Compiler switches that change the produced SPIR-V (and so are part of the cache key).
struct CompileOptions {
  VulkanTarget target = VulkanTarget::vulkan_1_1;
  bool debug_info = false;  // OpLine/OpSource for debuggers (RenderDoc)
  // Keeps SPV_GOOGLE_hlsl_functionality1 semantic strings in the module. Off by default:
  // drivers need VK_GOOGLE_hlsl_functionality1 for them; reflection reads them first.
  bool keep_hlsl_semantics = false;
  bool warnings_as_errors = false;
  // Runs SPIRV-Tools' validator on glslang's output (about 4 ms per small HLSL shader):
  // glslang accepts some code it then translates to invalid SPIR-V.
  bool validate = true;
};

}  // namespace fx
