// Hull + domain shader passes drawn on the validated device: the mesh goes in as patches of
// three control points, an integer-partitioned tessellator splits each triangle, and the
// pieces keep the triangle's coverage and winding; a hull shader wanting other patches
// leaves its technique with a reason.
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <string>

#include "effect_test_util.h"

namespace fx::vk::testing {
namespace {

// `Plain` draws the sphere untessellated; `Tessellated` passes it through a triangle-domain
// tessellator (factor TessFactor, integer partitioning) with a domain shader that places each
// new vertex on its patch's plane. Both draw every face, nearest first. Red is
// SV_IsFrontFace, so a winding flipped by tessellation shows; green and blue are the domain
// location of the provoking vertex (flat), so only pieces of a split patch show values
// between 0 and 1. `Quads` wants patches of four control points.
constexpr const char* kEffect = R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float TessFactor = 4;
struct V { float4 p : SV_Position; };
struct P { float4 p : SV_Position; nointerpolation float3 uvw : TEXCOORD0; };
struct Factors { float edges[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
V VS(float4 p : POSITION) { V o; o.p = mul(p, WorldViewProjection); return o; }
Factors Constants(InputPatch<V, 3> patch) {
  Factors f; f.edges[0] = f.edges[1] = f.edges[2] = TessFactor; f.inside = TessFactor; return f; }
[domain("tri")] [partitioning("integer")] [outputtopology("triangle_cw")] [outputcontrolpoints(3)]
[patchconstantfunc("Constants")]
V HS(InputPatch<V, 3> patch, uint i : SV_OutputControlPointID) { return patch[i]; }
[domain("tri")] P DS(Factors f, float3 uvw : SV_DomainLocation, const OutputPatch<V, 3> patch) {
  P o; o.p = uvw.x * patch[0].p + uvw.y * patch[1].p + uvw.z * patch[2].p; o.uvw = uvw; return o; }
float4 PS(P i, bool front : SV_IsFrontFace) : SV_Target { return float4(front ? 1 : 0, i.uvw.xy, 1); }
float4 PlainPS(V i, bool front : SV_IsFrontFace) : SV_Target { return float4(front ? 1 : 0, 0, 0, 1); }
Factors QuadConstants(InputPatch<V, 4> patch) {
  Factors f; f.edges[0] = f.edges[1] = f.edges[2] = 2; f.inside = 2; return f; }
[domain("tri")] [partitioning("integer")] [outputtopology("triangle_cw")] [outputcontrolpoints(3)]
[patchconstantfunc("QuadConstants")]
V QuadHS(InputPatch<V, 4> patch, uint i : SV_OutputControlPointID) { return patch[i]; }
RasterizerState BothFaces { CullMode = None; };
DepthStencilState Nearest { DepthEnable = TRUE; DepthFunc = Less; };
technique11 Plain { pass P {
  SetRasterizerState(BothFaces);
  SetDepthStencilState(Nearest, 0);
  SetVertexShader(CompileShader(vs_5_0, VS()));
  SetPixelShader(CompileShader(ps_5_0, PlainPS()));
} }
technique11 Tessellated { pass P {
  SetRasterizerState(BothFaces);
  SetDepthStencilState(Nearest, 0);
  SetVertexShader(CompileShader(vs_5_0, VS()));
  SetHullShader(CompileShader(hs_5_0, HS()));
  SetDomainShader(CompileShader(ds_5_0, DS()));
  SetPixelShader(CompileShader(ps_5_0, PS()));
} }
technique11 Quads { pass P {
  SetVertexShader(CompileShader(vs_5_0, VS()));
  SetHullShader(CompileShader(hs_5_0, QuadHS()));
  SetDomainShader(CompileShader(ds_5_0, DS()));
  SetPixelShader(CompileShader(ps_5_0, PS()));
} }
)";

constexpr uint32_t kSize = 48;

class TessellationRenderTest : public VulkanTest {
 protected:
  void SetUp() override {
    VulkanTest::SetUp();
    if (!ctx().features().tessellation_shader) GTEST_SKIP() << "no tessellationShader";
    path_ = write_effect("tessellation.fx", kEffect);
  }

