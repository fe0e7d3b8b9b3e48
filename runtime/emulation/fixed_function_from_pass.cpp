// The fixed-function state of a pass: its D3D9 texture-stage, transform, light, material,
// fog, point and alpha-test states read from the resolved pass states over D3D's defaults,
// with values bound to parameters kept as parameter references.
#include <string>
#include <string_view>

#include "fx/ascii_case.h"
#include "fx/emulation/fixed_function.h"

namespace fx {
namespace {

class PassReader {
 public:
  PassReader(const EffectModel& model, DiagnosticSink& diags) : model_(model), diags_(diags) {}

  // The parameter a state reads at draw time; none for a static one (its value is fixed).
  ParameterRef ref(const ResolvedState& s) const {
    if (s.kind != StateValueKind::parameter || s.target >= model_.parameters.size()) return {};
    const Parameter& p = model_.parameters[s.target];
    if (!p.is_uniform()) return {};
    return {p.name, p.type.to_string()};
  }
  // The number a state carries; a parameter's default when it is bound.
  double number(const ResolvedState& s) const {
    if (s.kind == StateValueKind::parameter && s.target < model_.parameters.size()) {
      const auto& d = model_.parameters[s.target].default_value;
      return d && d->is_numeric() ? d->number() : 0.0;
    }
    if (s.kind == StateValueKind::floating) return s.floating;
    return static_cast<double>(s.integer);
  }
  FixedScalar scalar(const ResolvedState& s) const { return {static_cast<float>(number(s)), ref(s)}; }
  FixedVector vector(const ResolvedState& s) const { return {s.vector, ref(s)}; }
  FixedMatrix matrix(const ResolvedState& s) const {
    FixedMatrix m;
    m.parameter = ref(s);
    if (s.kind == StateValueKind::parameter && s.target < model_.parameters.size()) {
      const auto& d = model_.parameters[s.target].default_value;
      if (d && d->components.size() == 16)
        for (int i = 0; i < 16; ++i) m.value[i] = static_cast<float>(d->components[i]);
    }
    return m;
  }
  // A state that shapes the generated code: a parameter's default, with a warning that
  // later changes of the parameter do not reach the shader.
  int64_t structural(const ResolvedState& s) const {
    if (s.kind == StateValueKind::parameter && s.target < model_.parameters.size()) {
      diags_.warning("fixed-function-frozen", s.range,
                     std::string(1, '\'').append(s.info->name) + "' takes the default of '" +
                         model_.parameters[s.target].name +
                         "': the generated fixed-function shader does not follow later changes");
      return static_cast<int64_t>(number(s));
    }
    return s.kind == StateValueKind::floating ? static_cast<int64_t>(s.floating) : s.integer;
  }
  bool flag(const ResolvedState& s) const { return structural(s) != 0; }

  // The texture type a Texture[n] or Sampler[n] state names.
  StageTexture texture(const ResolvedState& s) const {
    if (s.kind != StateValueKind::parameter || s.target >= model_.parameters.size()) return StageTexture::none;
    const Type& t = model_.parameters[s.target].type;
    if (t.cls == TypeClass::sampler) {
      switch (t.sampler) {
        case SamplerShape::cube: return StageTexture::cube;
        case SamplerShape::s3d: return StageTexture::volume;
        default: break;
      }
      for (const SamplerInfo& si : model_.samplers)
        if (si.parameter == s.target && si.texture != kNoIndex) return shape(si.texture);
      return StageTexture::tex2d;
    }
    return shape(s.target);
  }

 private:
  StageTexture shape(uint32_t texture_parameter) const {
    const Type& t = model_.parameters[texture_parameter].type;
    if (t.texture == TextureShape::cube) return StageTexture::cube;
    if (t.texture == TextureShape::tex3d) return StageTexture::volume;
    if (const TextureInfo* info = model_.texture_of(texture_parameter)) {
      if (info->shape == TextureShape::cube) return StageTexture::cube;
      if (info->shape == TextureShape::tex3d) return StageTexture::volume;
    }
    return StageTexture::tex2d;
  }

