// Textures from DDS files named by ResourceName, sampled by real effects on the validated
// device: a cube map face by face, BC3 blocks texel by texel, a missing file located at its
// annotation with a stand-in, and a file found through the include folders.
#include <gtest/gtest.h>

#include <array>

#include "dds_writer.h"
#include "effect_folder.h"
#include "effect_test_util.h"

namespace fx::vk::testing {
namespace {

using fx::testing::DdsHeader;
using fx::testing::EffectFolder;

// Writes `text` as `name` in `folder` and returns its path.
std::string write(const EffectFolder& folder, const std::string& name, const std::string& text) {
  folder.write(name, text);
  return folder.path(name);
}

class DdsTextureTest : public VulkanTest {
 protected:
  // Renders technique T of `r` with `At` set and returns the centre pixel.
  std::array<uint8_t, 4> centre(RenderedEffect& r, std::array<float, 3> at) {
    EXPECT_TRUE(r.effect->params->set(r.effect->params->find("At"), std::span<const float>(at)));
    auto image = r.render();
    if (!image) return {};
    const uint8_t* p = image->at(image->width / 2, image->height / 2);
    return {p[0], p[1], p[2], p[3]};
  }
};

constexpr const char* kCubeEffect = R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float3 At;
texture Sky < string ResourceName = "sky.dds"; >;
samplerCUBE SkySampler = sampler_state { Texture = <Sky>; MinFilter = POINT; MagFilter = POINT; };
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return texCUBE(SkySampler, At); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";

// Each face of a 2x2 DX9 cube map has its own colour; a direction along each axis reads it.
TEST_F(DdsTextureTest, CubeMapFacesSampleTheirTexels) {
  EffectFolder folder("dds_cube");
  DdsHeader h;
  h.width = h.height = 2;
  h.cube = true;
  const std::array<std::array<uint8_t, 4>, 6> faces = {{{255, 0, 0, 255},
                                                        {0, 255, 0, 255},
                                                        {0, 0, 255, 255},
                                                        {255, 255, 0, 255},
                                                        {0, 255, 255, 255},
                                                        {255, 0, 255, 255}}};
  std::vector<uint8_t> data;
  for (const auto& face : faces)
    for (int texel = 0; texel < 4; ++texel) data.insert(data.end(), face.begin(), face.end());
  fx::testing::write_dds(folder.path("sky.dds"), h, data);
  auto r = bind_effect(ctx(), write(folder, "cube.fx", kCubeEffect), "T", "quad", 16);
  ASSERT_TRUE(r);
  const std::array<std::array<float, 3>, 6> directions = {
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  for (size_t f = 0; f < 6; ++f) EXPECT_EQ(centre(*r, directions[f]), faces[f]) << "face " << f;
}

constexpr const char* kBc3Effect = R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float3 At;
texture Albedo < string ResourceName = "albedo.dds"; >;
sampler2D AlbedoSampler = sampler_state { Texture = <Albedo>; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return tex2Dlod(AlbedoSampler, float4(At.xy, 0, At.z)); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

// An 8x4 DXT5 texture of two blocks (red with alpha 200, blue) and a 4x2 second mip level of
// one green block: each block samples its colour, uploaded compressed or decoded.
TEST_F(DdsTextureTest, Bc3BlocksSampleTheirColours) {
  EffectFolder folder("dds_bc3");
  DdsHeader h;
  h.width = 8, h.height = 4, h.mips = 2;
  h.fourcc = fx::testing::dds_fourcc("DXT5");
  std::vector<uint8_t> data = fx::testing::bc3_solid_block(0xF800, 200);
  for (const auto& block : {fx::testing::bc3_solid_block(0x001F, 255), fx::testing::bc3_solid_block(0x07E0, 255)})
    data.insert(data.end(), block.begin(), block.end());
  fx::testing::write_dds(folder.path("albedo.dds"), h, data);
  auto r = bind_effect(ctx(), write(folder, "bc3.fx", kBc3Effect), "T", "quad", 16);
  ASSERT_TRUE(r);
  EXPECT_EQ(centre(*r, {0.2f, 0.5f, 0}), (std::array<uint8_t, 4>{255, 0, 0, 200}));
  EXPECT_EQ(centre(*r, {0.8f, 0.5f, 0}), (std::array<uint8_t, 4>{0, 0, 255, 255}));
  EXPECT_EQ(centre(*r, {0.5f, 0.5f, 1}), (std::array<uint8_t, 4>{0, 255, 0, 255}));
}

// The diagnostics of binding `path` with its textures looked for in `texture_dirs` after the
// effect's folder, and the line and column of the first "vk-texture-file-missing" (0 if none).
struct Bound {
  DiagnosticSink sink;
  PresumedLocation missing_at;
  std::string missing_message;
};
void bind_textures_of(const Context& ctx, const std::string& path, std::vector<std::filesystem::path> texture_dirs,
                      Bound& out) {
  auto effect = EffectFile::load(path, {}, out.sink);
  ASSERT_TRUE(effect) << describe(out.sink);
  auto mesh = make_mesh("quad", out.sink);
  ASSERT_TRUE(mesh);
  auto preview = EffectPreview::create(ctx, *mesh, {}, out.sink);
  ASSERT_TRUE(preview) << describe(out.sink);
  EffectBindingDesc bd = preview->binding_desc();
  bd.effect_dir = std::filesystem::path(path).parent_path();
  bd.texture_dirs = std::move(texture_dirs);
  auto binding = EffectBinding::create(ctx, *effect->model, *effect->programs, *effect->params, preview->textures(),
                                       preview->frames(), bd, out.sink);
  ASSERT_TRUE(binding) << describe(out.sink);
  for (const Diagnostic& d : out.sink.diagnostics())
    if (d.id == "vk-texture-file-missing" && !out.missing_at.valid()) {
      out.missing_at = effect->sources.presumed(d.range.begin);
      out.missing_message = d.message;
    }
}

// A file that is not there: a warning at the ResourceName annotation, and the white stand-in.
TEST_F(DdsTextureTest, MissingFileIsLocatedAtItsAnnotation) {
  EffectFolder folder("dds_missing");
  Bound bound;
  bind_textures_of(ctx(), write(folder, "missing.fx", kBc3Effect), {}, bound);
  ASSERT_TRUE(bound.missing_at.valid()) << describe(bound.sink);
  EXPECT_EQ(bound.missing_at.line, 3u);
  EXPECT_EQ(bound.missing_at.column, 18u);  // `string ResourceName`
  EXPECT_NE(bound.missing_message.find("albedo.dds"), std::string::npos);
}

// A file not beside the effect is found in a folder named by texture_dirs (-I).
TEST_F(DdsTextureTest, FileIsFoundInTheIncludeFolders) {
  EffectFolder effects("dds_effects"), textures("dds_textures");
  DdsHeader h;
  h.width = h.height = 2;
  h.cube = true;
  fx::testing::write_dds(textures.path("sky.dds"), h, std::vector<uint8_t>(6 * 4 * 4, 128));
  Bound bound;
  bind_textures_of(ctx(), write(effects, "cube.fx", kCubeEffect), {textures.path()}, bound);
  EXPECT_FALSE(bound.missing_at.valid()) << bound.missing_message;
}

}  // namespace
}  // namespace fx::vk::testing
