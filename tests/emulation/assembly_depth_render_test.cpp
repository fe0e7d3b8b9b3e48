// The depth-writing ps.1.x instructions (texm3x2depth, texdepth) rendered on the device
// against the CPU interpreter (asm_interpreter.h): an HLSL vertex shader hands affine
// texture coordinates to the translated pixel shader, drawn into a D32 depth target whose
// every pixel must hold the interpreter's z / w.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "asm_interpreter.h"
#include "effect_test_util.h"
#include "fixed_function_rig.h"

namespace fx::vk::testing {
namespace {

using emulation::testing::AsmMachine;
using emulation::testing::Vec4;

constexpr uint32_t kSize = 16;

// Texture coordinates as affine functions of the quad's (u, v): {constant, u, v} per
// component, exact under the rasterizer's linear interpolation.
struct Affine {
  std::array<std::array<double, 3>, 4> c;
  Vec4 at(double u, double v) const {
    Vec4 out;
    for (int k = 0; k < 4; ++k) out[k] = c[k][0] + c[k][1] * u + c[k][2] * v;
    return out;
  }
  std::string hlsl() const {
    std::string s = "float4(";
    for (int k = 0; k < 4; ++k) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%s%.9g + %.9g * uv.x + %.9g * uv.y", k ? ", " : "", c[k][0], c[k][1], c[k][2]);
      s += buf;
    }
    return s + ")";
  }
};

struct Case {
  const char* name;
  const char* pixel;              // the asm block's text
  std::vector<Affine> texcoords;  // TEXCOORD0, 1, ... the vertex shader writes
  Vec4 c0, c1;                    // PixelShaderConstant[0..1]
};

const std::vector<Case>& cases() {
  static const std::vector<Case> list = {
      // z = TEXCOORD1 . t0, w = TEXCOORD2 . t0 with t0 = saturate(TEXCOORD0): 0 to 0.47.
      {"texm3x2depth",
       "ps.1.3\ntexcoord t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\nmov r0, c0",
       {{{{{0, 1, 0}, {0, 0, 1}, {0.5, 0, 0}, {1, 0, 0}}}},
        {{{{0.2, 0.3, 0}, {0.1, 0, 0}, {0, 0, 0.4}, {0, 0, 0}}}},
        {{{{0.5, 0, 0}, {0.6, 0, 0.2}, {0.3, 0.5, 0}, {0, 0, 0}}}}},
       {0.25, 0.5, 0.75, 1},
       {}},
      // A z row larger than the w row: z / w clamps to 1 over part of the quad.
      {"texm3x2depth_clamped",
       "ps.1.3\ntexcoord t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\nmov r0, c0",
       {{{{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}}}},
        {{{{0.1, 0.9, 0}, {0, 0, 0.3}, {0.2, 0, 0}, {0, 0, 0}}}},
        {{{{0, 0.2, 0.5}, {0.3, 0, 0}, {0.4, 0, 0}, {0, 0, 0}}}}},
       {0.5, 0.25, 0, 1},
       {}},
      // r5.r / r5.g from coordinates scaled by c0: 0.75 u / v, clamped where u > 4v / 3.
      {"texdepth",
       "ps.1.4\ntexcrd r1.rgb, t0\nmul r5.rg, r1, c0\nphase\ntexdepth r5\nmov r0, c1",
       {{{{{0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {1, 0, 0}}}}},
       {0.9, 1.2, 0, 0},
       {0.2, 0.4, 0.6, 0.8}},
      // r5.g = 0: depth 1, whatever r5.r is.
      {"texdepth_zero_w",
       "ps.1.4\ndef c2, 0.5, 0.0, 0.0, 0.0\ntexcrd r1.rgb, t0\nmov r5, c2\nphase\ntexdepth r5\nadd r0, r1, c1",
       {{{{{0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {1, 0, 0}}}}},
       {},
       {0.1, 0.1, 0.1, 1}},
  };
  return list;
}

std::string float4(const Vec4& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "float4(%.9g, %.9g, %.9g, %.9g)", v[0], v[1], v[2], v[3]);
  return buf;
}

// The quad over the whole target, (u, v) = (0, 0) at the top left; depth 0.5 as rasterized.
std::vector<FixedVertex> quad() {
  auto vertex = [](float x, float y) {
    return FixedVertex{x, y, 0.5f, 0, 0, -1, {1, 1, 1, 1}, {0, 0, 0, 0}, (x + 1) / 2, (y + 1) / 2};
  };
  const FixedVertex a = vertex(-1, -1), b = vertex(1, -1), c = vertex(1, 1), d = vertex(-1, 1);
  return {a, c, b, a, d, c};
}

class AssemblyDepthTest : public VulkanTest {};

TEST_F(AssemblyDepthTest, DepthInstructionsWriteTheInterpretersDepth) {
  double worst = 0;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::string effect =
        "float4 C0 = " + float4(c.c0) + ";\nfloat4 C1 = " + float4(c.c1) +
        ";\ntechnique t { pass p {\n  PixelShaderConstant[0] = <C0>;\n  PixelShaderConstant[1] = <C1>;\n"
        "  PixelShader = asm {\n" +
        c.pixel + "\n  };\n} }\n";
    DiagnosticSink sink;
    auto file = EffectFile::load(write_effect(std::string("depth_") + c.name + ".fx", effect), {}, sink);
    ASSERT_TRUE(file) << describe(sink);
    const StageUnit* ps = file->units->passes()[0].find(ShaderStage::fragment);
    ASSERT_TRUE(ps && ps->kind == StageSourceKind::assembly) << describe(sink);
    EXPECT_NE(ps->translated.find("SV_Depth"), std::string::npos) << ps->translated;

    std::string vs = "struct Out { float4 p : POSITION;";
    for (size_t t = 0; t < c.texcoords.size(); ++t)
      vs += " float4 t" + std::to_string(t) + " : TEXCOORD" + std::to_string(t) + ";";
    vs += " };\nOut VS(float3 p : POSITION, float2 uv : TEXCOORD0) {\n  Out o;\n  o.p = float4(p, 1);\n";
    for (size_t t = 0; t < c.texcoords.size(); ++t)
      vs += "  o.t" + std::to_string(t) + " = " + c.texcoords[t].hlsl() + ";\n";
    vs += "  return o;\n}\n";

    FixedFunctionRig rig(ctx(), kSize, true);
    ASSERT_TRUE(rig.build({vs, "VS", "vs_3_0"}, {ps->translated, ps->entry_point, "ps_3_0"}));
    ASSERT_TRUE(rig.set_uniform(
        "C0", std::array<float, 4>{float(c.c0[0]), float(c.c0[1]), float(c.c0[2]), float(c.c0[3])}.data(), 16));
    ASSERT_TRUE(rig.set_uniform(
        "C1", std::array<float, 4>{float(c.c1[0]), float(c.c1[1]), float(c.c1[2]), float(c.c1[3])}.data(), 16));
    const fx::ImageF colour = rig.render(quad());
    const std::vector<float> depth = rig.depth();
    ASSERT_EQ(depth.size(), size_t(kSize) * kSize);
    EXPECT_EQ(ctx().validation_error_count() + ctx().validation_warning_count(), 0u) << describe_messages(ctx());
    ctx().clear_validation_messages();

    const PassInfo& pass = file->model->techniques[0].passes[0];
    std::optional<emulation::AsmProgram> program;
    for (const ShaderBinding& b : pass.shaders)
      if (b.stage == PassStage::pixel)
        program = emulation::parse_assembly(*file->model->ast, b.asm_code, b.decl_code, sink);
    ASSERT_TRUE(program) << describe(sink);
    int clamped = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const double u = (x + 0.5) / kSize, v = (y + 0.5) / kSize;
        AsmMachine m;
        for (size_t t = 0; t < c.texcoords.size(); ++t) m.texcoord[t] = c.texcoords[t].at(u, v);
        m.c[0] = c.c0;
        m.c[1] = c.c1;
        m.run(*program);
        ASSERT_TRUE(m.depth);
        clamped += *m.depth == 1.0;
        const double e = std::fabs(depth[y * kSize + x] - *m.depth);
        worst = std::max(worst, e);
        // Single against double precision: a division and two dot products of values below 2.
        ASSERT_LE(e, 1e-5) << x << "," << y << ": GPU " << depth[y * kSize + x] << ", interpreter " << *m.depth;
        for (int k = 0; k < 4; ++k) ASSERT_NEAR(colour.at(x, y)[k], m.r0[k], 1e-5) << x << "," << y << " channel " << k;
      }
    if (std::string(c.name).ends_with("clamped") || std::string(c.name) == "texdepth") {
      EXPECT_GT(clamped, 0);
    }
    if (std::string(c.name) == "texm3x2depth") {
      EXPECT_EQ(clamped, 0);
    }
  }
  std::printf("[ assembly ] depth instructions: largest |GPU - interpreter| %.3g\n", worst);
}

}  // namespace
}  // namespace fx::vk::testing
