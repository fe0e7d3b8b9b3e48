// The fixed-function vertex shader: world/view/projection transform or pre-transformed
// (XYZRHW) positions, fixed-function lighting (directional, point and spot lights,
// material colour sources, ambient, specular), texture-coordinate generation and texture
// transforms, vertex fog and point size, generated as HLSL (entry fx_ff_vs).
#include <string>

#include "fixed_function_hlsl.h"
#include "fixed_function_stages.h"
#include "fx/emulation/fixed_function.h"

namespace fx {
namespace {

using ff_detail::Declarations;
using ff_detail::literal;

class VertexShaderWriter {
 public:
  explicit VertexShaderWriter(const FixedFunctionState& s) : s_(s) {}

  FixedFunctionShader write() {
    std::string in = s_.pretransformed ? "  float4 fx_position : POSITION;\n" : "  float3 fx_position : POSITION;\n";
    const bool lit = s_.lighting && !s_.pretransformed;
    const bool need_normal = s_.vertex_normal && !s_.pretransformed && (lit || uses_texgen(true));
    if (need_normal) in += "  float3 fx_normal : NORMAL;\n";
    if (s_.vertex_diffuse) in += "  float4 fx_diffuse : COLOR0;\n";
    if (s_.vertex_specular) in += "  float4 fx_specular : COLOR1;\n";

    body_ += "  fx_ff_vs_out fx_o;\n";
    if (s_.pretransformed) {
      decl_.uniform("float4", "fx_ff_screen_to_clip");
      // D3D's rhw is 1/w: multiplying back by w keeps the interpolation perspective-correct.
      body_ += "  float fx_w = 1.0 / i.fx_position.w;\n";
      body_ +=
          "  fx_o.fx_position = float4(i.fx_position.xy * fx_ff_screen_to_clip.xy + fx_ff_screen_to_clip.zw, "
          "i.fx_position.z, 1.0) * fx_w;\n";
    } else {
      body_ += "  float4x4 fx_world_view = mul(" + decl_.matrix(s_.world) + ", " + decl_.matrix(s_.view) + ");\n";
      body_ += "  float4 fx_view_position = mul(float4(i.fx_position, 1.0), fx_world_view);\n";
      body_ += "  fx_o.fx_position = mul(fx_view_position, " + decl_.matrix(s_.projection) + ");\n";
      if (need_normal) normal();
      else body_ += "  float3 fx_normal = float3(0.0, 0.0, 0.0);\n";
    }
    body_ += "  float4 fx_vertex_diffuse = " +
             std::string(s_.vertex_diffuse ? "i.fx_diffuse" : "float4(1.0, 1.0, 1.0, 1.0)") + ";\n";
    body_ += "  float4 fx_vertex_specular = " +
             std::string(s_.vertex_specular ? "i.fx_specular" : "float4(0.0, 0.0, 0.0, 0.0)") + ";\n";
    if (lit) lighting();
    else body_ += "  float4 fx_diffuse = fx_vertex_diffuse;\n  float4 fx_specular = fx_vertex_specular;\n";
    const FixedFunctionState::PixelShaderInputs& ps = s_.pixel_shader_inputs;
    const bool exact = s_.pixel_shader && ps.known;  // write exactly what the pixel shader reads
    // Outputs a pixel shader does not read are left out (Vulkan warns about them).
    std::string out = "  float4 fx_position : POSITION;\n";
    if (!exact || ps.diffuse) {
      out += "  float4 fx_diffuse : COLOR0;\n";
      body_ += "  fx_o.fx_diffuse = fx_diffuse;\n";
    }
    if (!exact || ps.specular) {
      out += "  float4 fx_specular : COLOR1;\n";
      body_ += "  fx_o.fx_specular = fx_specular;\n";
    }
    for (int i = 0; i < kTextureStages; ++i)
      if (exact ? (ps.texcoords >> i) & 1 : i < ff_detail::active_stages(s_) && ff_detail::samples(s_, i)) {
        texcoord(i, in);
        out += "  float4 fx_tc" + std::to_string(i) + " : TEXCOORD" + std::to_string(i) + ";\n";
      }
    if (exact ? ps.fog : s_.fog && s_.fog_table_mode == FogMode::none) {
      fog();
      out += "  float fx_fog : FOG;\n";
    }
    if (s_.point_size_written) {
      std::string size = decl_.scalar(s_.point_size);
      if (s_.point_scale && !s_.pretransformed) {
        decl_.uniform("float4", "fx_ff_screen_to_clip");
        body_ += "  float fx_eye_distance = length(fx_view_position.xyz);\n";
        size = "2.0 / abs(fx_ff_screen_to_clip.y) * " + size + " * sqrt(1.0 / (" + decl_.scalar(s_.point_scale_a) +
               " + " + decl_.scalar(s_.point_scale_b) + " * fx_eye_distance + " + decl_.scalar(s_.point_scale_c) +
               " * fx_eye_distance * fx_eye_distance))";
      }
      body_ += "  fx_o.fx_point_size = clamp(" + size + ", " + decl_.scalar(s_.point_size_min) + ", " +
               decl_.scalar(s_.point_size_max) + ");\n";
      out += "  float fx_point_size : PSIZE;\n";
    }
    body_ += "  return fx_o;\n";

    FixedFunctionShader result;
    result.entry = "fx_ff_vs";
    result.profile = "vs_3_0";
    result.source = "// fxkit fixed-function vertex shader (generated)\n" + decl_.text() + "struct fx_ff_vs_in {\n" +
                    in + "};\nstruct fx_ff_vs_out {\n" + out + "};\nfx_ff_vs_out fx_ff_vs(fx_ff_vs_in i) {\n" + body_ +
                    "}\n";
    return result;
  }

