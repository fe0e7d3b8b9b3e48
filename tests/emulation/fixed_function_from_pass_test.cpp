// The fixed-function state read from a pass: the seed effects' DOTPRODUCT3, emboss and
// specular-emboss passes, and values bound to parameters kept as parameter references.
#include <gtest/gtest.h>

#include <filesystem>

#include "../model/model_test_util.h"
#include "fixed_function_rig.h"

namespace fx {
namespace {

namespace ta = texture_arg;

struct LoadedEffect {
  SourceManager sm;
  DiagnosticSink diags;
  ParsedEffect parsed;
  EffectModel model;
};

std::unique_ptr<LoadedEffect> load(const std::string& file) {
  auto e = std::make_unique<LoadedEffect>();
  FrontEndOptions options;
  options.preprocessor.include_dirs = {std::string(FXKIT_SOURCE_DIR) + "/effects"};
  e->parsed = parse_effect_file(std::string(FXKIT_SOURCE_DIR) + "/effects/" + file, e->sm, e->diags, options);
  e->model = build_effect_model(e->parsed, e->sm, e->diags);
  return e;
}

const PassInfo& pass_of(const EffectModel& m, std::string_view technique, size_t index = 0) {
  const TechniqueInfo* t = m.find_technique(technique);
  EXPECT_TRUE(t && index < t->passes.size()) << technique;
  static const PassInfo none;
  return t && index < t->passes.size() ? t->passes[index] : none;
}

// Compiles the generated pixel shader; "" when it compiles.
std::string compile_pixel_shader(const FixedFunctionState& s) {
  CompiledShader ps =
      ShaderCompiler().compile(vk::testing::unit(generate_fixed_function_pixel_shader(s), ShaderStage::fragment));
  return ps.ok ? "" : ps.info_log;
}

TEST(FixedFunctionFromPass, SeedDot3EmbossAndSpecularEmbossPasses) {
  auto e = load("per_pixel_lighting.fx");
  ASSERT_FALSE(e->diags.has_errors());
  DiagnosticSink diags;
  const FixedFunctionState dot3 = fixed_function_state(e->model, pass_of(e->model, "dot3_multitexture"), diags);
  EXPECT_TRUE(dot3.vertex_shader);  // the pass's vs.1.1 writes the interpolants
  EXPECT_EQ(dot3.stages[0].color_op, TextureOp::dot_product3);
  EXPECT_EQ(dot3.stages[0].color_arg[1], ta::texture);
  EXPECT_EQ(dot3.stages[0].color_arg[2], ta::diffuse);
  EXPECT_EQ(dot3.stages[1].color_op, TextureOp::modulate);
  EXPECT_EQ(dot3.stages[1].color_arg[2], ta::current);
  EXPECT_EQ(dot3.stages[2].color_op, TextureOp::disable);
  EXPECT_EQ(dot3.stages[1].tex_coord_index, 0u);
  EXPECT_EQ(dot3.stages[0].texture, StageTexture::tex2d);
  EXPECT_EQ(dot3.stages[1].texture, StageTexture::tex2d);
  const std::string ps = generate_fixed_function_pixel_shader(dot3).source;
  // TexCoordIndex[1] = 0 with a vertex shader: both stages read the shader's oT0.
  EXPECT_NE(ps.find("TEXCOORD0"), std::string::npos) << ps;
  EXPECT_EQ(ps.find("TEXCOORD1"), std::string::npos) << ps;
  EXPECT_EQ(compile_pixel_shader(dot3), "");

  const FixedFunctionState emboss = fixed_function_state(e->model, pass_of(e->model, "emboss"), diags);
  EXPECT_EQ(emboss.stages[0].color_op, TextureOp::select_arg1);
  EXPECT_EQ(emboss.stages[1].color_op, TextureOp::add_signed);
  EXPECT_EQ(emboss.stages[1].color_arg[1], ta::texture | ta::complement);
  EXPECT_EQ(emboss.stages[1].tex_coord_index, 1u);
  EXPECT_EQ(compile_pixel_shader(emboss), "");

  // Specular emboss: the emboss pass, then a highlight pass that subtracts.
  EXPECT_EQ(fixed_function_state(e->model, pass_of(e->model, "specular_emboss"), diags).stages[1].color_op,
            TextureOp::add_signed);
  const FixedFunctionState specular = fixed_function_state(e->model, pass_of(e->model, "specular_emboss", 1), diags);
  EXPECT_EQ(specular.stages[1].color_op, TextureOp::subtract);
  EXPECT_EQ(compile_pixel_shader(specular), "");
  EXPECT_FALSE(diags.has_errors());
  // Three different passes, three different keys; the same pass read twice, the same key.
  EXPECT_NE(fixed_function_key(dot3), fixed_function_key(emboss));
  EXPECT_NE(fixed_function_key(emboss), fixed_function_key(specular));
  EXPECT_EQ(fixed_function_key(dot3),
            fixed_function_key(fixed_function_state(e->model, pass_of(e->model, "dot3_multitexture"), diags)));
}

TEST(FixedFunctionFromPass, EveryD3D9PassOfTheSeedEffectsGivesStagesThatCompile) {
  // Both generated stages of every D3D9 pass, whether or not the pass has its own shaders.
  int passes = 0;
  const ShaderCompiler compiler;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(FXKIT_SOURCE_DIR) + "/effects")) {
    if (entry.path().extension() != ".fx") continue;
    auto e = load(entry.path().filename().string());
    ASSERT_FALSE(e->diags.has_errors()) << entry.path();
    for (const TechniqueInfo& t : e->model.techniques) {
      if (t.version != 9) continue;
      for (const PassInfo& p : t.passes) {
        DiagnosticSink diags;
        const FixedFunctionState s = fixed_function_state(e->model, p, diags);
        EXPECT_FALSE(diags.has_errors());
        const CompiledShader vs =
            compiler.compile(vk::testing::unit(generate_fixed_function_vertex_shader(s), ShaderStage::vertex));
        const CompiledShader ps =
            compiler.compile(vk::testing::unit(generate_fixed_function_pixel_shader(s), ShaderStage::fragment));
        EXPECT_TRUE(vs.ok && ps.ok) << entry.path().filename() << " " << t.name << "/" << p.name << "\n"
                                    << vs.info_log << ps.info_log;
        ++passes;
      }
    }
  }
  std::printf("[ fixed-function ] %d D3D9 passes of effects/: both generated stages compile\n", passes);
  EXPECT_GE(passes, 20);
}

