// Shader model 1 instructions rendered on the device (translated to HLSL) against the CPU
// interpreter (asm_interpreter.h): each case is a pass whose vertex shader hands constant
// colours and texture coordinates to a one-instruction-family pixel shader, drawn into a
// float target; the centre pixel must match the interpreter. Vertex shader cases write their
// result to oT0, which a ps.1.4 `texcrd` passes through unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "asm_interpreter.h"
#include "effect_test_util.h"

namespace fx::vk::testing {
namespace {

using emulation::testing::AsmMachine;
using emulation::testing::Vec4;

class AssemblyInstructionTest : public VulkanTest {};

// Inputs every case shares: colours v0/v1, texture coordinates t0-t3, pixel constants c0-c3.
const Vec4 kColor[2] = {{0.8, 0.3, 0.55, 0.9}, {0.2, 0.65, 0.4, 0.35}};
const Vec4 kTexcoord[4] = {
    {0.3, 0.7, 0.45, 0.6}, {0.55, 0.2, 0.8, 0.25}, {1.3, -0.2, 0.5, 0.75}, {0.6, 0.35, 0.9, 0.4}};
const Vec4 kPixelConstant[4] = {
    {0.25, -0.5, 0.75, 0.6}, {-0.3, 0.9, 0.1, 0.45}, {0.7, -0.2, 0.0, -0.6}, {0.4, 0.45, 0.3, 0.2}};
// Vertex shader constants c10-c15 for the vertex cases.
const Vec4 kVertexConstant[6] = {{2.5, -0.75, 0.4, 4.0}, {0.6, 0.8, -0.3, 16.0}, {-1.25, 3.0, 0.5, 0.25},
                                 {3.0, 0.0, 0.0, 0.0},   {0.1, 0.2, 0.3, 0.4},   {0.9, 0.8, 0.7, 0.6}};

std::string float4(const Vec4& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "float4(%.9g, %.9g, %.9g, %.9g)", v[0], v[1], v[2], v[3]);
  return buf;
}

// The float table every stage samples (rgb = v, a = u at texel centres, 16x16, point
// sampling and wrap as D3D9's default sampler states), and its CPU model.
constexpr int kTable = 16;
Vec4 table_sample(uint32_t, const Vec4& c) {
  auto texel = [](double x) {
    double f = x - std::floor(x);
    int i = std::min(kTable - 1, int(std::floor(f * kTable)));
    return (i + 0.5) / kTable;
  };
  const double v = texel(c[1]), u = texel(c[0]);
  return {v, v, v, u};
}

std::string effect_text(const std::string& vertex_body, const std::string& pixel, bool precision,
                        const std::string& extra_states) {
  std::string s =
      "float4x4 WorldViewProjection : WORLDVIEWPROJECTION;\n"
      "texture Table < string Generator = \"pow\"; int Width = 16; int Height = 16; float Exponent = 1; "
      "string Format = \"float32\"; >;\n";
  s += std::string("technique t < bool Ps1xPrecision = ") + (precision ? "true" : "false") + "; > { pass p {\n";
  s += "  VertexShaderConstant[0] = <WorldViewProjection>;\n";
  for (int i = 0; i < 2; ++i)
    s += "  VertexShaderConstant[" + std::to_string(4 + i) + "] = " + float4(kColor[i]) + ";\n";
  for (int i = 0; i < 4; ++i)
    s += "  VertexShaderConstant[" + std::to_string(6 + i) + "] = " + float4(kTexcoord[i]) + ";\n";
  for (int i = 0; i < 6; ++i)
    s += "  VertexShaderConstant[" + std::to_string(10 + i) + "] = " + float4(kVertexConstant[i]) + ";\n";
  for (int i = 0; i < 4; ++i)
    s += "  PixelShaderConstant[" + std::to_string(i) + "] = " + float4(kPixelConstant[i]) + ";\n";
  for (int i = 0; i < 4; ++i) s += "  Texture[" + std::to_string(i) + "] = <Table>;\n";
  s += extra_states;
  s += "  VertexShader = asm {\n    vs.1.1\n    m4x4 oPos, v0, c0\n" + vertex_body + "  };\n";
  s += "  PixelShader = asm {\n" + pixel + "\n  };\n} }\n";
  return s;
}

const char* kPassThrough =
    "    mov oD0, c4\n    mov oD1, c5\n    mov oT0, c6\n    mov oT1, c7\n    mov oT2, c8\n    mov oT3, c9\n";

struct Case {
  const char* name;
  const char* pixel;             // pixel shader (version line included)
  const char* vertex = nullptr;  // vertex shader body writing oT0 (pixel is then `texcrd`)
  bool precision = false;
  const char* states = "";
};

const Case kCases[] = {
    {"mov", "ps.1.1\nmov r0, c0"},
    {"add_sub", "ps.1.1\nadd r1, v0, c1\nsub r0, r1, v1"},
    {"mul_mad_modifiers", "ps.1.1\nmul r1, v0_bx2, -v1\nmad_x2 r0, r1, 1-v0, c2"},
    {"bias_x4_d2", "ps.1.1\nadd_x4 r1, v0_bias, v1_bias\nmul_d2 r0, r1, v0"},
    {"sat", "ps.1.1\nadd_sat r0, v0, v1"},
    {"dp3", "ps.1.1\ndp3 r0, v0_bx2, v1_bx2"},
    {"dp3_sat_d2", "ps.1.1\ndp3_d2_sat r0, v0_bx2, c1"},
    {"dp4", "ps.1.2\ndp4 r0, c0, c1"},
    {"lrp", "ps.1.1\nlrp r0, v0, c0, c1"},
    {"cnd", "ps.1.1\nmov r0, v1\ncnd r0, r0.a, c0, c1"},
    {"cnd_14", "ps.1.4\ncnd r0, c0, c2, c1"},
    {"cmp", "ps.1.2\ncmp r0, c2, c0, c1"},
    {"masks_and_selectors", "ps.1.1\nmov r0, c0\nmov r0.a, c1.b\nmul r0.rgb, r0, v0.a"},
    {"coissue", "ps.1.1\nmov r0, c0\nmov r1, c1\nadd r0.rgb, r0, r1\n+mul r0.a, r0, r1"},
    {"swizzle_14", "ps.1.4\nmov r0.xz, c0.wzyx\nmov r0.yw, c1.x"},
    {"x2_source_14", "ps.1.4\nadd r0, c0_x2, c1"},
    {"tex", "ps.1.1\ntex t0\ntex t1\nmul r0, t0, t1"},
    {"texcoord", "ps.1.1\ntexcoord t2\nmov r0, t2"},
    {"texm3x2", "ps.1.1\ntex t0\ntexm3x2pad t1, t0_bx2\ntexm3x2tex t2, t0_bx2\nmov r0, t2"},
    {"texreg2ar_gb", "ps.1.1\ntex t0\ntexreg2ar t1, t0\ntexreg2gb t2, t0\nadd r0, t1, t2"},
    {"texm3x3tex", "ps.1.1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3tex t3, t0\nmov r0, t3"},
    {"texm3x3", "ps.1.2\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3 t3, t0\nmov r0, t3"},
    {"texm3x3spec", "ps.1.1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, c3\nmov r0, t3"},
    {"texm3x3vspec", "ps.1.1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3vspec t3, t0\nmov r0, t3"},
    {"texdp3", "ps.1.2\ntex t0\ntexdp3 t1, t0\nmov r0, t1"},
    {"texdp3tex", "ps.1.2\ntex t0\ntexdp3tex t1, t0\nmov r0, t1"},
    {"texbem", "ps.1.1\ntex t0\ntexbem t1, t0\nmov r0, t1", nullptr, false,
     "BumpEnvMat00[1] = 0.5; BumpEnvMat01[1] = -0.25; BumpEnvMat10[1] = 0.125; BumpEnvMat11[1] = 0.75;\n"},
    {"texbeml", "ps.1.1\ntex t0\ntexbeml t1, t0\nmov r0, t1", nullptr, false,
     "BumpEnvMat00[1] = 0.5; BumpEnvMat11[1] = 0.75; BumpEnvLScale[1] = 0.8; BumpEnvLOffset[1] = 0.1;\n"},
    {"texld_texcrd_14", "ps.1.4\ntexld r0, t0\ntexcrd r1, t1\nadd r0, r0, r1"},
    {"texld_divide_14", "ps.1.4\ntexld r1, t3_dz\ntexcrd r2, t2_dw\nmad r0, r1, c3, r2"},
    {"phase_14", "ps.1.4\ntexcrd r1.rgb, t0\nmul r1, r1, c3\nphase\ntexld r1, r1\nmov r0, r1"},
    {"bem_14", "ps.1.4\nbem r1.rg, c0, c1\nphase\ntexld r1, r1\nmov r0, r1", nullptr, false,
     "BumpEnvMat00[1] = 0.5; BumpEnvMat01[1] = -0.25; BumpEnvMat10[1] = 0.125; BumpEnvMat11[1] = 0.7;\n"},
    {"def", "ps.1.1\ndef c5, 0.125, 0.25, -0.5, 1.0\nmad r0, c5, v0, c1"},
    // Hardware precision: 8-bit fractions, clamps at +-1 (ps.1.1) and +-8 (ps.1.4).
    {"precision_mul", "ps.1.1\nmul r0, v0, v1\nmul r0, r0, v0", nullptr, true},
    {"precision_clamp_11", "ps.1.1\nmul_x4 r0, v0, c1", nullptr, true},
    {"precision_clamp_14", "ps.1.4\nmul_x8 r0, c0, c1\nadd_x8 r0, r0, c3", nullptr, true},
    // Interpolated texture coordinates read as data take the register model: texcoord
    // clamps to [0, 1], texcrd to [-8, 8], both at 8-bit fractions; texm3x3's rows too.
    {"precision_texcoord", "ps.1.1\ntexcoord t2\ntexcoord t3\nmul r0, t2, t3", nullptr, true},
    {"precision_texcrd_14", "ps.1.4\ntexcrd r1, t2\ntexcrd r2, t3\nmad r0, r1, c1, r2", nullptr, true},
    {"precision_texcrd_range", nullptr, "    mul oT0, c10, c11.w\n", true},  // (40, -12, 6.4): clamped to +-8
    {"precision_texm3x3", "ps.1.2\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3 t3, t0\nmov r0, t3", nullptr,
     true},
    // Vertex shader instructions, result in oT0.
    {"vs_arithmetic", nullptr,
     "    add r0, c10, c11\n    mad r1, r0, c12, -c10\n    max r1, r1, c13\n    min oT0, r1, c11\n"},
    {"vs_dp_and_matrix", nullptr, "    m3x3 r0, c10, c12\n    dp4 r0.w, c10, c11\n    mov oT0, r0\n"},
    {"vs_m4x3_m3x2", nullptr, "    m4x3 r0, c10, c12\n    m3x2 r1, c11, c13\n    add oT0, r0, r1\n"},
    {"vs_rcp_rsq", nullptr,
     "    rcp r0.x, c10.x\n    rsq r0.y, c10.w\n    rcp r0.z, c11\n    rsq r0.w, c12.y\n    mov oT0, r0\n"},
    {"vs_slt_sge_frc", nullptr,
     "    slt r0, c10, c11\n    sge r1, c10, c11\n    frc r2, c12\n    mad oT0, r0, c14, r1\n    add oT0.w, r2.x, "
     "r2.y\n"},
    {"vs_exp_log", nullptr,
     "    exp r0.x, c10.x\n    log r0.y, c11.w\n    expp r1, c12.x\n    logp r2, c10.w\n    mov oT0.xy, r0\n    add "
     "oT0.z, r1.y, r2.y\n"},
    {"vs_lit_dst", nullptr, "    lit r0, c11\n    dst r1, c10, c12\n    add oT0, r0, r1\n"},
    {"vs_relative", nullptr, "    mov a0.x, c13.x\n    mov oT0, c[a0.x + 10]\n"},
    {"vs_swizzle_negate", nullptr, "    mov r0, -c10.wzyx\n    mul r0.xz, r0, c11.y\n    mov oT0, r0\n"},
};

TEST_F(AssemblyInstructionTest, RendersAsTheInterpreterComputes) {
  size_t pixel_cases = 0, vertex_cases = 0;
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.name);
    const bool vertex = c.vertex != nullptr;
    const std::string pixel = vertex ? "ps.1.4\ntexcrd r0, t0" : c.pixel;
    const std::string vertex_body = vertex ? std::string(c.vertex) : std::string(kPassThrough);
    const std::string path =
        write_effect(std::string("asm_") + c.name + ".fx", effect_text(vertex_body, pixel, c.precision, c.states));
    auto r = bind_effect(ctx(), path, "t", "sphere", 16, std::nullopt, VK_FORMAT_R32G32B32A32_SFLOAT);
    ASSERT_TRUE(r);
    auto image = r->render_floats();
    ASSERT_TRUE(image);
    EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
    ctx().clear_validation_messages();