 private:
  // Whether a sampling stage generates coordinates (from the normal when `normal_only`).
  bool uses_texgen(bool normal_only) const {
    for (int i = 0; i < ff_detail::active_stages(s_); ++i) {
      const uint32_t gen = s_.stages[i].tex_coord_index & 0xFFFF0000u;
      if (!ff_detail::samples(s_, i) || gen == texcoord_gen::passthru) continue;
      if (!normal_only || gen != texcoord_gen::camera_space_position) return true;
    }
    return false;
  }

  // The camera-space normal: the inverse transpose of world*view's 3x3 (cofactors / det).
  void normal() {
    body_ += "  float3x3 fx_wv = (float3x3)fx_world_view;\n";
    body_ +=
        "  float3x3 fx_cofactors = float3x3(cross(fx_wv[1], fx_wv[2]), cross(fx_wv[2], fx_wv[0]), cross(fx_wv[0], "
        "fx_wv[1]));\n";
    body_ += "  float3 fx_normal = mul(i.fx_normal, fx_cofactors) / dot(fx_wv[0], fx_cofactors[0]);\n";
    if (s_.normalize_normals) body_ += "  fx_normal = normalize(fx_normal);\n";
  }

  // A material colour from its source: the vertex colour when ColorVertex is on and the
  // vertex has it, the material's otherwise.
  std::string material(MaterialSource source, const FixedVector& m) {
    if (s_.color_vertex && source == MaterialSource::color1 && s_.vertex_diffuse) return "fx_vertex_diffuse";
    if (s_.color_vertex && source == MaterialSource::color2 && s_.vertex_specular) return "fx_vertex_specular";
    return decl_.vector(m);
  }

