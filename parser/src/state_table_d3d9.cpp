// Direct3D 9 effect states: render states, texture-stage states, transforms, lights,
// materials, shaders and shader constants in passes, and sampler states. Names follow the
// D3DX effect spelling (D3DRS_ZENABLE -> ZEnable). The Vulkan meaning says what the runtime
// can do with each: the fixed-function pipeline has no Vulkan equivalent.
#include "state_table_data.h"

namespace fx::state_data {
namespace {

using T = StateValueType;
using M = VulkanMeaning;
using A = VulkanArea;

constexpr StateInfo row(std::string_view name, StateBlock block, T type, M meaning, A area,
                        const EnumSet* enums = nullptr, uint16_t index_count = 0,
                        bool index_required = false) {
  StateInfo s;
  s.name = name;
  s.block = block;
  s.type = type;
  s.enums = enums;
  s.index_count = index_count;
  s.index_required = index_required;
  s.api = StateApi::d3d9;
  s.vulkan = meaning;
  s.area = area;
  return s;
}

// A render state set in a pass.
constexpr StateInfo rs(std::string_view name, T type, M meaning, A area,
                       const EnumSet* enums = nullptr) {
  return row(name, StateBlock::pass, type, meaning, area, enums);
}
// A render state indexed by light, plane, stage or register.
constexpr StateInfo rsi(std::string_view name, T type, M meaning, A area, uint16_t count,
                        const EnumSet* enums = nullptr, bool required = false) {
  return row(name, StateBlock::pass, type, meaning, area, enums, count, required);
}
// A shader state: the code of `stage` (`compile ps_2_0 PS()`, `asm { }`, GLSL blocks).
constexpr StateInfo shader(std::string_view name, PassStage stage) {
  StateInfo s = rs(name, T::shader, M::maps_to_vulkan, A::shader_stage);
  s.stage = stage;
  return s;
}
// Fixed-function state (texture stages, fog, lighting, transforms): parsed, never applied.
constexpr StateInfo ff(std::string_view name, T type, const EnumSet* enums = nullptr,
                       uint16_t count = 0) {
  return row(name, StateBlock::pass, type, M::fixed_function, A::none, enums, count);
}
// Texture-stage state: `ColorOp[0..7]`.
constexpr StateInfo stage(std::string_view name, T type, const EnumSet* enums = nullptr) {
  return ff(name, type, enums, 8);
}
// Shader constant registers: the index is the first register and is required.
constexpr StateInfo constants(std::string_view name, uint16_t registers) {
  return row(name, StateBlock::pass, T::shader_constant, M::maps_to_vulkan,
             A::shader_constants, nullptr, registers, true);
}
// `StateBlock = <sb>;` applies the states of `stateblock sb = stateblock_state { ... };`,
// which fxkit expands into the pass rather than recording a D3D9 state block.
constexpr StateInfo state_block_row() {
  StateInfo s = rs("StateBlock", T::state_object, M::emulated, A::none);
  s.object_kind = "stateblock";
  return s;
}
constexpr StateInfo sampler(std::string_view name, T type, M meaning,
                            const EnumSet* enums = nullptr) {
  return row(name, StateBlock::sampler_state, type, meaning, A::sampler, enums);
}

}  // namespace

std::span<const StateInfo> d3d9_pass_states() {
  static const StateInfo rows[] = {
      // Depth and stencil.
      rs("ZEnable", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kZBuffer),
      rs("ZWriteEnable", T::boolean, M::maps_to_vulkan, A::depth_stencil),
      rs("ZFunc", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kCompare),
      rs("StencilEnable", T::boolean, M::maps_to_vulkan, A::depth_stencil),
      rs("StencilFail", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kStencilOp),
      rs("StencilZFail", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kStencilOp),
      rs("StencilPass", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kStencilOp),
      rs("StencilFunc", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kCompare),
      rs("StencilRef", T::integer, M::maps_to_vulkan, A::depth_stencil),
      rs("StencilMask", T::integer, M::maps_to_vulkan, A::depth_stencil),
      rs("StencilWriteMask", T::integer, M::maps_to_vulkan, A::depth_stencil),
      rs("TwoSidedStencilMode", T::boolean, M::maps_to_vulkan, A::depth_stencil),
      rs("CCW_StencilFail", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kStencilOp),
      rs("CCW_StencilZFail", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kStencilOp),
      rs("CCW_StencilPass", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kStencilOp),
      rs("CCW_StencilFunc", T::enumeration, M::maps_to_vulkan, A::depth_stencil, &kCompare),
      // Rasterization.
      rs("FillMode", T::enumeration, M::maps_to_vulkan, A::rasterization, &kFill9),
      rs("CullMode", T::enumeration, M::maps_to_vulkan, A::rasterization, &kCull9),
      rs("DepthBias", T::floating, M::maps_to_vulkan, A::rasterization),
      rs("SlopeScaleDepthBias", T::floating, M::maps_to_vulkan, A::rasterization),
      rs("ScissorTestEnable", T::boolean, M::maps_to_vulkan, A::rasterization),
      rs("AntialiasedLineEnable", T::boolean, M::maps_to_vulkan, A::rasterization),
      // Clip planes become gl_ClipDistance writes the shader must make.
      rs("ClipPlaneEnable", T::flags, M::emulated, A::rasterization),
      rsi("ClipPlane", T::float4, M::emulated, A::shader_constants, 6),
      rs("Clipping", T::boolean, M::ignored, A::none),
      rs("LastPixel", T::boolean, M::ignored, A::none),
      rs("DitherEnable", T::boolean, M::ignored, A::none),
      // Blending and output.
      rs("AlphaBlendEnable", T::boolean, M::maps_to_vulkan, A::color_blend),
      rs("SrcBlend", T::enumeration, M::maps_to_vulkan, A::color_blend, &kBlend),
      rs("DestBlend", T::enumeration, M::maps_to_vulkan, A::color_blend, &kBlend),
      rs("BlendOp", T::enumeration, M::maps_to_vulkan, A::color_blend, &kBlendOp),
      rs("SeparateAlphaBlendEnable", T::boolean, M::maps_to_vulkan, A::color_blend),
      rs("SrcBlendAlpha", T::enumeration, M::maps_to_vulkan, A::color_blend, &kBlend),
      rs("DestBlendAlpha", T::enumeration, M::maps_to_vulkan, A::color_blend, &kBlend),
      rs("BlendOpAlpha", T::enumeration, M::maps_to_vulkan, A::color_blend, &kBlendOp),
      rs("BlendFactor", T::color, M::maps_to_vulkan, A::color_blend),
      rsi("ColorWriteEnable", T::flags, M::maps_to_vulkan, A::color_blend, 4, &kColorWrite),
      rs("ColorWriteEnable1", T::flags, M::maps_to_vulkan, A::color_blend, &kColorWrite),
      rs("ColorWriteEnable2", T::flags, M::maps_to_vulkan, A::color_blend, &kColorWrite),
      rs("ColorWriteEnable3", T::flags, M::maps_to_vulkan, A::color_blend, &kColorWrite),
      // sRGB writes select an sRGB attachment view; alpha test becomes a discard.
      rs("SRGBWriteEnable", T::boolean, M::emulated, A::color_blend),
      rs("AlphaTestEnable", T::boolean, M::emulated, A::shader_stage),
      rs("AlphaFunc", T::enumeration, M::emulated, A::shader_stage, &kCompare),
      rs("AlphaRef", T::integer, M::emulated, A::shader_stage),
      rs("MultiSampleAntialias", T::boolean, M::maps_to_vulkan, A::multisample),
      rs("MultiSampleMask", T::integer, M::maps_to_vulkan, A::multisample),
      // Shaders, constants and resources.
      shader("VertexShader", PassStage::vertex),
      shader("PixelShader", PassStage::pixel),
      // The GLSL blocks' spellings (`FragmentShader = { Common, HairFS };`), and nvFX's.
      shader("FragmentShader", PassStage::pixel),
      shader("VertexProgram", PassStage::vertex),
      shader("FragmentProgram", PassStage::pixel),
      shader("GeometryProgram", PassStage::geometry),
      shader("ComputeProgram", PassStage::compute),
      constants("VertexShaderConstant", 256), constants("VertexShaderConstantF", 256),
      constants("VertexShaderConstantB", 16), constants("VertexShaderConstantI", 16),
      constants("VertexShaderConstant1", 256), constants("VertexShaderConstant2", 256),
      constants("VertexShaderConstant3", 256), constants("VertexShaderConstant4", 256),
      constants("PixelShaderConstant", 224), constants("PixelShaderConstantF", 224),
      constants("PixelShaderConstantB", 16), constants("PixelShaderConstantI", 16),
      constants("PixelShaderConstant1", 224), constants("PixelShaderConstant2", 224),
      constants("PixelShaderConstant3", 224), constants("PixelShaderConstant4", 224),
      rsi("Texture", T::texture, M::maps_to_vulkan, A::resource_binding, kSamplerStages),
      rsi("Sampler", T::sampler, M::maps_to_vulkan, A::resource_binding, kSamplerStages),
      rs("FVF", T::integer, M::ignored, A::input_assembly),
      state_block_row(),
      // Cylindrical texture-coordinate wrapping per coordinate set.
      ff("Wrap0", T::flags, &kWrap), ff("Wrap1", T::flags, &kWrap), ff("Wrap2", T::flags, &kWrap),
      ff("Wrap3", T::flags, &kWrap), ff("Wrap4", T::flags, &kWrap), ff("Wrap5", T::flags, &kWrap),
      ff("Wrap6", T::flags, &kWrap), ff("Wrap7", T::flags, &kWrap), ff("Wrap8", T::flags, &kWrap),
      ff("Wrap9", T::flags, &kWrap), ff("Wrap10", T::flags, &kWrap),
      ff("Wrap11", T::flags, &kWrap), ff("Wrap12", T::flags, &kWrap),
      ff("Wrap13", T::flags, &kWrap), ff("Wrap14", T::flags, &kWrap),
      ff("Wrap15", T::flags, &kWrap),
      // Fixed-function shading, fog and lighting.
      ff("ShadeMode", T::enumeration, &kShade),
      ff("FogEnable", T::boolean), ff("FogColor", T::color),
      ff("FogTableMode", T::enumeration, &kFogMode), ff("FogVertexMode", T::enumeration, &kFogMode),
      ff("FogStart", T::floating), ff("FogEnd", T::floating), ff("FogDensity", T::floating),
      ff("RangeFogEnable", T::boolean),
      ff("Lighting", T::boolean), ff("Ambient", T::color), ff("SpecularEnable", T::boolean),
      ff("ColorVertex", T::boolean), ff("LocalViewer", T::boolean),
      ff("NormalizeNormals", T::boolean),
      ff("DiffuseMaterialSource", T::enumeration, &kMaterialSource),
      ff("SpecularMaterialSource", T::enumeration, &kMaterialSource),
      ff("AmbientMaterialSource", T::enumeration, &kMaterialSource),
      ff("EmissiveMaterialSource", T::enumeration, &kMaterialSource),
      ff("VertexBlend", T::enumeration, &kVertexBlend),
      ff("IndexedVertexBlendEnable", T::boolean), ff("TweenFactor", T::floating),
      ff("TextureFactor", T::color),
      ff("PointSize", T::floating), ff("PointSize_Min", T::floating),
      ff("PointSize_Max", T::floating), ff("PointSpriteEnable", T::boolean),
      ff("PointScaleEnable", T::boolean), ff("PointScale_A", T::floating),
      ff("PointScale_B", T::floating), ff("PointScale_C", T::floating),
      // N-patch and adaptive tessellation (D3D9 fixed function).
      ff("PatchEdgeStyle", T::enumeration, &kPatchEdge),
      ff("PositionDegree", T::enumeration, &kDegree), ff("NormalDegree", T::enumeration, &kDegree),
      ff("EnableAdaptiveTessellation", T::boolean),
      ff("MinTessellationLevel", T::floating), ff("MaxTessellationLevel", T::floating),
      ff("AdaptiveTess_X", T::floating), ff("AdaptiveTess_Y", T::floating),
      ff("AdaptiveTess_Z", T::floating), ff("AdaptiveTess_W", T::floating),
      // Transforms, lights and material.
      ff("WorldTransform", T::matrix, nullptr, 256), ff("ViewTransform", T::matrix),
      ff("ProjectionTransform", T::matrix), ff("TextureTransform", T::matrix, nullptr, 8),
      ff("LightEnable", T::boolean, nullptr, 8), ff("LightType", T::enumeration, &kLightType, 8),
      ff("LightDiffuse", T::float4, nullptr, 8), ff("LightSpecular", T::float4, nullptr, 8),
      ff("LightAmbient", T::float4, nullptr, 8), ff("LightPosition", T::float4, nullptr, 8),
      ff("LightDirection", T::float4, nullptr, 8), ff("LightRange", T::floating, nullptr, 8),
      ff("LightFalloff", T::floating, nullptr, 8),
      ff("LightAttenuation0", T::floating, nullptr, 8),
      ff("LightAttenuation1", T::floating, nullptr, 8),
      ff("LightAttenuation2", T::floating, nullptr, 8), ff("LightTheta", T::floating, nullptr, 8),
      ff("LightPhi", T::floating, nullptr, 8),
      ff("MaterialDiffuse", T::float4), ff("MaterialAmbient", T::float4),
      ff("MaterialSpecular", T::float4), ff("MaterialEmissive", T::float4),
      ff("MaterialPower", T::floating),
      // Texture stages.
      stage("ColorOp", T::enumeration, &kTextureOp), stage("ColorArg0", T::flags, &kTextureArg),
      stage("ColorArg1", T::flags, &kTextureArg), stage("ColorArg2", T::flags, &kTextureArg),
      stage("AlphaOp", T::enumeration, &kTextureOp), stage("AlphaArg0", T::flags, &kTextureArg),
      stage("AlphaArg1", T::flags, &kTextureArg), stage("AlphaArg2", T::flags, &kTextureArg),
      stage("ResultArg", T::flags, &kTextureArg),
      stage("BumpEnvMat00", T::floating), stage("BumpEnvMat01", T::floating),
      stage("BumpEnvMat10", T::floating), stage("BumpEnvMat11", T::floating),
      stage("BumpEnvLScale", T::floating), stage("BumpEnvLOffset", T::floating),
      stage("TexCoordIndex", T::flags, &kTexCoordIndex),
      stage("TextureTransformFlags", T::flags, &kTextureTransform),
      stage("Constant", T::color),
  };
  return rows;
}

std::span<const StateInfo> d3d9_sampler_states() {
  static const StateInfo rows[] = {
      row("Texture", StateBlock::sampler_state, T::texture, M::maps_to_vulkan,
          A::resource_binding),
      sampler("AddressU", T::enumeration, M::maps_to_vulkan, &kTextureAddress),
      sampler("AddressV", T::enumeration, M::maps_to_vulkan, &kTextureAddress),
      sampler("AddressW", T::enumeration, M::maps_to_vulkan, &kTextureAddress),
      sampler("BorderColor", T::color, M::maps_to_vulkan),
      sampler("MagFilter", T::enumeration, M::maps_to_vulkan, &kTextureFilter),
      sampler("MinFilter", T::enumeration, M::maps_to_vulkan, &kTextureFilter),
      sampler("MipFilter", T::enumeration, M::maps_to_vulkan, &kTextureFilter),
      sampler("MipMapLodBias", T::floating, M::maps_to_vulkan),
      sampler("MaxMipLevel", T::integer, M::maps_to_vulkan),
      sampler("MaxAnisotropy", T::integer, M::maps_to_vulkan),
      // sRGB decoding is a property of the image view format on Vulkan.
      sampler("SRGBTexture", T::boolean, M::emulated),
      sampler("ElementIndex", T::integer, M::ignored),
      sampler("DMapOffset", T::integer, M::ignored),
  };
  return rows;
}

}  // namespace fx::state_data
