// The Direct3D 9 fixed-function pipeline as generated HLSL: the state of a pass's texture
// stages, vertex processing (transform, lighting, texgen, fog, point size), alpha test and
// fog, and the vertex (`fx_ff_vs`) and pixel (`fx_ff_ps`) shaders that reproduce it.
//
// The shaders link by D3D semantic (POSITION, NORMAL, COLOR0/1, TEXCOORDn, FOG) with HLSL
// or translated shader-model-1 stages through the ordinary glslang HLSL path (profiles
// vs_3_0 / ps_3_0). What they declare:
//   - `sampler2D fx_stage<N>` (samplerCUBE / sampler3D by TextureStageState::texture) for
//     every stage N that samples: the caller binds the texture of pass state Texture[N]
//     with stage N's sampler states.
//   - a value bound to an effect parameter (`TextureFactor = <tf>;`) is declared as a
//     uniform with the parameter's own name and type and read from it; a constant value is
//     written as a literal (as is an array, struct or object parameter's resolved value).
//     Every identifier the generators make starts with fx_: no local hides a parameter.
//   - `float4 fx_ff_screen_to_clip` (vertex shader, pre-transformed vertices and point scaling): clip.xy =
//     screen.xy * .xy + .zw, screen being D3D9 pixel coordinates (pixel centres on integers).
//     For a W x H target with clip-space +Y down (Vulkan, positive viewport height):
//     (2/W, 2/H, -1 + 1/W, -1 + 1/H); with +Y up (negative viewport): (2/W, -2/H, -1 + 1/W, 1 - 1/H).
// Formulas and the measured error: docs/fixed-function.md.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/model/effect_model.h"
#include "fx/model/pass_state.h"

