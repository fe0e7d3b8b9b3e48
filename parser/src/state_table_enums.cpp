// Enumeration sets of the state table. Values are the Direct3D numeric values, so D3D9
// and D3D10/11 spellings that agree (blend factors, comparisons, stencil ops, addressing)
// share one set; where the meaning differs (cull modes: D3D9 culls by winding, D3D10 by
// facing) there are two sets.
#include "state_table_data.h"

namespace fx::state_data {
namespace {

using P = std::string_view;

constexpr EnumValue kBooleanValues[] = {{"FALSE", 0}, {"TRUE", 1}};
constexpr P kNoPrefix[] = {""};

constexpr EnumValue kZBufferValues[] = {{"FALSE", 0}, {"TRUE", 1}, {"USEW", 2}};
constexpr P kZBufferPrefix[] = {"D3DZB_"};

constexpr EnumValue kFill9Values[] = {{"Point", 1}, {"Wireframe", 2}, {"Solid", 3}};
constexpr P kFill9Prefix[] = {"D3DFILL_"};
constexpr EnumValue kFill10Values[] = {{"WIREFRAME", 2}, {"SOLID", 3}};
constexpr P kFill10Prefix[] = {"D3D10_FILL_", "D3D11_FILL_", "FILL_"};

constexpr EnumValue kCull9Values[] = {{"None", 1}, {"CW", 2}, {"CCW", 3}};
constexpr P kCull9Prefix[] = {"D3DCULL_"};
constexpr EnumValue kCull10Values[] = {{"NONE", 1}, {"FRONT", 2}, {"BACK", 3}};
constexpr P kCull10Prefix[] = {"D3D10_CULL_", "D3D11_CULL_", "CULL_"};

constexpr EnumValue kBlendValues[] = {
    {"Zero", 1},          {"One", 2},           {"SrcColor", 3},         {"InvSrcColor", 4},   {"SrcAlpha", 5},
    {"InvSrcAlpha", 6},   {"DestAlpha", 7},     {"InvDestAlpha", 8},     {"DestColor", 9},     {"InvDestColor", 10},
    {"SrcAlphaSat", 11},  {"BothSrcAlpha", 12}, {"BothInvSrcAlpha", 13}, {"BlendFactor", 14},  {"InvBlendFactor", 15},
    {"SrcColor2", 16},    {"InvSrcColor2", 17}, {"Src1Color", 16},       {"InvSrc1Color", 17}, {"Src1Alpha", 18},
    {"InvSrc1Alpha", 19},
};
constexpr P kBlendPrefix[] = {"D3DBLEND_", "D3D10_BLEND_", "D3D11_BLEND_"};

constexpr EnumValue kBlendOpValues[] = {{"Add", 1}, {"Subtract", 2}, {"RevSubtract", 3}, {"Min", 4}, {"Max", 5}};
constexpr P kBlendOpPrefix[] = {"D3DBLENDOP_", "D3D10_BLEND_OP_", "D3D11_BLEND_OP_", "BLEND_OP_"};

constexpr EnumValue kCompareValues[] = {{"Never", 1},   {"Less", 2},     {"Equal", 3},        {"LessEqual", 4},
                                        {"Greater", 5}, {"NotEqual", 6}, {"GreaterEqual", 7}, {"Always", 8}};
constexpr P kComparePrefix[] = {"D3DCMP_", "D3D10_COMPARISON_", "D3D11_COMPARISON_", "COMPARISON_"};

constexpr EnumValue kStencilOpValues[] = {{"Keep", 1},    {"Zero", 2},   {"Replace", 3}, {"IncrSat", 4},
                                          {"DecrSat", 5}, {"Invert", 6}, {"Incr", 7},    {"Decr", 8}};
constexpr P kStencilOpPrefix[] = {"D3DSTENCILOP_", "D3D10_STENCIL_OP_", "D3D11_STENCIL_OP_", "STENCIL_OP_"};

constexpr EnumValue kShadeValues[] = {{"Flat", 1}, {"Gouraud", 2}, {"Phong", 3}};
constexpr P kShadePrefix[] = {"D3DSHADE_"};

constexpr EnumValue kFogModeValues[] = {{"None", 0}, {"Exp", 1}, {"Exp2", 2}, {"Linear", 3}};
constexpr P kFogModePrefix[] = {"D3DFOG_"};

constexpr EnumValue kMaterialSourceValues[] = {{"Material", 0}, {"Color1", 1}, {"Color2", 2}};
constexpr P kMaterialSourcePrefix[] = {"D3DMCS_"};

constexpr EnumValue kVertexBlendValues[] = {{"Disable", 0},  {"1Weights", 1},   {"2Weights", 2},
                                            {"3Weights", 3}, {"Tweening", 255}, {"0Weights", 256}};
constexpr P kVertexBlendPrefix[] = {"D3DVBF_"};

constexpr EnumValue kPatchEdgeValues[] = {{"Discrete", 0}, {"Continuous", 1}};
constexpr P kPatchEdgePrefix[] = {"D3DPATCHEDGE_"};

constexpr EnumValue kDegreeValues[] = {{"Linear", 1}, {"Quadratic", 2}, {"Cubic", 3}, {"Quintic", 5}};
constexpr P kDegreePrefix[] = {"D3DDEGREE_"};

// `None` (no channel) is XNA's ColorWriteChannels.None, which MonoGame's effect compiler
// accepts in a pass (its ParserTest.fx writes `ColorWriteEnable = None;`).
constexpr EnumValue kColorWriteValues[] = {{"Red", 1},   {"Green", 2}, {"Blue", 4},
                                           {"Alpha", 8}, {"All", 15},  {"None", 0}};
constexpr P kColorWritePrefix[] = {"D3DCOLORWRITEENABLE_", "D3D10_COLOR_WRITE_ENABLE_", "D3D11_COLOR_WRITE_ENABLE_",
                                   "COLOR_WRITE_ENABLE_"};

constexpr EnumValue kWrapValues[] = {{"U", 1},      {"V", 2},      {"W", 4},     {"Coord0", 1},
                                     {"Coord1", 2}, {"Coord2", 4}, {"Coord3", 8}};
constexpr P kWrapPrefix[] = {"D3DWRAP_"};

constexpr EnumValue kTextureOpValues[] = {{"Disable", 1},
                                          {"SelectArg1", 2},
                                          {"SelectArg2", 3},
                                          {"Modulate", 4},
                                          {"Modulate2x", 5},
                                          {"Modulate4x", 6},
                                          {"Add", 7},
                                          {"AddSigned", 8},
                                          {"AddSigned2x", 9},
                                          {"Subtract", 10},
                                          {"AddSmooth", 11},
                                          {"BlendDiffuseAlpha", 12},
                                          {"BlendTextureAlpha", 13},
                                          {"BlendFactorAlpha", 14},
                                          {"BlendTextureAlphaPM", 15},
                                          {"BlendCurrentAlpha", 16},
                                          {"PreModulate", 17},
                                          {"ModulateAlpha_AddColor", 18},
                                          {"ModulateColor_AddAlpha", 19},
                                          {"ModulateInvAlpha_AddColor", 20},
                                          {"ModulateInvColor_AddAlpha", 21},
                                          {"BumpEnvMap", 22},
                                          {"BumpEnvMapLuminance", 23},
                                          {"DotProduct3", 24},
                                          {"MultiplyAdd", 25},
                                          {"Lerp", 26}};
constexpr P kTextureOpPrefix[] = {"D3DTOP_"};

constexpr EnumValue kTextureArgValues[] = {{"Diffuse", 0},  {"Current", 1},       {"Texture", 2},
                                           {"TFactor", 3},  {"Specular", 4},      {"Temp", 5},
                                           {"Constant", 6}, {"Complement", 0x10}, {"AlphaReplicate", 0x20}};
constexpr P kTextureArgPrefix[] = {"D3DTA_"};

constexpr EnumValue kTexCoordIndexValues[] = {{"PassThru", 0},
                                              {"CameraSpaceNormal", 0x10000},
                                              {"CameraSpacePosition", 0x20000},
                                              {"CameraSpaceReflectionVector", 0x30000},
                                              {"SphereMap", 0x40000}};
constexpr P kTexCoordIndexPrefix[] = {"D3DTSS_TCI_"};

constexpr EnumValue kTextureTransformValues[] = {{"Disable", 0}, {"Count1", 1}, {"Count2", 2},
                                                 {"Count3", 3},  {"Count4", 4}, {"Projected", 256}};
constexpr P kTextureTransformPrefix[] = {"D3DTTFF_"};

constexpr EnumValue kTextureAddressValues[] = {
    {"Wrap", 1}, {"Mirror", 2}, {"Clamp", 3}, {"Border", 4}, {"MirrorOnce", 5}};
constexpr P kTextureAddressPrefix[] = {"D3DTADDRESS_", "D3D10_TEXTURE_ADDRESS_", "D3D11_TEXTURE_ADDRESS_",
                                       "TEXTURE_ADDRESS_"};

constexpr EnumValue kTextureFilterValues[] = {{"None", 0},           {"Point", 1},         {"Linear", 2},
                                              {"Anisotropic", 3},    {"PyramidalQuad", 6}, {"GaussianQuad", 7},
                                              {"ConvolutionMono", 8}};
constexpr P kTextureFilterPrefix[] = {"D3DTEXF_"};

// D3D11_FILTER: bit 0 mip linear, bit 2 mag linear, bit 4 min linear, 0x55 anisotropic,
// 0x80 comparison, 0x100 minimum, 0x180 maximum reduction.
constexpr EnumValue kFilter11Values[] = {{"MIN_MAG_MIP_POINT", 0x00},
                                         {"MIN_MAG_POINT_MIP_LINEAR", 0x01},
                                         {"MIN_POINT_MAG_LINEAR_MIP_POINT", 0x04},
                                         {"MIN_POINT_MAG_MIP_LINEAR", 0x05},
                                         {"MIN_LINEAR_MAG_MIP_POINT", 0x10},
                                         {"MIN_LINEAR_MAG_POINT_MIP_LINEAR", 0x11},
                                         {"MIN_MAG_LINEAR_MIP_POINT", 0x14},
                                         {"MIN_MAG_MIP_LINEAR", 0x15},
                                         {"ANISOTROPIC", 0x55},
                                         {"COMPARISON_MIN_MAG_MIP_POINT", 0x80},
                                         {"COMPARISON_MIN_MAG_POINT_MIP_LINEAR", 0x81},
                                         {"COMPARISON_MIN_POINT_MAG_LINEAR_MIP_POINT", 0x84},
                                         {"COMPARISON_MIN_POINT_MAG_MIP_LINEAR", 0x85},
                                         {"COMPARISON_MIN_LINEAR_MAG_MIP_POINT", 0x90},
                                         {"COMPARISON_MIN_LINEAR_MAG_POINT_MIP_LINEAR", 0x91},
                                         {"COMPARISON_MIN_MAG_LINEAR_MIP_POINT", 0x94},
                                         {"COMPARISON_MIN_MAG_MIP_LINEAR", 0x95},
                                         {"COMPARISON_ANISOTROPIC", 0xd5},
                                         {"MINIMUM_MIN_MAG_MIP_POINT", 0x100},
                                         {"MINIMUM_MIN_MAG_POINT_MIP_LINEAR", 0x101},
                                         {"MINIMUM_MIN_POINT_MAG_LINEAR_MIP_POINT", 0x104},
                                         {"MINIMUM_MIN_POINT_MAG_MIP_LINEAR", 0x105},
                                         {"MINIMUM_MIN_LINEAR_MAG_MIP_POINT", 0x110},
                                         {"MINIMUM_MIN_LINEAR_MAG_POINT_MIP_LINEAR", 0x111},
                                         {"MINIMUM_MIN_MAG_LINEAR_MIP_POINT", 0x114},
                                         {"MINIMUM_MIN_MAG_MIP_LINEAR", 0x115},
                                         {"MINIMUM_ANISOTROPIC", 0x155},
                                         {"MAXIMUM_MIN_MAG_MIP_POINT", 0x180},
                                         {"MAXIMUM_MIN_MAG_POINT_MIP_LINEAR", 0x181},
                                         {"MAXIMUM_MIN_POINT_MAG_LINEAR_MIP_POINT", 0x184},
                                         {"MAXIMUM_MIN_POINT_MAG_MIP_LINEAR", 0x185},
                                         {"MAXIMUM_MIN_LINEAR_MAG_MIP_POINT", 0x190},
                                         {"MAXIMUM_MIN_LINEAR_MAG_POINT_MIP_LINEAR", 0x191},
                                         {"MAXIMUM_MIN_MAG_LINEAR_MIP_POINT", 0x194},
                                         {"MAXIMUM_MIN_MAG_MIP_LINEAR", 0x195},
                                         {"MAXIMUM_ANISOTROPIC", 0x1d5}};
constexpr P kFilter11Prefix[] = {"D3D10_FILTER_", "D3D11_FILTER_", "FILTER_"};

constexpr EnumValue kDepthWriteMaskValues[] = {{"ZERO", 0}, {"ALL", 1}};
constexpr P kDepthWriteMaskPrefix[] = {"D3D10_DEPTH_WRITE_MASK_", "D3D11_DEPTH_WRITE_MASK_", "DEPTH_WRITE_MASK_"};

constexpr EnumValue kLightTypeValues[] = {{"Point", 1}, {"Spot", 2}, {"Directional", 3}};
constexpr P kLightTypePrefix[] = {"D3DLIGHT_"};

}  // namespace

const EnumSet kBoolean{"bool", kBooleanValues, kNoPrefix};
const EnumSet kZBuffer{"zbuffer", kZBufferValues, kZBufferPrefix};
const EnumSet kFill9{"fill", kFill9Values, kFill9Prefix};
const EnumSet kFill10{"fill10", kFill10Values, kFill10Prefix};
const EnumSet kCull9{"cull", kCull9Values, kCull9Prefix};
const EnumSet kCull10{"cull10", kCull10Values, kCull10Prefix};
const EnumSet kBlend{"blend", kBlendValues, kBlendPrefix};
const EnumSet kBlendOp{"blendop", kBlendOpValues, kBlendOpPrefix};
const EnumSet kCompare{"cmp", kCompareValues, kComparePrefix};
const EnumSet kStencilOp{"stencilop", kStencilOpValues, kStencilOpPrefix};
const EnumSet kShade{"shade", kShadeValues, kShadePrefix};
const EnumSet kFogMode{"fog", kFogModeValues, kFogModePrefix};
const EnumSet kMaterialSource{"mcs", kMaterialSourceValues, kMaterialSourcePrefix};
const EnumSet kVertexBlend{"vbf", kVertexBlendValues, kVertexBlendPrefix};
const EnumSet kPatchEdge{"patchedge", kPatchEdgeValues, kPatchEdgePrefix};
const EnumSet kDegree{"degree", kDegreeValues, kDegreePrefix};
const EnumSet kColorWrite{"colorwrite", kColorWriteValues, kColorWritePrefix};
const EnumSet kWrap{"wrap", kWrapValues, kWrapPrefix};
const EnumSet kTextureOp{"textureop", kTextureOpValues, kTextureOpPrefix};
const EnumSet kTextureArg{"texturearg", kTextureArgValues, kTextureArgPrefix};
const EnumSet kTexCoordIndex{"tci", kTexCoordIndexValues, kTexCoordIndexPrefix};
const EnumSet kTextureTransform{"ttff", kTextureTransformValues, kTextureTransformPrefix};
const EnumSet kTextureAddress{"address", kTextureAddressValues, kTextureAddressPrefix};
const EnumSet kTextureFilter{"texf", kTextureFilterValues, kTextureFilterPrefix};
const EnumSet kFilter11{"filter", kFilter11Values, kFilter11Prefix};
const EnumSet kDepthWriteMask{"depthwritemask", kDepthWriteMaskValues, kDepthWriteMaskPrefix};
const EnumSet kLightType{"lighttype", kLightTypeValues, kLightTypePrefix};

}  // namespace fx::state_data
