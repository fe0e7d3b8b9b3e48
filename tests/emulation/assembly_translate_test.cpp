// Shader model 1 assembly parsing and translation without a device: errors located at the
// instruction's line and column, constants bound from the pass states, the seeds' listings
// translated, and the precision model present only when asked for.
#include <gtest/gtest.h>

#include "fx/compile/effect_units.h"
#include "fx/diagnostic_render.h"
#include "fx/emulation/assembly.h"
#include "fx/frontend.h"

namespace fx {
namespace {

struct Units {
  SourceManager sm;
  DiagnosticSink diags;
  ParsedEffect parsed;
  std::unique_ptr<EffectUnits> units;
  std::string errors() const { return render_text(diags.diagnostics(), sm); }
};

std::unique_ptr<Units> units_of(const std::string& text, EffectUnitOptions options = {}) {
  auto u = std::make_unique<Units>();
  u->parsed = parse_effect_text("asm.fx", text, u->sm, u->diags, {});
  u->units = std::make_unique<EffectUnits>(u->parsed.ast, u->sm, u->diags, options);
  return u;
}

std::unique_ptr<Units> seed(const std::string& file) {
  auto u = std::make_unique<Units>();
  FrontEndOptions options;
  options.preprocessor.include_dirs = {std::string(FXKIT_SOURCE_DIR) + "/effects"};
  u->parsed = parse_effect_file(std::string(FXKIT_SOURCE_DIR) + "/effects/" + file, u->sm, u->diags, options);
  u->units = std::make_unique<EffectUnits>(u->parsed.ast, u->sm, u->diags);
  return u;
}

const char* kPass = R"(float4x4 World;
float3 Light;
float4 Colors[2];
technique t { pass p {
  VertexShaderConstant[0] = <World>;
  VertexShaderConstant[4] = <Light>;
  VertexShaderConstant[5] = <Colors>;
  VertexShaderConstant[9] = float4(0.5, 0.25, -1, 2);
  PixelShaderConstant[0] = <Light>;
  VertexShader = asm {
    vs.1.1
    m4x4 oPos, v0, c0
    mad oD0, c5, c9, c6
    mov oT0, c4
  };
  PixelShader = asm {
    ps.1.1
    mul r0, v0, c0
  };
} }
)";

TEST(AssemblyTranslation, ConstantsReadTheParametersThePassNames) {
  auto u = units_of(kPass);
  ASSERT_FALSE(u->diags.has_errors()) << u->errors();
  const EffectPass& pass = u->units->passes()[0];
  const StageUnit* vs = pass.find(ShaderStage::vertex);
  ASSERT_TRUE(vs);
  EXPECT_EQ(vs->kind, StageSourceKind::assembly);
  EXPECT_EQ(vs->emulation, "vs.1.1 assembly translated to HLSL");
  // A column-major matrix: one column per register, as D3DX uploads it.
  EXPECT_NE(vs->translated.find("float4 c3 = (float4)(transpose(World)[3]);"), std::string::npos) << vs->translated;
  EXPECT_NE(vs->translated.find("float4 c4 = float4(Light, 0.0);"), std::string::npos);
  EXPECT_NE(vs->translated.find("float4 c6 = (float4)(Colors[1]);"), std::string::npos);
  EXPECT_NE(vs->translated.find("float4 c9 = float4(0.5, 0.25, -1.0, 2.0);"), std::string::npos);
  EXPECT_NE(vs->translated.find("float4 v0 : POSITION;"), std::string::npos);
  std::optional<TranslationUnit> unit = u->units->unit(*vs);
  ASSERT_TRUE(unit);
  EXPECT_EQ(unit->profile, "vs_3_0");
  const StageUnit* ps = pass.find(ShaderStage::fragment);
  ASSERT_TRUE(ps);
  EXPECT_NE(ps->translated.find("float4 c0 = float4(Light, 0.0);"), std::string::npos) << ps->translated;
  EXPECT_EQ(ps->translated.find("fx_precision"), std::string::npos);
}

TEST(AssemblyTranslation, PrecisionModelWhenAskedFor) {
  fx::EffectUnitOptions precision;
  precision.ps1x_precision = true;
  auto on = units_of(kPass, precision);
  const StageUnit* ps = on->units->passes()[0].find(ShaderStage::fragment);
  ASSERT_TRUE(ps);
  EXPECT_NE(ps->translated.find("clamp(floor(x * 255.0 + 0.5) / 255.0, -1.0, 1.0)"), std::string::npos)
      << ps->translated;
  EXPECT_NE(ps->emulation.find("precision modelled"), std::string::npos);
  std::string annotated = kPass;
  annotated.replace(annotated.find("technique t"), 11, "technique t < bool Ps1xPrecision = true; >");
  auto by_annotation = units_of(annotated);
  EXPECT_NE(by_annotation->units->passes()[0].find(ShaderStage::fragment)->translated.find("fx_precision("),
            std::string::npos);
}

struct BadCase {
  const char* code;
  const char* located;  // "asm.fx:line:col: error: ..." prefix and message part
};

TEST(AssemblyTranslation, ErrorsPointAtTheInstruction) {
  const BadCase cases[] = {
      {"ps.1.1\n  mov r0, v0\n  frob r0, r1", "asm.fx:5:3: error: 'frob' is not a ps.1.1 instruction"},
      {"ps.1.1\n  mul r0, v0", "asm.fx:4:3: error: 'mul' takes 3 operand(s), 2 given"},
      {"ps.1.1\n  mov r0, q7", "asm.fx:4:11: error: 'q7' is not a ps.1.1 register"},
      {"ps.1.1\n  mov r0.xq, v0", "asm.fx:4:7: error: expected a write mask"},
      {"ps.1.1\n  mov_x3 r0, v0", "asm.fx:4:3: error: unknown instruction modifier '_x3'"},
      {"ps.1.1\n  mov r0, v0_bx3", "asm.fx:4:11: error: unknown source modifier '_bx3'"},
      {"ps.1.4\n  texld r0, t0\n  phase\n  phase", "asm.fx:6:3: error: a shader has one 'phase'"},
      {"ps.1.1\n  texld r0, t0", "asm.fx:4:3: error: 'texld' is not a ps.1.1 instruction"},
      {"ps.1.1\n  texm3x2tex t1, t0", "asm.fx:4:3: error: 'texm3x2tex' must follow one texm3x2pad"},
      {"xs.1.1\n  mov r0, v0", "asm.fx:3:5: error: expected a version"},
      {"ps.1.1\n  def c0, 1, 2, x, 4", "asm.fx:4:17: error: expected a number"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.code);
    auto u = units_of(std::string("technique t { pass p {\n  PixelShader = asm {\n    ") + c.code + "\n  };\n} }\n");
    const std::string errors = u->errors();
    EXPECT_NE(errors.find(c.located), std::string::npos) << errors;
    const StageUnit* ps = u->units->passes()[0].find(ShaderStage::fragment);
    ASSERT_TRUE(ps);
    EXPECT_EQ(ps->kind, StageSourceKind::invalid);
  }
}

TEST(AssemblyTranslation, LaterShaderModelsAreNotTranslatedButNotErrors) {
  auto u = units_of(
      "technique t { pass p {\n  PixelShader = asm {\n    ps_2_0\n    dcl t0.xy\n    mov oC0, t0\n  };\n} }\n");
  EXPECT_FALSE(u->diags.has_errors()) << u->errors();
  const StageUnit* ps = u->units->passes()[0].find(ShaderStage::fragment);
  ASSERT_TRUE(ps);
  EXPECT_EQ(ps->kind, StageSourceKind::assembly);
  EXPECT_NE(ps->unsupported.find("ps_2_0 assembly is not translated"), std::string::npos);
  EXPECT_FALSE(u->units->unit(*ps).has_value());
}

TEST(AssemblyTranslation, InstructionsMayShareALine) {
  auto u = units_of(
      "technique t { pass p {\n  VertexShader = asm { vs.1.1 dcl_position v0 m4x4 oPos, v0, c0 };\n"
      "  PixelShader = asm { ps.1.1 mov r1, v0 +mov r1.a, v0 mul r0, r1, r1 };\n} }\n");
  ASSERT_FALSE(u->diags.has_errors()) << u->errors();
  const StageUnit* ps = u->units->passes()[0].find(ShaderStage::fragment);
  ASSERT_TRUE(ps);
  EXPECT_EQ(ps->kind, StageSourceKind::assembly);
  EXPECT_NE(ps->translated.find("r0 = fx_a;"), std::string::npos) << ps->translated;
}

TEST(AssemblyTranslation, EverySeedListingTranslates) {
  size_t stages = 0;
  for (const char* file : {"brdf.fx", "hemisphere.fx", "per_pixel_lighting.fx", "strand_aniso.fx"}) {
    SCOPED_TRACE(file);
    auto u = seed(file);
    ASSERT_FALSE(u->diags.has_errors()) << u->errors();
    for (const EffectPass& p : u->units->passes())
      for (const StageUnit& s : p.stages) {
        if (s.kind == StageSourceKind::hlsl || s.kind == StageSourceKind::fixed_function) continue;
        EXPECT_EQ(s.kind, StageSourceKind::assembly) << p.technique << ": " << s.unsupported;
        EXPECT_FALSE(s.translated.empty());
        ++stages;
      }
  }
  // 7 techniques with both stages in assembly, 4 with an assembly vertex shader and
  // fixed-function texture stages.
  EXPECT_EQ(stages, 18u);
}

}  // namespace
}  // namespace fx
