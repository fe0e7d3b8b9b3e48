// Every generated fixed-function shader compiles and validates: a sweep of every texture
// operation with every argument register and modifier, every vertex-processing path
// (lights, material sources, texgen, texture transforms, fog modes, XYZRHW, point size),
// and each generated vertex shader links with its pixel shader by semantic.
#include <gtest/gtest.h>

#include "fixed_function_rig.h"

namespace fx {
namespace {

using vk::testing::unit;

// Compiles both stages (SPIR-V validated by ShaderCompiler) and links them; "" when fine.
std::string build(const FixedFunctionState& s) {
  static const ShaderCompiler compiler;  // validate = true: SPIRV-Tools' validator runs on each
  const FixedFunctionShader vs_text = generate_fixed_function_vertex_shader(s);
  const FixedFunctionShader ps_text = generate_fixed_function_pixel_shader(s);
  CompiledShader vs = compiler.compile(unit(vs_text, ShaderStage::vertex));
  CompiledShader ps = compiler.compile(unit(ps_text, ShaderStage::fragment));
  if (!vs.ok) return vs.info_log + "\n" + vs_text.source;
  if (!ps.ok) return ps.info_log + "\n" + ps_text.source;
  DiagnosticSink sink;
  link_program({&vs, &ps}, sink);
  if (sink.has_errors() || sink.warning_count()) {
    std::string out;
    for (const Diagnostic& d : sink.diagnostics()) out += d.message + "\n";
    return out + vs_text.source + ps_text.source;
  }
  return "";
}

TEST(FixedFunctionCompile, EveryOperationWithEveryRegisterAndModifier) {
  int built = 0;
  for (int op = kTextureOpFirst; op <= kTextureOpLast; ++op)
    for (uint32_t reg = 0; reg <= texture_arg::constant; ++reg) {
      const uint32_t mods[] = {0, texture_arg::complement, texture_arg::alpha_replicate,
                               texture_arg::complement | texture_arg::alpha_replicate};
      const uint32_t m = mods[reg % 4];
      FixedFunctionState s;
      for (int i = 0; i < 3; ++i) {
        TextureStageState& st = s.stages[i];
        st.texture = i == 1 ? StageTexture::cube : StageTexture::tex2d;
        st.color_op = static_cast<TextureOp>(i == 1 ? op : (op % 7) + 2);
        st.alpha_op = static_cast<TextureOp>(i == 1 ? (kTextureOpLast + kTextureOpFirst - op) : 4);
        st.color_arg = {((reg + 5) % 7) | m, reg | m, ((reg + 3) % 7)};
        st.alpha_arg = {reg, ((reg + 1) % 7) | m, ((reg + 2) % 7) | m};
      }
      s.stages[0].result_arg = texture_arg::temp;
      ASSERT_EQ(build(s), "") << "op " << to_string(static_cast<TextureOp>(op)) << " register " << reg;
      ++built;
    }
  EXPECT_EQ(built, 26 * 7);
}

TEST(FixedFunctionCompile, EveryVertexProcessingPath) {
  int built = 0;
  for (int light_type = 1; light_type <= 3; ++light_type)
    for (int variant = 0; variant < 8; ++variant) {
      FixedFunctionState s;
      s.lighting = true;
      s.specular_enable = variant & 1;
      s.local_viewer = variant & 2;
      s.normalize_normals = variant & 4;
      s.diffuse_source = static_cast<MaterialSource>(variant % 3);
      s.specular_source = static_cast<MaterialSource>((variant + 1) % 3);
      s.ambient_source = static_cast<MaterialSource>((variant + 2) % 3);
      s.vertex_specular = variant != 3;
      s.vertex_diffuse = variant != 5;
      s.lights[variant % kFixedLights].enabled = true;
      s.lights[variant % kFixedLights].type = static_cast<LightType>(light_type);
      s.lights[(variant + 3) % kFixedLights].enabled = true;
      s.stages[0].texture = StageTexture::tex2d;
      s.stages[0].tex_coord_index = static_cast<uint32_t>(variant % 5) << 16;
      s.stages[0].texture_transform_flags = variant < 4 ? 2u : (3u | texture_transform::projected);
      s.fog = variant != 0;
      s.fog_vertex_mode = static_cast<FogMode>(variant % 4);
      s.fog_table_mode = variant == 7 ? FogMode::exp2 : FogMode::none;
      s.range_fog = variant & 1;
      s.point_size_written = variant >= 6;
      s.point_scale = variant == 7;
      s.point_scale_b.value = 0.5f;
      ASSERT_EQ(build(s), "") << "light type " << light_type << " variant " << variant;
      ++built;
    }
  for (bool pretransformed : {false, true}) {
    FixedFunctionState s;
    s.pretransformed = pretransformed;
    s.lighting = false;
    s.stages[0].texture = StageTexture::volume;
    s.vertex_texcoord_size[0] = 3;
    s.fog = true;
    ASSERT_EQ(build(s), "") << "pretransformed " << pretransformed;
    ++built;
  }
  EXPECT_EQ(built, 26);
}

TEST(FixedFunctionCompile, ParameterBoundValuesAreDeclaredWithTheParameterNames) {
  FixedFunctionState s;
  s.texture_factor.parameter = {"Tint", "float4"};
  s.stages[0].color_arg[2] = texture_arg::tfactor;
  s.stages[0].texture = StageTexture::tex2d;
  s.world.parameter = {"mWorld", "float4x4"};
  s.lights[0].enabled = true;
  s.lights[0].direction.parameter = {"LightDirection", "float3"};
  s.material_diffuse.parameter = {"Albedo", "float3"};
  s.diffuse_source = MaterialSource::material;
  s.alpha_test = true;
  s.alpha_func = CompareOp::greater;
  s.alpha_ref.parameter = {"Cutoff", "int"};
  s.fog = true;
  s.fog_color.parameter = {"FogColour", "uint"};
  s.lights[0].diffuse.parameter = {"Lights", "float4[4]"};  // an array: its resolved value, as a literal
  s.lights[0].diffuse.value = {0.5f, 0.25f, 0.125f, 1};
  const std::string ps = generate_fixed_function_pixel_shader(s).source;
  const std::string vs = generate_fixed_function_vertex_shader(s).source;
  EXPECT_NE(ps.find("float4 Tint;"), std::string::npos) << ps;
  EXPECT_NE(ps.find("int Cutoff;"), std::string::npos) << ps;
  EXPECT_NE(ps.find("uint FogColour;"), std::string::npos) << ps;
  EXPECT_NE(vs.find("float4x4 mWorld;"), std::string::npos) << vs;
  EXPECT_NE(vs.find("float3 LightDirection;"), std::string::npos) << vs;
  EXPECT_NE(vs.find("float3 Albedo;"), std::string::npos) << vs;
  EXPECT_EQ(vs.find("Lights"), std::string::npos) << vs;
  EXPECT_NE(vs.find("float4(0.5, 0.25, 0.125, 1.0)"), std::string::npos) << vs;
  EXPECT_EQ(build(s), "");
}

TEST(FixedFunctionCompile, KeyFollowsEveryFieldAndOnlyThem) {
  const FixedFunctionState base;
  EXPECT_EQ(fixed_function_key(base), fixed_function_key(FixedFunctionState{}));
  EXPECT_EQ(fixed_function_description(base), "");
  FixedFunctionState a = base, b = base, c = base;
  a.stages[3].color_arg[1] = texture_arg::tfactor;
  b.texture_factor.parameter = {"tf", "float4"};
  c.lights[2].phi.value = 0.5f;
  const uint64_t keys[] = {fixed_function_key(base), fixed_function_key(a), fixed_function_key(b),
                           fixed_function_key(c)};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) EXPECT_NE(keys[i], keys[j]) << i << " " << j;
  EXPECT_EQ(fixed_function_description(a), "stage3.color_arg1=3\n");
}

}  // namespace
}  // namespace fx