namespace fx {

// D3DTEXTUREOP, with D3D's values.
enum class TextureOp : uint8_t {
  disable = 1,
  select_arg1,
  select_arg2,
  modulate,
  modulate_2x,
  modulate_4x,
  add,
  add_signed,
  add_signed_2x,
  subtract,
  add_smooth,
  blend_diffuse_alpha,
  blend_texture_alpha,
  blend_factor_alpha,
  blend_texture_alpha_pm,
  blend_current_alpha,
  premodulate,
  modulate_alpha_add_color,
  modulate_color_add_alpha,
  modulate_inv_alpha_add_color,
  modulate_inv_color_add_alpha,
  bump_env_map,
  bump_env_map_luminance,
  dot_product3,
  multiply_add,
  lerp,
};
inline constexpr int kTextureOpFirst = 1, kTextureOpLast = 26;
// "Modulate2x" ... as the state table spells it.
const char* to_string(TextureOp op);

// D3DTA_* texture arguments: a register in the low bits and modifier flags.
namespace texture_arg {
inline constexpr uint32_t diffuse = 0, current = 1, texture = 2, tfactor = 3, specular = 4, temp = 5, constant = 6,
                          select_mask = 0xF, complement = 0x10, alpha_replicate = 0x20;
}

// The texture a stage samples, as its sampler type.
enum class StageTexture : uint8_t { none, tex2d, cube, volume };

// An effect parameter a value is read from (`<tf>`): empty name for a constant.
struct ParameterRef {
  std::string name;
  std::string type;  // HLSL spelling of its type: "float4", "float3", "float", "float4x4", "int"
  bool bound() const { return !name.empty(); }
  bool operator==(const ParameterRef&) const = default;
};

// Values of fixed-function states: a constant, or a parameter when `parameter` is bound.
struct FixedScalar {
  float value = 0;
  ParameterRef parameter;
  bool operator==(const FixedScalar&) const = default;
};
struct FixedVector {
  std::array<float, 4> value{0, 0, 0, 0};
  ParameterRef parameter;
  bool operator==(const FixedVector&) const = default;
};
struct FixedMatrix {  // row-vector convention as D3D: v' = v * M, m[row * 4 + col]
  std::array<float, 16> value{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  ParameterRef parameter;
  bool operator==(const FixedMatrix&) const = default;
};

// D3DTSS_TCI_* texture-coordinate generation (the high word of TexCoordIndex).
namespace texcoord_gen {
inline constexpr uint32_t passthru = 0, camera_space_normal = 0x10000, camera_space_position = 0x20000,
                          camera_space_reflection_vector = 0x30000, sphere_map = 0x40000;
}
// D3DTTFF_* texture transform flags.
namespace texture_transform {
inline constexpr uint32_t disable = 0, count_mask = 0xFF, projected = 0x100;
}

// One texture stage (D3DTSS_*), with D3D's defaults for stage `index`.
struct TextureStageState {
  TextureOp color_op = TextureOp::disable, alpha_op = TextureOp::disable;
  std::array<uint32_t, 3> color_arg{texture_arg::current, texture_arg::texture, texture_arg::current};
  std::array<uint32_t, 3> alpha_arg{texture_arg::current, texture_arg::texture, texture_arg::current};
  uint32_t result_arg = texture_arg::current;  // current or temp
  uint32_t tex_coord_index = 0;                // set in the low 16 bits, texcoord_gen in the high
  uint32_t texture_transform_flags = texture_transform::disable;
  FixedMatrix texture_transform;              // TextureTransform[n] (D3DTS_TEXTUREn)
  std::array<FixedScalar, 4> bump_env_mat{};  // 00, 01, 10, 11
  FixedScalar bump_env_lscale, bump_env_loffset;
  FixedVector constant;                       // D3DTSS_CONSTANT (D3DTA_CONSTANT)
  StageTexture texture = StageTexture::none;  // whether Texture[n] is bound, and its type
  bool operator==(const TextureStageState&) const = default;
};
inline constexpr int kTextureStages = 8;

// D3DLIGHTTYPE.
enum class LightType : uint8_t { point = 1, spot = 2, directional = 3 };
struct FixedLight {  // D3D's default light: white directional along +z
  bool enabled = false;
  LightType type = LightType::directional;
  FixedVector diffuse{{1, 1, 1, 0}, {}}, specular, ambient;
  FixedVector position, direction{{0, 0, 1, 0}, {}};
  FixedScalar range, falloff, attenuation0, attenuation1, attenuation2, theta, phi;
  bool operator==(const FixedLight&) const = default;
};
inline constexpr int kFixedLights = 8;

// D3DMATERIALCOLORSOURCE and D3DFOGMODE.
enum class MaterialSource : uint8_t { material = 0, color1 = 1, color2 = 2 };
enum class FogMode : uint8_t { none = 0, exp = 1, exp2 = 2, linear = 3 };

struct FixedFunctionState {
  std::array<TextureStageState, kTextureStages> stages = default_stages();
  FixedVector texture_factor{{1, 1, 1, 1}, {}};  // TextureFactor (D3DTA_TFACTOR), D3DCOLOR 0xFFFFFFFF