  const EffectModel& model_;
  DiagnosticSink& diags_;
};

// Light states: LightDiffuse[n] ... by name, after the "Light" prefix.
void read_light(FixedLight& l, std::string_view name, const ResolvedState& s, const PassReader& r) {
  if (iequals(name, "Enable")) l.enabled = r.flag(s);
  else if (iequals(name, "Type")) l.type = static_cast<LightType>(r.structural(s));
  else if (iequals(name, "Diffuse")) l.diffuse = r.vector(s);
  else if (iequals(name, "Specular")) l.specular = r.vector(s);
  else if (iequals(name, "Ambient")) l.ambient = r.vector(s);
  else if (iequals(name, "Position")) l.position = r.vector(s);
  else if (iequals(name, "Direction")) l.direction = r.vector(s);
  else if (iequals(name, "Range")) l.range = r.scalar(s);
  else if (iequals(name, "Falloff")) l.falloff = r.scalar(s);
  else if (iequals(name, "Attenuation0")) l.attenuation0 = r.scalar(s);
  else if (iequals(name, "Attenuation1")) l.attenuation1 = r.scalar(s);
  else if (iequals(name, "Attenuation2")) l.attenuation2 = r.scalar(s);
  else if (iequals(name, "Theta")) l.theta = r.scalar(s);
  else if (iequals(name, "Phi")) l.phi = r.scalar(s);
}

// Texture-stage states.
bool read_stage(TextureStageState& st, std::string_view n, const ResolvedState& s, const PassReader& r) {
  const auto arg = [&] { return static_cast<uint32_t>(r.structural(s)); };
  if (iequals(n, "ColorOp")) st.color_op = static_cast<TextureOp>(r.structural(s));
  else if (iequals(n, "AlphaOp")) st.alpha_op = static_cast<TextureOp>(r.structural(s));
  else if (iequals(n, "ColorArg0")) st.color_arg[0] = arg();
  else if (iequals(n, "ColorArg1")) st.color_arg[1] = arg();
  else if (iequals(n, "ColorArg2")) st.color_arg[2] = arg();
  else if (iequals(n, "AlphaArg0")) st.alpha_arg[0] = arg();
  else if (iequals(n, "AlphaArg1")) st.alpha_arg[1] = arg();
  else if (iequals(n, "AlphaArg2")) st.alpha_arg[2] = arg();
  else if (iequals(n, "ResultArg")) st.result_arg = arg();
  else if (iequals(n, "TexCoordIndex")) st.tex_coord_index = arg();
  else if (iequals(n, "TextureTransformFlags")) st.texture_transform_flags = arg();
  else if (iequals(n, "BumpEnvMat00")) st.bump_env_mat[0] = r.scalar(s);
  else if (iequals(n, "BumpEnvMat01")) st.bump_env_mat[1] = r.scalar(s);
  else if (iequals(n, "BumpEnvMat10")) st.bump_env_mat[2] = r.scalar(s);
  else if (iequals(n, "BumpEnvMat11")) st.bump_env_mat[3] = r.scalar(s);
  else if (iequals(n, "BumpEnvLScale")) st.bump_env_lscale = r.scalar(s);
  else if (iequals(n, "BumpEnvLOffset")) st.bump_env_loffset = r.scalar(s);
  else if (iequals(n, "Constant")) st.constant = r.vector(s);
  else if (iequals(n, "TextureTransform")) st.texture_transform = r.matrix(s);
  else if (iequals(n, "Texture") || iequals(n, "Sampler")) st.texture = r.texture(s);
  else return false;
  return true;
}

// Point states: PointSize, PointSize_Min/Max, PointScaleEnable, PointScale_A/B/C.
bool read_point(FixedFunctionState& out, std::string_view n, const ResolvedState& s, const PassReader& r) {
  if (iequals(n, "PointSize")) out.point_size = r.scalar(s);
  else if (iequals(n, "PointSize_Min")) out.point_size_min = r.scalar(s);
  else if (iequals(n, "PointSize_Max")) out.point_size_max = r.scalar(s);
  else if (iequals(n, "PointScaleEnable")) out.point_scale = r.flag(s);
  else if (iequals(n, "PointScale_A")) out.point_scale_a = r.scalar(s);
  else if (iequals(n, "PointScale_B")) out.point_scale_b = r.scalar(s);
  else if (iequals(n, "PointScale_C")) out.point_scale_c = r.scalar(s);
  else return false;
  return true;
}

MaterialSource source(int64_t v) {
  return v >= 0 && v <= 2 ? static_cast<MaterialSource>(v) : MaterialSource::material;
}
FogMode fog_mode(int64_t v) { return v >= 0 && v <= 3 ? static_cast<FogMode>(v) : FogMode::none; }

}  // namespace

FixedFunctionState fixed_function_state(const EffectModel& model, const PassInfo& pass, DiagnosticSink& diags) {
  FixedFunctionState out;
  const PassReader r(model, diags);
  const ShaderBinding* vs = pass.shader(PassStage::vertex);
  out.vertex_shader = vs && vs->source != ShaderSource::null;
  const ShaderBinding* ps = pass.shader(PassStage::pixel);
  out.pixel_shader = ps && ps->source != ShaderSource::null;
  out.alpha_test = pass.summary.alpha_test;
  out.alpha_func = pass.summary.alpha_compare;
  out.alpha_ref.value = static_cast<float>(pass.summary.alpha_ref);
  for (const ResolvedState& s : pass.states) {
    if (!s.info || s.kind == StateValueKind::invalid || s.info->block != StateBlock::pass) continue;
    const std::string_view n = s.info->name;
    if (s.index < kTextureStages && read_stage(out.stages[s.index], n, s, r)) continue;
    if (n.size() > 5 && iequals(n.substr(0, 5), "Light") && !iequals(n, "Lighting")) {
      if (s.index < kFixedLights) read_light(out.lights[s.index], n.substr(5), s, r);
      continue;
    }
    if (iequals(n, "TextureFactor")) out.texture_factor = r.vector(s);
    else if (iequals(n, "WorldTransform") && s.index == 0) out.world = r.matrix(s);
    else if (iequals(n, "ViewTransform")) out.view = r.matrix(s);
    else if (iequals(n, "ProjectionTransform")) out.projection = r.matrix(s);
    else if (iequals(n, "Lighting")) out.lighting = r.flag(s);
    else if (iequals(n, "MaterialDiffuse")) out.material_diffuse = r.vector(s);
    else if (iequals(n, "MaterialAmbient")) out.material_ambient = r.vector(s);
    else if (iequals(n, "MaterialSpecular")) out.material_specular = r.vector(s);
    else if (iequals(n, "MaterialEmissive")) out.material_emissive = r.vector(s);
    else if (iequals(n, "MaterialPower")) out.material_power = r.scalar(s);
    else if (iequals(n, "Ambient")) out.ambient = r.vector(s);
    else if (iequals(n, "SpecularEnable")) out.specular_enable = r.flag(s);
    else if (iequals(n, "ColorVertex")) out.color_vertex = r.flag(s);
    else if (iequals(n, "LocalViewer")) out.local_viewer = r.flag(s);
    else if (iequals(n, "NormalizeNormals")) out.normalize_normals = r.flag(s);
    else if (iequals(n, "DiffuseMaterialSource")) out.diffuse_source = source(r.structural(s));
    else if (iequals(n, "SpecularMaterialSource")) out.specular_source = source(r.structural(s));
    else if (iequals(n, "AmbientMaterialSource")) out.ambient_source = source(r.structural(s));
    else if (iequals(n, "EmissiveMaterialSource")) out.emissive_source = source(r.structural(s));
    else if (read_point(out, n, s, r)) out.point_size_written = true;
    else if (iequals(n, "FogEnable")) out.fog = r.flag(s);
    else if (iequals(n, "FogColor")) out.fog_color = r.vector(s);
    else if (iequals(n, "FogTableMode")) out.fog_table_mode = fog_mode(r.structural(s));
    else if (iequals(n, "FogVertexMode")) out.fog_vertex_mode = fog_mode(r.structural(s));
    else if (iequals(n, "FogStart")) out.fog_start = r.scalar(s);
    else if (iequals(n, "FogEnd")) out.fog_end = r.scalar(s);
    else if (iequals(n, "FogDensity")) out.fog_density = r.scalar(s);
    else if (iequals(n, "RangeFogEnable")) out.range_fog = r.flag(s);
    else if (iequals(n, "AlphaRef")) out.alpha_ref = r.scalar(s);
  }
  return out;
}

}  // namespace fx
