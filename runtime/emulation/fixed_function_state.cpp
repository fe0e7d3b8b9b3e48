// The fixed-function state's defaults, names, canonical description and stable key.
#include <cstdio>
#include <type_traits>

#include "fixed_function_hlsl.h"
#include "fx/emulation/fixed_function.h"

namespace fx {
namespace {

void line(std::string& out, const std::string& name, const std::string& value) { out += name + "=" + value + "\n"; }

std::string text(const ParameterRef& p) { return "<" + p.type + " " + p.name + ">"; }
std::string text(const FixedScalar& v) { return v.parameter.bound() ? text(v.parameter) : ff_detail::literal(v.value); }
std::string text(const FixedVector& v) {
  return v.parameter.bound() ? text(v.parameter) : ff_detail::literal4(v.value);
}
std::string text(const FixedMatrix& m) {
  if (m.parameter.bound()) return text(m.parameter);
  std::string s;
  for (float f : m.value) s += ff_detail::literal(f) + " ";
  return s;
}
std::string text(bool b) { return b ? "1" : "0"; }
std::string text(uint32_t v) { return std::to_string(v); }
template <class E>
requires std::is_enum_v<E> std::string text(E v) { return std::to_string(static_cast<int>(v)); }

// Writes `name=value` when `value` differs from `base` (D3D's default).
template <class T>
void field(std::string& out, const std::string& name, const T& value, const T& base) {
  if (!(value == base)) line(out, name, text(value));
}

}  // namespace

const char* to_string(TextureOp op) {
  static const char* names[] = {"Disable",
                                "SelectArg1",
                                "SelectArg2",
                                "Modulate",
                                "Modulate2x",
                                "Modulate4x",
                                "Add",
                                "AddSigned",
                                "AddSigned2x",
                                "Subtract",
                                "AddSmooth",
                                "BlendDiffuseAlpha",
                                "BlendTextureAlpha",
                                "BlendFactorAlpha",
                                "BlendTextureAlphaPM",
                                "BlendCurrentAlpha",
                                "PreModulate",
                                "ModulateAlpha_AddColor",
                                "ModulateColor_AddAlpha",
                                "ModulateInvAlpha_AddColor",
                                "ModulateInvColor_AddAlpha",
                                "BumpEnvMap",
                                "BumpEnvMapLuminance",
                                "DotProduct3",
                                "MultiplyAdd",
                                "Lerp"};
  const int i = static_cast<int>(op);
  return i >= kTextureOpFirst && i <= kTextureOpLast ? names[i - 1] : "?";
}

std::array<TextureStageState, kTextureStages> FixedFunctionState::default_stages() {
  std::array<TextureStageState, kTextureStages> s{};
  for (int i = 0; i < kTextureStages; ++i) s[i].tex_coord_index = static_cast<uint32_t>(i);
  s[0].color_op = TextureOp::modulate;
  s[0].alpha_op = TextureOp::select_arg1;
  return s;
}

// One line per field that differs from the default state `d`, named as the field.
#define FIELD(name) field(out, #name, s.name, d.name)
#define STAGE_FIELD(name) field(out, p + #name, st.name, ds.name)
#define LIGHT_FIELD(name) field(out, p + #name, li.name, dl.name)

std::string fixed_function_description(const FixedFunctionState& s) {
  const FixedFunctionState d;
  std::string out;
  for (int i = 0; i < kTextureStages; ++i) {
    const TextureStageState &st = s.stages[i], &ds = d.stages[i];
    const std::string p = "stage" + std::to_string(i) + ".";
    STAGE_FIELD(color_op);
    STAGE_FIELD(alpha_op);
    for (int a = 0; a < 3; ++a) {
      field(out, p + "color_arg" + std::to_string(a), st.color_arg[a], ds.color_arg[a]);
      field(out, p + "alpha_arg" + std::to_string(a), st.alpha_arg[a], ds.alpha_arg[a]);
    }
    STAGE_FIELD(result_arg);
    STAGE_FIELD(tex_coord_index);
    STAGE_FIELD(texture_transform_flags);
    STAGE_FIELD(texture_transform);
    for (int m = 0; m < 4; ++m)
      field(out, p + "bump_env_mat" + std::to_string(m), st.bump_env_mat[m], ds.bump_env_mat[m]);
    STAGE_FIELD(bump_env_lscale);
    STAGE_FIELD(bump_env_loffset);
    STAGE_FIELD(constant);
    STAGE_FIELD(texture);
  }
  FIELD(texture_factor);
  FIELD(vertex_shader);
  FIELD(pixel_shader);
  FIELD(pixel_shader_inputs.known);
  FIELD(pixel_shader_inputs.diffuse);
  FIELD(pixel_shader_inputs.specular);
  FIELD(pixel_shader_inputs.fog);
  field(out, "pixel_shader_inputs.texcoords", uint32_t{s.pixel_shader_inputs.texcoords},
        uint32_t{d.pixel_shader_inputs.texcoords});
  FIELD(vertex_shader_outputs.known);
  field(out, "vertex_shader_outputs.diffuse", uint32_t{s.vertex_shader_outputs.diffuse},
        uint32_t{d.vertex_shader_outputs.diffuse});
  field(out, "vertex_shader_outputs.specular", uint32_t{s.vertex_shader_outputs.specular},
        uint32_t{d.vertex_shader_outputs.specular});
  field(out, "vertex_shader_outputs.fog", uint32_t{s.vertex_shader_outputs.fog}, uint32_t{d.vertex_shader_outputs.fog});
  for (int t = 0; t < 8; ++t)
    field(out, "vertex_shader_outputs.texcoord" + std::to_string(t), uint32_t{s.vertex_shader_outputs.texcoords[t]},
          uint32_t{d.vertex_shader_outputs.texcoords[t]});
  FIELD(pretransformed);
  FIELD(vertex_diffuse);
  FIELD(vertex_specular);
  FIELD(vertex_normal);
  for (int t = 0; t < 8; ++t)
    field(out, "vertex_texcoord_size" + std::to_string(t), uint32_t{s.vertex_texcoord_size[t]},
          uint32_t{d.vertex_texcoord_size[t]});
  FIELD(world);
  FIELD(view);
  FIELD(projection);
  FIELD(lighting);
  for (int l = 0; l < kFixedLights; ++l) {
    const FixedLight &li = s.lights[l], &dl = d.lights[l];
    const std::string p = "light" + std::to_string(l) + ".";
    LIGHT_FIELD(enabled);
    LIGHT_FIELD(type);
    LIGHT_FIELD(diffuse);
    LIGHT_FIELD(specular);
    LIGHT_FIELD(ambient);
    LIGHT_FIELD(position);
    LIGHT_FIELD(direction);
    LIGHT_FIELD(range);
    LIGHT_FIELD(falloff);
    LIGHT_FIELD(attenuation0);
    LIGHT_FIELD(attenuation1);
    LIGHT_FIELD(attenuation2);
    LIGHT_FIELD(theta);
    LIGHT_FIELD(phi);
  }
  FIELD(material_diffuse);
  FIELD(material_ambient);
  FIELD(material_specular);
  FIELD(material_emissive);
  FIELD(material_power);
  FIELD(ambient);
  FIELD(specular_enable);
  FIELD(color_vertex);
  FIELD(local_viewer);
  FIELD(normalize_normals);
  FIELD(diffuse_source);
  FIELD(specular_source);
  FIELD(ambient_source);
  FIELD(emissive_source);
  FIELD(point_size);
  FIELD(point_size_written);
  FIELD(point_scale);
  FIELD(point_scale_a);
  FIELD(point_scale_b);
  FIELD(point_scale_c);
  FIELD(point_size_min);
  FIELD(point_size_max);
  FIELD(fog);
  FIELD(fog_table_mode);
  FIELD(fog_vertex_mode);
  FIELD(fog_start);
  FIELD(fog_end);
  FIELD(fog_density);
  FIELD(fog_color);
  FIELD(range_fog);
  FIELD(alpha_test);
  FIELD(alpha_func);
  FIELD(alpha_ref);
  return out;
}

#undef FIELD
#undef STAGE_FIELD
#undef LIGHT_FIELD

uint64_t fixed_function_key(const FixedFunctionState& state) {
  // FNV-1a 64 over the canonical description: stable across runs, builds and machines.
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : fixed_function_description(state)) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

}  // namespace fx