  // Technique `name` rendered on the sphere; fails on a validation error while rendering.
  std::optional<fx::Image> render(const std::string& name, std::optional<DynamicStateSet> dynamic) {
    auto r = bind_effect(ctx(), path_, name, "sphere", kSize, dynamic);
    if (!r) return std::nullopt;
    const size_t errors = ctx().validation_error_count();
    auto image = r->render();
    EXPECT_EQ(ctx().validation_error_count(), errors) << describe_messages(ctx());
    return image;
  }

  std::string path_;
};

const uint8_t* pixel(const fx::Image& image, uint32_t x, uint32_t y) {
  return &image.pixels[(y * image.width + x) * 4];
}

// The sphere where the untessellated technique draws it, front faces nearest (the
// tessellator's triangle_cw winding is Direct3D's: a flipped one would make the near side's
// pieces back faces), and pieces of split patches: flat domain locations strictly between 0 and 1.
// On the dynamic-state path (patch control points recorded where the device has
// extendedDynamicState2PatchControlPoints) and the fully static one.
TEST_F(TessellationRenderTest, TessellatedSphereCoversTheUntessellatedOneWithFrontFaces) {
  for (const std::optional<DynamicStateSet>& dynamic :
       {std::optional<DynamicStateSet>{}, std::optional<DynamicStateSet>{DynamicStateSet::none()}}) {
    SCOPED_TRACE(dynamic ? "static path" : "dynamic path");
    auto plain = render("Plain", dynamic);
    auto tessellated = render("Tessellated", dynamic);
    ASSERT_TRUE(plain && tessellated);
    ASSERT_EQ(pixel(*plain, kSize / 2, kSize / 2)[0], 255) << "the untessellated sphere shows no front face";
    uint32_t covered = 0, differing = 0;
    std::set<uint8_t> inner_locations;  // domain location components neither 0 nor 1
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const uint8_t* a = pixel(*plain, x, y);
        const uint8_t* b = pixel(*tessellated, x, y);
        const bool drawn_a = a[3] == 255 && a[0] == 255, drawn_b = b[3] == 255 && b[0] == 255;
        covered += drawn_a;
        differing += drawn_a != drawn_b;
        if (drawn_b)
          for (uint8_t c : {b[1], b[2]})
            if (c > 8 && c < 247) inner_locations.insert(c);
      }
    EXPECT_GT(covered, kSize * kSize / 4);
    // Pieces of a planar patch cover what the patch covers; edges may round differently.
    EXPECT_LE(differing, covered / 50) << differing << " of " << covered << " pixels differ";
    // Factor 4, integer partitioning: the edges are split in quarters (64, 128, 191), the
    // inner ring's corners sit at 1/6 and 2/3 (43, 170).
    for (uint8_t quarter : {64, 128, 191})
      EXPECT_TRUE(inner_locations.count(quarter) || inner_locations.count(quarter - 1) ||
                  inner_locations.count(quarter + 1))
          << "no vertex at " << quarter / 255.0 << " along an edge";
  }
}

// fxkit's meshes are triangle lists, patches of three: a hull shader taking InputPatch<V, 4>
// cannot run on them, and says so.
TEST_F(TessellationRenderTest, AHullShaderWantingOtherPatchesHasAReason) {
  auto r = bind_effect(ctx(), path_, "Plain", "sphere", kSize);
  ASSERT_TRUE(r);
  const uint32_t quads = r->effect->find_technique("Quads");
  ASSERT_NE(quads, kNoIndex);
  EXPECT_FALSE(r->binding->technique_ok(quads));
  EXPECT_EQ(r->binding->technique_reason(quads),
            "pass 'P': its hull shader takes patches of 4 control points; the geometry comes in patches of 3 "
            "(triangle lists)");
  EXPECT_TRUE(r->binding->technique_ok(r->effect->find_technique("Tessellated")));
}

}  // namespace
}  // namespace fx::vk::testing