  // Which stages come from shaders: a programmable vertex stage writes COLOR0/1,
  // TEXCOORDn and FOG itself, and texture stage N then reads TEXCOORD<TexCoordIndex[N]>.
  bool vertex_shader = false;
  // A programmable pixel stage reads the generated vertex shader's outputs instead of the
  // texture stages (whose ColorOps D3D then ignores). When its inputs are `known` (the caller
  // read them from the pixel shader's reflection) the vertex shader writes exactly those,
  // TEXCOORDn being stage n's coordinates (TexCoordIndex[n], texgen, texture transform);
  // otherwise it writes both colours and the coordinates of the stages the cascade samples.
  bool pixel_shader = false;
  struct PixelShaderInputs {
    bool known = false;
    bool diffuse = true, specular = true, fog = false;
    uint8_t texcoords = 0;  // bit n: TEXCOORDn
    bool operator==(const PixelShaderInputs&) const = default;
  } pixel_shader_inputs;
  // The programmable vertex stage's outputs, when `known` (the caller read them from an HLSL
  // entry's declaration): the pixel shader reads exactly those, each with the components it
  // writes (0: not written). What it does not write reads D3D's default: diffuse (1,1,1,1),
  // specular (0,0,0,0), texture coordinates (0,0,0,1) (missing components too), fog 1.
  // Unknown (assembly, generated stages): the pixel shader reads D3D's full register set.
  struct VertexShaderOutputs {
    bool known = false;
    uint8_t diffuse = 0, specular = 0, fog = 0;
    std::array<uint8_t, 8> texcoords{};  // components of TEXCOORDn
    bool operator==(const VertexShaderOutputs&) const = default;
  } vertex_shader_outputs;
  // Vertex processing (ignored with vertex_shader).
  bool pretransformed = false;                                          // XYZRHW positions (D3DFVF_XYZRHW)
  bool vertex_diffuse = true, vertex_specular = true;                   // the mesh has COLOR0 / COLOR1
  bool vertex_normal = true;                                            // the mesh has NORMAL
  std::array<uint8_t, 8> vertex_texcoord_size{2, 2, 2, 2, 2, 2, 2, 2};  // components of TEXCOORDn
  FixedMatrix world, view, projection;
  bool lighting = true;  // D3DRS_LIGHTING
  std::array<FixedLight, kFixedLights> lights{};
  FixedVector material_diffuse, material_ambient, material_specular, material_emissive;
  FixedScalar material_power;
  FixedVector ambient;  // D3DRS_AMBIENT
  bool specular_enable = false, color_vertex = true, local_viewer = true, normalize_normals = false;
  MaterialSource diffuse_source = MaterialSource::color1, specular_source = MaterialSource::color2,
                 ambient_source = MaterialSource::material, emissive_source = MaterialSource::material;
  FixedScalar point_size{1, {}};
  bool point_size_written = false;  // a point state was set: the vertex shader writes PSIZE
  // PointScaleEnable: size = Vh * PointSize * sqrt(1 / (A + B De + C De^2)), De the eye
  // distance, Vh the viewport height (2 / |fx_ff_screen_to_clip.y|); then clamped to
  // [PointSize_Min, PointSize_Max].
  bool point_scale = false;
  FixedScalar point_scale_a{1, {}}, point_scale_b, point_scale_c;
  FixedScalar point_size_min{1, {}}, point_size_max{64, {}};

  // Fog: table (per pixel) when table_mode is not none, else vertex fog (per vertex mode,
  // or the FOG input / specular alpha when that is none).
  bool fog = false;
  FogMode fog_table_mode = FogMode::none, fog_vertex_mode = FogMode::none;
  FixedScalar fog_start{0, {}}, fog_end{1, {}}, fog_density{1, {}};
  FixedVector fog_color;
  bool range_fog = false;

  // Alpha test (emulated by a discard).
  bool alpha_test = false;
  CompareOp alpha_func = CompareOp::always;
  FixedScalar alpha_ref;  // 0..255

  bool operator==(const FixedFunctionState&) const = default;
  static std::array<TextureStageState, kTextureStages> default_stages();
};

// Generated HLSL of one stage.
struct FixedFunctionShader {
  std::string source;
  std::string entry;    // "fx_ff_vs" / "fx_ff_ps"
  std::string profile;  // "vs_3_0" / "ps_3_0"
};

// The pixel shader of the texture stages, specular add, fog blend and alpha test.
FixedFunctionShader generate_fixed_function_pixel_shader(const FixedFunctionState& state);
// The vertex shader: transform (or XYZRHW), lighting, texgen, texture transforms, vertex
// fog, point size. Its outputs are what generate_fixed_function_pixel_shader reads.
FixedFunctionShader generate_fixed_function_vertex_shader(const FixedFunctionState& state);

// A stable key of everything that changes the generated shaders (parameter names included,
// parameter values not): equal states have equal keys across runs and machines.
uint64_t fixed_function_key(const FixedFunctionState& state);
// The canonical text the key hashes: one `name=value` line per field that differs from D3D's defaults.
std::string fixed_function_description(const FixedFunctionState& state);

// The fixed-function state of `pass`: its D3D9 texture-stage, light, material, transform,
// fog and alpha-test states over D3D's defaults. Values bound to parameters become
// ParameterRefs. A stage's texture type comes from the texture parameter Texture[n] names.
// vertex_shader / pixel_shader are set when the pass binds that stage (the caller fills
// pixel_shader_inputs from the pixel shader's reflection). Warns `fixed-function-frozen` when
// a state that shapes the code is bound to a parameter (its default is used).
FixedFunctionState fixed_function_state(const EffectModel& model, const PassInfo& pass, DiagnosticSink& diags);

}  // namespace fx