TEST(FixedFunctionFromPass, ParameterBoundValuesStayParameterReferences) {
  auto b = test::build(R"(
float4 Tint = {1, 0.5, 0.25, 1};
float3 LightDir = {0, 0, 1};
float4x4 World;
float Start = 2;
bool Lit = true;
textureCUBE Sky;
technique t {
  pass p {
    TextureFactor = <Tint>;
    MaterialDiffuse = <Tint>;
    LightEnable[2] = TRUE;
    LightType[2] = Spot;
    LightDirection[2] = <LightDir>;
    LightRange[2] = 10;
    WorldTransform[0] = <World>;
    Texture[0] = <Sky>;
    Lighting = <Lit>;
    FogEnable = TRUE;
    FogVertexMode = Linear;
    FogStart = <Start>;
    FogEnd = 9;
    AlphaTestEnable = TRUE;
    AlphaFunc = Greater;
    AlphaRef = 100;
    ColorOp[0] = Lerp;
    ColorArg0[0] = TFactor | Complement;
    ResultArg[0] = Temp;
    TexCoordIndex[1] = CameraSpaceReflectionVector | 1;
    TextureTransformFlags[1] = Count3 | Projected;
    BumpEnvMat00[1] = 0.5;
    PointSize = 4;
    PointScaleEnable = TRUE;
    PointScale_B = 0.5;
    PointSize_Max = 32;
  }
}
)");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  DiagnosticSink diags;
  const FixedFunctionState s = fixed_function_state(b->model, b->model.techniques[0].passes[0], diags);
  EXPECT_EQ(s.texture_factor.parameter, (ParameterRef{"Tint", "float4"}));
  EXPECT_EQ(s.material_diffuse.parameter, (ParameterRef{"Tint", "float4"}));
  EXPECT_TRUE(s.lights[2].enabled);
  EXPECT_EQ(s.lights[2].type, LightType::spot);
  EXPECT_EQ(s.lights[2].direction.parameter, (ParameterRef{"LightDir", "float3"}));
  EXPECT_FLOAT_EQ(s.lights[2].range.value, 10);
  EXPECT_EQ(s.world.parameter, (ParameterRef{"World", "float4x4"}));
  EXPECT_EQ(s.stages[0].texture, StageTexture::cube);
  EXPECT_TRUE(s.lighting);
  EXPECT_TRUE(s.fog);
  EXPECT_EQ(s.fog_vertex_mode, FogMode::linear);
  EXPECT_EQ(s.fog_start.parameter, (ParameterRef{"Start", "float"}));
  EXPECT_FLOAT_EQ(s.fog_start.value, 2);
  EXPECT_FLOAT_EQ(s.fog_end.value, 9);
  EXPECT_TRUE(s.alpha_test);
  EXPECT_EQ(s.alpha_func, CompareOp::greater);
  EXPECT_FLOAT_EQ(s.alpha_ref.value, 100);
  EXPECT_EQ(s.stages[0].color_op, TextureOp::lerp);
  EXPECT_EQ(s.stages[0].color_arg[0], ta::tfactor | ta::complement);
  EXPECT_EQ(s.stages[0].result_arg, ta::temp);
  EXPECT_EQ(s.stages[1].tex_coord_index, texcoord_gen::camera_space_reflection_vector | 1);
  EXPECT_EQ(s.stages[1].texture_transform_flags, 3u | texture_transform::projected);
  EXPECT_FLOAT_EQ(s.stages[1].bump_env_mat[0].value, 0.5f);
  EXPECT_TRUE(s.point_size_written && s.point_scale);
  EXPECT_FLOAT_EQ(s.point_size.value, 4);
  EXPECT_FLOAT_EQ(s.point_scale_b.value, 0.5f);
  EXPECT_FLOAT_EQ(s.point_size_max.value, 32);
  // Lighting = <Lit> shapes the generated code: it takes Lit's default, with a warning.
  ASSERT_EQ(diags.warning_count(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].id, "fixed-function-frozen");
  // The generated shaders read the parameters by name.
  const std::string vs = generate_fixed_function_vertex_shader(s).source;
  EXPECT_NE(vs.find("float4x4 World;"), std::string::npos) << vs;
  EXPECT_NE(vs.find("float3 LightDir;"), std::string::npos) << vs;
  EXPECT_NE(vs.find("float Start;"), std::string::npos) << vs;
  EXPECT_NE(vs.find("fx_eye_distance"), std::string::npos) << vs;
  EXPECT_NE(vs.find(": PSIZE;"), std::string::npos) << vs;
  EXPECT_NE(generate_fixed_function_pixel_shader(s).source.find("samplerCUBE fx_stage0;"), std::string::npos);
}

}  // namespace
}  // namespace fx