    // The same programs on the CPU.
    const PassInfo& pass = r->effect->model->techniques[0].passes[0];
    DiagnosticSink sink;
    std::optional<emulation::AsmProgram> vs, ps;
    for (const ShaderBinding& b : pass.shaders) {
      auto program = emulation::parse_assembly(*r->effect->model->ast, b.asm_code, b.decl_code, sink);
      ASSERT_TRUE(program) << describe(sink);
      (b.stage == PassStage::vertex ? vs : ps) = std::move(program);
    }
    ASSERT_TRUE(vs && ps);
    AsmMachine vm;
    vm.v[0] = {0, 0, 0, 1};
    for (int i = 0; i < 2; ++i) vm.c[4 + i] = kColor[i];
    for (int i = 0; i < 4; ++i) vm.c[6 + i] = kTexcoord[i];
    for (int i = 0; i < 6; ++i) vm.c[10 + i] = kVertexConstant[i];
    vm.run(*vs);
    AsmMachine pm;
    pm.v[0] = vm.color[0];
    pm.v[1] = vm.color[1];
    pm.texcoord = vm.out_texcoord;
    for (int i = 0; i < 4; ++i) pm.c[i] = kPixelConstant[i];
    pm.sample = table_sample;
    pm.hardware_precision = c.precision;
    const ast::Pass* ast_pass = nullptr;
    for (const ast::Decl& d : r->effect->model->ast->decls)
      if (d.kind == ast::DeclKind::technique) ast_pass = &d.technique->passes[0];
    ASSERT_TRUE(ast_pass);
    DiagnosticSink bind_sink;
    pm.bump = emulation::bind_pass_states(*ast_pass, true, {}, bind_sink).bump;
    pm.run(*ps);
    const float* px = image->at(image->width / 2, image->height / 2);
    // Float arithmetic: single vs double precision. Modelled precision: one 8-bit step, for
    // a value rounding the other way.
    const double tolerance = c.precision ? 1.0 / 255.0 + 1e-4 : 2e-4 * 8;
    const int channels = vertex ? 3 : 4;  // texcrd sets w to 1
    for (int k = 0; k < channels; ++k)
      EXPECT_NEAR(px[k], pm.r0[k], tolerance * std::max(1.0, std::abs(pm.r0[k]))) << "channel " << k;
    (vertex ? vertex_cases : pixel_cases)++;
  }
  EXPECT_GE(pixel_cases, 30u);
  EXPECT_GE(vertex_cases, 8u);
}

}  // namespace
}  // namespace fx::vk::testing