  void lighting() {
    body_ += "  float4 fx_material_diffuse = " + material(s_.diffuse_source, s_.material_diffuse) + ";\n";
    body_ += "  float4 fx_material_ambient = " + material(s_.ambient_source, s_.material_ambient) + ";\n";
    body_ += "  float4 fx_material_specular = " + material(s_.specular_source, s_.material_specular) + ";\n";
    body_ += "  float4 fx_material_emissive = " + material(s_.emissive_source, s_.material_emissive) + ";\n";
    body_ += "  float3 fx_ambient_sum = " + decl_.vector(s_.ambient) + ".rgb;\n";
    body_ += "  float3 fx_diffuse_sum = float3(0.0, 0.0, 0.0);\n  float3 fx_specular_sum = float3(0.0, 0.0, 0.0);\n";
    body_ += "  float3 fx_to_eye = " +
             std::string(s_.local_viewer ? "normalize(-fx_view_position.xyz)" : "float3(0.0, 0.0, -1.0)") + ";\n";
    const std::string view = decl_.matrix(s_.view);
    for (int l = 0; l < kFixedLights; ++l) {
      const FixedLight& light = s_.lights[l];
      if (!light.enabled) continue;
      body_ += "  {  // light " + std::to_string(l) + "\n";
      if (light.type == LightType::directional) {
        body_ += "    float3 fx_to_light = normalize(-mul(" + decl_.vector(light.direction, {0, 0, 0, 0}) +
                 ".xyz, (float3x3)" + view + "));\n";
        body_ += "    float fx_attenuation = 1.0;\n";
      } else {
        body_ += "    float3 fx_light_position = mul(float4(" + decl_.vector(light.position) + ".xyz, 1.0), " + view +
                 ").xyz;\n";
        body_ += "    float3 fx_offset = fx_light_position - fx_view_position.xyz;\n";
        body_ += "    float fx_d = length(fx_offset);\n";
        body_ += "    float3 fx_to_light = fx_offset / max(fx_d, 1e-30);\n";
        body_ += "    float fx_attenuation = fx_d <= " + decl_.scalar(light.range) + " ? 1.0 / (" +
                 decl_.scalar(light.attenuation0) + " + " + decl_.scalar(light.attenuation1) + " * fx_d + " +
                 decl_.scalar(light.attenuation2) + " * fx_d * fx_d) : 0.0;\n";
        if (light.type == LightType::spot) {
          body_ += "    float3 fx_spot_direction = normalize(mul(" + decl_.vector(light.direction, {0, 0, 0, 0}) +
                   ".xyz, (float3x3)" + view + "));\n";
          body_ += "    float fx_rho = dot(-fx_to_light, fx_spot_direction);\n";
          body_ += "    float fx_cos_theta = cos(" + decl_.scalar(light.theta) + " * 0.5);\n";
          body_ += "    float fx_cos_phi = cos(" + decl_.scalar(light.phi) + " * 0.5);\n";
          body_ +=
              "    float fx_spot = fx_rho > fx_cos_theta ? 1.0 : fx_rho <= fx_cos_phi ? 0.0 : pow(saturate((fx_rho - "
              "fx_cos_phi) / "
              "(fx_cos_theta - fx_cos_phi)), " +
              decl_.scalar(light.falloff) + ");\n";
          body_ += "    fx_attenuation *= fx_spot;\n";
        }
      }
      body_ += "    float fx_n_dot_l = dot(fx_normal, fx_to_light);\n";
      body_ += "    fx_ambient_sum += fx_attenuation * " + decl_.vector(light.ambient) + ".rgb;\n";
      body_ +=
          "    fx_diffuse_sum += fx_attenuation * max(fx_n_dot_l, 0.0) * " + decl_.vector(light.diffuse) + ".rgb;\n";
      if (s_.specular_enable) {
        body_ += "    float3 fx_halfway = normalize(fx_to_eye + fx_to_light);\n";
        body_ += "    float fx_n_dot_h = max(dot(fx_normal, fx_halfway), 0.0);\n";
        body_ += "    if (fx_n_dot_l > 0.0) fx_specular_sum += fx_attenuation * pow(fx_n_dot_h, " +
                 decl_.scalar(s_.material_power) + ") * " + decl_.vector(light.specular) + ".rgb;\n";
      }
      body_ += "  }\n";
    }
    body_ +=
        "  float4 fx_diffuse = saturate(float4(fx_material_emissive.rgb + fx_material_ambient.rgb * fx_ambient_sum + "
        "fx_material_diffuse.rgb * fx_diffuse_sum, fx_material_diffuse.a));\n";
    body_ +=
        "  float4 fx_specular = saturate(float4(fx_material_specular.rgb * fx_specular_sum, fx_vertex_specular.a));\n";
  }

