#include "fx/state_table.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <tuple>

#include "fx/ascii_case.h"

namespace fx {
namespace {

TEST(StateTable, LooksUpNamesCaseInsensitivelyPerBlock) {
  const StateInfo* z = find_state("zenable", StateBlock::pass);
  ASSERT_NE(z, nullptr);
  EXPECT_EQ(z->name, "ZEnable");
  EXPECT_EQ(find_state("ZENABLE", StateBlock::pass), z);
  EXPECT_EQ(find_state("ZEnable", StateBlock::blend_state), nullptr);
  EXPECT_EQ(find_state("ZEnabled", StateBlock::pass), nullptr);
  EXPECT_EQ(find_state("", StateBlock::pass), nullptr);

  const StateInfo* cull9 = find_state("CullMode", StateBlock::pass);
  const StateInfo* cull10 = find_state("cullmode", StateBlock::rasterizer_state);
  ASSERT_TRUE(cull9 && cull10);
  EXPECT_NE(cull9, cull10);
  EXPECT_EQ(cull9->api, StateApi::d3d9);
  EXPECT_EQ(cull10->api, StateApi::d3d10);
}

TEST(StateTable, EveryRowIsUniqueAndComplete) {
  std::set<std::pair<int, std::string>> seen;
  for (const StateInfo& s : all_states()) {
    std::string lower;
    for (char c : s.name) lower.push_back(static_cast<char>(std::tolower(c)));
    EXPECT_TRUE(seen.insert({int(s.block), lower}).second) << s.name << " twice in " << to_string(s.block);
    if (s.type == StateValueType::enumeration || (s.type == StateValueType::flags && s.name != "ClipPlaneEnable")) {
      EXPECT_NE(s.enums, nullptr) << s.name;
    }
    if (s.type == StateValueType::state_object) {
      EXPECT_FALSE(s.object_kind.empty()) << s.name;
    }
    if (s.index_required) {
      EXPECT_GT(s.index_count, 0) << s.name;
    }
    EXPECT_EQ(find_state(s.name, s.block), &s) << s.name;
  }
  EXPECT_GT(all_states().size(), 200u);
}

TEST(StateTable, CoversTheDocumentedStates) {
  const char* pass[] = {"ZEnable",
                        "ZWriteEnable",
                        "ZFunc",
                        "CullMode",
                        "FillMode",
                        "AlphaBlendEnable",
                        "SrcBlend",
                        "DestBlend",
                        "BlendOp",
                        "SeparateAlphaBlendEnable",
                        "SrcBlendAlpha",
                        "DestBlendAlpha",
                        "BlendOpAlpha",
                        "AlphaTestEnable",
                        "AlphaFunc",
                        "AlphaRef",
                        "StencilEnable",
                        "StencilFail",
                        "StencilZFail",
                        "StencilPass",
                        "StencilFunc",
                        "StencilRef",
                        "StencilMask",
                        "StencilWriteMask",
                        "TwoSidedStencilMode",
                        "CCW_StencilFail",
                        "CCW_StencilZFail",
                        "CCW_StencilPass",
                        "CCW_StencilFunc",
                        "ColorWriteEnable",
                        "DepthBias",
                        "SlopeScaleDepthBias",
                        "ScissorTestEnable",
                        "SRGBWriteEnable",
                        "MultiSampleAntialias",
                        "MultiSampleMask",
                        "FogEnable",
                        "Lighting",
                        "MaterialDiffuse",
                        "ColorOp",
                        "AlphaOp",
                        "TexCoordIndex",
                        "VertexShader",
                        "PixelShader",
                        "VertexShaderConstant",
                        "PixelShaderConstant",
                        "Texture",
                        "AddressU",
                        "AddressV",
                        "AddressW",
                        "BorderColor",
                        "MagFilter",
                        "MinFilter",
                        "MipFilter",
                        "MipMapLodBias",
                        "MaxMipLevel",
                        "MaxAnisotropy",
                        "SRGBTexture",
                        "SetVertexShader",
                        "SetPixelShader",
                        "SetGeometryShader",
                        "SetHullShader",
                        "SetDomainShader",
                        "SetComputeShader",
                        "SetBlendState",
                        "SetDepthStencilState",
                        "SetRasterizerState"};
  for (const char* n : pass) EXPECT_NE(find_state(n, StateBlock::pass), nullptr) << n;
  const char* blend[] = {"AlphaToCoverageEnable",
                         "BlendEnable",
                         "SrcBlend",
                         "DestBlend",
                         "BlendOp",
                         "SrcBlendAlpha",
                         "DestBlendAlpha",
                         "BlendOpAlpha",
                         "RenderTargetWriteMask"};
  for (const char* n : blend) EXPECT_NE(find_state(n, StateBlock::blend_state), nullptr) << n;
  const char* depth[] = {"DepthEnable",
                         "DepthWriteMask",
                         "DepthFunc",
                         "StencilEnable",
                         "StencilReadMask",
                         "StencilWriteMask",
                         "FrontFaceStencilFail",
                         "FrontFaceStencilDepthFail",
                         "FrontFaceStencilPass",
                         "FrontFaceStencilFunc",
                         "BackFaceStencilFail",
                         "BackFaceStencilDepthFail",
                         "BackFaceStencilPass",
                         "BackFaceStencilFunc"};
  for (const char* n : depth) EXPECT_NE(find_state(n, StateBlock::depth_stencil_state), nullptr) << n;
  const char* raster[] = {"FillMode",
                          "CullMode",
                          "FrontCounterClockwise",
                          "DepthBias",
                          "DepthBiasClamp",
                          "SlopeScaledDepthBias",
                          "DepthClipEnable",
                          "ScissorEnable",
                          "MultisampleEnable",
                          "AntialiasedLineEnable"};
  for (const char* n : raster) EXPECT_NE(find_state(n, StateBlock::rasterizer_state), nullptr) << n;
  const char* samp[] = {"Filter",         "AddressU",    "AddressV", "AddressW", "MipLODBias", "MaxAnisotropy",
                        "ComparisonFunc", "BorderColor", "MinLOD",   "MaxLOD",   "Texture"};
  for (const char* n : samp) EXPECT_NE(find_state(n, StateBlock::sampler_object), nullptr) << n;
  const char* samp9[] = {"Texture",   "AddressU",  "AddressV",      "AddressW",    "BorderColor",   "MagFilter",
                         "MinFilter", "MipFilter", "MipMapLodBias", "MaxMipLevel", "MaxAnisotropy", "SRGBTexture"};
  for (const char* n : samp9) EXPECT_NE(find_state(n, StateBlock::sampler_state), nullptr) << n;
}

TEST(StateTable, IndexRanges) {
  const StateInfo* tex = find_state("Texture", StateBlock::pass);
  ASSERT_NE(tex, nullptr);
  EXPECT_EQ(tex->index_count, 16);
  EXPECT_FALSE(tex->index_required);
  const StateInfo* addr = find_state("AddressU", StateBlock::pass);
  ASSERT_NE(addr, nullptr);
  EXPECT_EQ(addr->index_count, 16);
  EXPECT_EQ(find_state("AddressU", StateBlock::sampler_state)->index_count, 0);
  const StateInfo* vsc = find_state("VertexShaderConstant", StateBlock::pass);
  EXPECT_EQ(vsc->index_count, 256);
  EXPECT_TRUE(vsc->index_required);
  EXPECT_EQ(find_state("RenderTargetWriteMask", StateBlock::blend_state)->index_count, 8);
  EXPECT_EQ(find_state("BlendEnable", StateBlock::blend_state)->index_count, 8);
  EXPECT_EQ(find_state("ColorOp", StateBlock::pass)->index_count, 8);
  EXPECT_EQ(find_state("ColorWriteEnable", StateBlock::pass)->index_count, 4);
  EXPECT_EQ(find_state("ZEnable", StateBlock::pass)->index_count, 0);
}

TEST(StateTable, EnumSpellingsOfD3D9AndD3D10) {
  const StateInfo& src = *find_state("SrcBlend", StateBlock::pass);
  EXPECT_EQ(find_enum(src, "D3DBLEND_SRCALPHA"), 5);
  EXPECT_EQ(find_enum(src, "SrcAlpha"), 5);
  EXPECT_EQ(find_enum(src, "SRC_ALPHA"), 5);
  EXPECT_EQ(find_enum(src, "srcalpha"), 5);
  EXPECT_EQ(find_enum(src, "D3D10_BLEND_SRC_ALPHA"), 5);
  EXPECT_EQ(find_enum(src, "INV_SRC_ALPHA"), 6);
  EXPECT_EQ(find_enum(src, "BLEND_FACTOR"), 14);
  EXPECT_EQ(find_enum(src, "SrcAlpa"), std::nullopt);
  EXPECT_EQ(find_enum(src, "D3DBLEND_"), std::nullopt);

  const StateInfo& cull = *find_state("CullMode", StateBlock::pass);
  EXPECT_EQ(find_enum(cull, "D3DCULL_CCW"), 3);
  EXPECT_EQ(find_enum(cull, "CCW"), 3);
  EXPECT_EQ(find_enum(cull, "None"), 1);
  EXPECT_EQ(find_enum(cull, "Back"), std::nullopt);  // a D3D10 name, not a D3D9 one
  const StateInfo& cull10 = *find_state("CullMode", StateBlock::rasterizer_state);
  EXPECT_EQ(find_enum(cull10, "BACK"), 3);
  EXPECT_EQ(find_enum(cull10, "D3D11_CULL_NONE"), 1);
  EXPECT_EQ(find_enum(cull10, "CCW"), std::nullopt);

  const StateInfo& filter = *find_state("Filter", StateBlock::sampler_object);
  EXPECT_EQ(find_enum(filter, "MIN_MAG_MIP_LINEAR"), 0x15);
  EXPECT_EQ(find_enum(filter, "D3D11_FILTER_ANISOTROPIC"), 0x55);
  EXPECT_EQ(find_enum(filter, "COMPARISON_MIN_MAG_LINEAR_MIP_POINT"), 0x94);
  EXPECT_EQ(find_enum(filter, "MAXIMUM_ANISOTROPIC"), 0x1d5);
  EXPECT_EQ(enum_names(filter).size(), 36u);

  const StateInfo& addr = *find_state("addressu", StateBlock::pass);
  EXPECT_EQ(find_enum(addr, "clamp"), 3);
  EXPECT_EQ(find_enum(addr, "D3DTADDRESS_WRAP"), 1);
  EXPECT_EQ(find_enum(addr, "MIRROR_ONCE"), 5);

  const StateInfo& zenable = *find_state("ZEnable", StateBlock::pass);
  EXPECT_EQ(find_enum(zenable, "TRUE"), 1);
  EXPECT_EQ(find_enum(zenable, "D3DZB_USEW"), 2);
  const StateInfo& zwrite = *find_state("ZWriteEnable", StateBlock::pass);
  EXPECT_EQ(find_enum(zwrite, "false"), 0);  // booleans accept TRUE/FALSE in any case
  const StateInfo& depth = *find_state("DepthFunc", StateBlock::depth_stencil_state);
  EXPECT_EQ(find_enum(depth, "LESS_EQUAL"), 4);
  EXPECT_EQ(find_enum(depth, "D3DCMP_LESSEQUAL"), 4);

  // XNA/MonoGame's ColorWriteChannels spell the empty mask None (MonoGame's ParserTest.fx).
  const StateInfo& write = *find_state("ColorWriteEnable", StateBlock::pass);
  EXPECT_EQ(find_enum(write, "None"), 0);
  EXPECT_EQ(find_enum(write, "All"), 15);
  EXPECT_EQ(find_enum(*find_state("RenderTargetWriteMask", StateBlock::blend_state), "D3D11_COLOR_WRITE_ENABLE_ALL"),
            15);

  const StateInfo& arg = *find_state("ColorArg1", StateBlock::pass);
  EXPECT_EQ(find_enum(arg, "Complement"), 0x10);
  EXPECT_EQ(find_enum(arg, std::string(200, 'x')), std::nullopt);
  EXPECT_TRUE(enum_names(*find_state("FogStart", StateBlock::pass)).empty());
}

TEST(StateTable, EnumLookupEdgeCases) {
  const StateInfo& src = *find_state("SrcBlend", StateBlock::pass);
  EXPECT_EQ(find_enum(src, ""), std::nullopt);
  EXPECT_EQ(find_enum(src, "___"), std::nullopt);
  // A prefix alone, or a prefix of a prefix, names no value.
  EXPECT_EQ(find_enum(src, "D3D10_BLEND"), std::nullopt);
  EXPECT_EQ(find_enum(src, "d3dblend"), std::nullopt);
  EXPECT_EQ(find_enum(src, "D3DBLEND_D3DBLEND_SRCALPHA"), std::nullopt);
  // Case and underscores are ignored everywhere, prefix boundaries included.
  EXPECT_EQ(find_enum(src, "s_R_c_A_l_P_h_A"), 5);
  EXPECT_EQ(find_enum(src, "_D3D_BLEND_SRCALPHA_"), 5);
  EXPECT_EQ(find_enum(src, "d3d11blendsrcalpha"), 5);
  EXPECT_EQ(find_enum(src, std::string(200, '_') + "SrcAlpha"), 5);  // underscores do not count
  EXPECT_EQ(find_enum(src, "SrcAlphaX"), std::nullopt);
  EXPECT_EQ(find_enum(src, "SrcAlph"), std::nullopt);
  // Names shared by two values of one set, and another set's prefix.
  EXPECT_EQ(find_enum(src, "SrcColor2"), 16);
  EXPECT_EQ(find_enum(src, "Src1Color"), 16);
  EXPECT_EQ(find_enum(src, "D3DCMP_LESS"), std::nullopt);
  EXPECT_EQ(find_enum(*find_state("CullMode", StateBlock::pass), "D3D10_CULL_BACK"), std::nullopt);
  // Booleans have TRUE/FALSE without a prefix; ZEnable's own set has D3DZB_.
  const StateInfo& zwrite = *find_state("ZWriteEnable", StateBlock::pass);
  EXPECT_EQ(find_enum(zwrite, "tRuE"), 1);
  EXPECT_EQ(find_enum(zwrite, "D3DZB_TRUE"), std::nullopt);
  EXPECT_EQ(find_enum(*find_state("ZEnable", StateBlock::pass), "D3DZB_TRUE"), 1);
  // No set: neither enums nor a boolean.
  EXPECT_EQ(find_enum(*find_state("FogStart", StateBlock::pass), "Linear"), std::nullopt);
}

TEST(StateTable, EveryEnumSpellingIsFound) {
  for (const StateInfo& s : all_states()) {
    if (!s.enums) continue;
    for (const EnumValue& v : s.enums->values) {
      std::optional<int64_t> bare = find_enum(s, v.name);
      ASSERT_TRUE(bare) << s.name << " " << v.name;
      for (std::string_view prefix : s.enums->prefixes)
        EXPECT_EQ(find_enum(s, std::string(prefix) + std::string(v.name)), bare) << s.name << " " << prefix << v.name;
    }
  }
}

TEST(StateTable, VulkanMeaning) {
  EXPECT_EQ(find_state("ZFunc", StateBlock::pass)->vulkan, VulkanMeaning::maps_to_vulkan);
  EXPECT_EQ(find_state("ZFunc", StateBlock::pass)->area, VulkanArea::depth_stencil);
  EXPECT_EQ(find_state("AlphaTestEnable", StateBlock::pass)->vulkan, VulkanMeaning::emulated);
  EXPECT_EQ(find_state("ColorOp", StateBlock::pass)->vulkan, VulkanMeaning::fixed_function);
  EXPECT_EQ(find_state("FogEnable", StateBlock::pass)->vulkan, VulkanMeaning::fixed_function);
  EXPECT_EQ(find_state("TexCoordIndex", StateBlock::pass)->vulkan, VulkanMeaning::fixed_function);
  EXPECT_EQ(find_state("Lighting", StateBlock::pass)->vulkan, VulkanMeaning::fixed_function);
  EXPECT_EQ(find_state("MinFilter", StateBlock::sampler_state)->area, VulkanArea::sampler);
  EXPECT_EQ(find_state("SetBlendState", StateBlock::pass)->call_args, 3);
  EXPECT_EQ(find_state("SetBlendState", StateBlock::pass)->object_kind, "BlendState");
  EXPECT_EQ(find_state("SetHullShader", StateBlock::pass)->api, StateApi::d3d11);
}

TEST(StateTable, StateObjectBlocks) {
  EXPECT_EQ(state_object_block("BlendState"), StateBlock::blend_state);
  EXPECT_EQ(state_object_block("samplercomparisonstate"), StateBlock::sampler_object);
  EXPECT_EQ(state_object_block("Texture2D"), std::nullopt);
  for (int b = 0; b < kStateBlockCount; ++b) EXPECT_FALSE(state_names(StateBlock(b)).empty());
}

// One table says which states name shader code and for which stage: the checker's profile
// rule, the parser's GLSL lists and the runtime's stage resolution all read it.
TEST(StateTable, ShaderStatesCarryTheirStage) {
  const std::pair<std::string_view, PassStage> cases[] = {
      {"VertexShader", PassStage::vertex},      {"pixelshader", PassStage::pixel},
      {"FragmentShader", PassStage::pixel},     {"VERTEXPROGRAM", PassStage::vertex},
      {"FragmentProgram", PassStage::pixel},    {"GeometryProgram", PassStage::geometry},
      {"ComputeProgram", PassStage::compute},   {"SetVertexShader", PassStage::vertex},
      {"SetPixelShader", PassStage::pixel},     {"setgeometryshader", PassStage::geometry},
      {"SetHullShader", PassStage::hull},       {"SetDomainShader", PassStage::domain},
      {"SetComputeShader", PassStage::compute}, {"GeometryShader", PassStage::geometry},
      {"HullShader", PassStage::hull},          {"DomainShader", PassStage::domain},
      {"ComputeShader", PassStage::compute}};
  for (auto [name, stage] : cases) EXPECT_EQ(shader_state_stage(name), stage) << name;
  for (std::string_view name : {"ZEnable", "VertexShaderConstant", "SetBlendState", "Shader", ""})
    EXPECT_EQ(shader_state_stage(name), std::nullopt) << name;
  // Every row naming shader code has a stage, and only those rows.
  for (const StateInfo& s : all_states()) EXPECT_EQ(s.stage.has_value(), s.type == StateValueType::shader) << s.name;
}

TEST(StateTable, ShaderObjectTypesAndProfilePrefixes) {
  const std::tuple<PassStage, std::string_view, std::string_view> stages[] = {
      {PassStage::vertex, "VertexShader", "vs"},     {PassStage::pixel, "PixelShader", "ps"},
      {PassStage::geometry, "GeometryShader", "gs"}, {PassStage::hull, "HullShader", "hs"},
      {PassStage::domain, "DomainShader", "ds"},     {PassStage::compute, "ComputeShader", "cs"}};
  for (auto [stage, type, prefix] : stages) {
    EXPECT_EQ(shader_type_name(stage), type);
    EXPECT_EQ(profile_prefix(stage), prefix);
    EXPECT_EQ(shader_type_stage(type), stage);
    EXPECT_EQ(shader_type_stage(ascii_lower(type)), stage);
  }
  EXPECT_EQ(to_string(PassStage::pixel), "pixel");
  for (std::string_view type : {"FragmentShader", "texture", "shader", "VertexShaders"})
    EXPECT_EQ(shader_type_stage(type), std::nullopt) << type;
}

TEST(StateTable, DocIsCurrent) {
  std::string path = std::string(FXKIT_SOURCE_DIR) + "/docs/states.md";
  std::string expected = render_state_table_markdown();
  if (const char* update = std::getenv("FXKIT_UPDATE_DOCS"); update && *update == '1') {
    std::ofstream(path, std::ios::binary) << expected;
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  // Report the first differing line, not two copies of the whole document.
  std::istringstream have(text.str()), want(expected);
  std::string a, b;
  for (int line = 1; std::getline(want, b); ++line) {
    bool more = static_cast<bool>(std::getline(have, a));
    ASSERT_TRUE(more && a == b) << "docs/states.md:" << line << " is stale (expected '" << b
                                << "'); rerun with FXKIT_UPDATE_DOCS=1";
  }
  EXPECT_FALSE(std::getline(have, a)) << "docs/states.md has extra lines";
}

// Every row says where its value lands; a row fxkit does not apply says why.
TEST(StateTable, EveryRowSaysWhereItLands) {
  for (const StateInfo& s : all_states()) {
    if (s.lands == StateLanding::unsupported || s.lands == StateLanding::fixed_function) {
      EXPECT_FALSE(s.reason.empty()) << s.name;
    } else {
      EXPECT_NE(s.field, StateField::none) << s.name;
    }
    if (s.vulkan == VulkanMeaning::maps_to_vulkan) {
      EXPECT_NE(s.lands, StateLanding::unsupported) << s.name;
    }
    if (s.vulkan == VulkanMeaning::fixed_function) {
      EXPECT_EQ(s.lands, StateLanding::fixed_function) << s.name;
    }
    if (s.field != StateField::none && s.lands != StateLanding::fixed_function) {
      EXPECT_EQ(s.lands, landing_of(s.field)) << s.name;
    }
  }
  EXPECT_EQ(find_state("ZWriteEnable", StateBlock::pass)->field, StateField::depth_write);
  EXPECT_EQ(find_state("DepthWriteMask", StateBlock::depth_stencil_state)->field, StateField::depth_write);
  const StateInfo& set_blend = *find_state("SetBlendState", StateBlock::pass);
  EXPECT_EQ(set_blend.call_fields[0], StateField::blend_constants);
  EXPECT_EQ(set_blend.call_fields[1], StateField::sample_mask);
  EXPECT_EQ(find_state("StencilRef", StateBlock::pass)->lands, StateLanding::dynamic);
  EXPECT_EQ(to_string(StateField::stage_alpha_op), "stage_alpha_op");
  EXPECT_NE(find_state("DitherEnable", StateBlock::pass)->reason, "");
}

}  // namespace
}  // namespace fx