  // Stage `i`'s texture coordinates: TEXCOORD<index> or generated, then transformed.
  void texcoord(int i, std::string& in) {
    const TextureStageState& st = s_.stages[i];
    const std::string n = std::to_string(i);
    const uint32_t gen = st.tex_coord_index & 0xFFFF0000u;
    std::string tc;
    if (gen == texcoord_gen::passthru || s_.pretransformed) {
      const uint32_t set = st.tex_coord_index & 0x7;
      const int size = s_.vertex_texcoord_size[set] ? s_.vertex_texcoord_size[set] : 2;
      const std::string name = "fx_texcoord" + std::to_string(set);
      const std::string decl = "  float" + (size > 1 ? std::to_string(size) : std::string()) + " " + name +
                               " : TEXCOORD" + std::to_string(set) + ";\n";
      if (in.find(decl) == std::string::npos) in += decl;
      // D3D extends a coordinate with 1 in its first missing component and 0 after it.
      static const char* pad[] = {"", ", 1.0, 0.0, 0.0)", ", 1.0, 0.0)", ", 1.0)", ")"};
      tc = "float4(i." + name + pad[size];
    } else if (gen == texcoord_gen::camera_space_normal) {
      tc = "float4(fx_normal, 1.0)";
    } else if (gen == texcoord_gen::camera_space_position) {
      tc = "float4(fx_view_position.xyz, 1.0)";
    } else {
      const std::string reflection =
          "reflect(" + std::string(s_.local_viewer ? "normalize(fx_view_position.xyz)" : "float3(0.0, 0.0, 1.0)") +
          ", fx_normal)";
      if (gen == texcoord_gen::camera_space_reflection_vector) {
        tc = "float4(" + reflection + ", 1.0)";
      } else {  // sphere map
        body_ += "  float3 fx_sphere_r" + n + " = " + reflection + ";\n";
        body_ += "  float fx_sphere_m" + n + " = 2.0 * sqrt(fx_sphere_r" + n + ".x * fx_sphere_r" + n +
                 ".x + fx_sphere_r" + n + ".y * fx_sphere_r" + n + ".y + (fx_sphere_r" + n +
                 ".z + 1.0) * (fx_sphere_r" + n + ".z + 1.0));\n";
        tc = "float4(fx_sphere_r" + n + ".xy / fx_sphere_m" + n + " + 0.5, 1.0, 1.0)";
      }
    }
    if ((st.texture_transform_flags & texture_transform::count_mask) != 0 && !s_.pretransformed)
      tc = "mul(" + tc + ", " + decl_.matrix(st.texture_transform) + ")";
    body_ += "  fx_o.fx_tc" + n + " = " + tc + ";\n";
  }

  void fog() {
    if (s_.pretransformed || s_.fog_vertex_mode == FogMode::none) {
      body_ += "  fx_o.fx_fog = fx_specular.a;\n";
      return;
    }
    body_ += "  float fx_fog_distance = " +
             std::string(s_.range_fog ? "length(fx_view_position.xyz)" : "abs(fx_view_position.z)") + ";\n";
    const std::string start = decl_.scalar(s_.fog_start), end = decl_.scalar(s_.fog_end),
                      density = decl_.scalar(s_.fog_density);
    std::string f;
    switch (s_.fog_vertex_mode) {
      case FogMode::linear: f = "(" + end + " - fx_fog_distance) / (" + end + " - " + start + ")"; break;
      case FogMode::exp: f = "exp(-" + density + " * fx_fog_distance)"; break;
      default: f = "exp(-(" + density + " * fx_fog_distance) * (" + density + " * fx_fog_distance))"; break;
    }
    body_ += "  fx_o.fx_fog = saturate(" + f + ");\n";
  }

  const FixedFunctionState& s_;
  Declarations decl_;
  std::string body_;
};

}  // namespace

FixedFunctionShader generate_fixed_function_vertex_shader(const FixedFunctionState& state) {
  return VertexShaderWriter(state).write();
}

}  // namespace fx
