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
using F = StateField;

constexpr StateInfo row(std::string_view name, StateBlock block, T type, M meaning, A area, F field,
                        const EnumSet* enums = nullptr, uint16_t index_count = 0, bool index_required = false) {
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
  s.field = field;
  s.lands = landing_of(field);
  return s;
}

// A render state set in a pass, with a direct Vulkan equivalent.
constexpr StateInfo rs(std::string_view name, T type, A area, F field, const EnumSet* enums = nullptr) {
  return row(name, StateBlock::pass, type, M::maps_to_vulkan, area, field, enums);
}
// A render state indexed by plane, stage or render target.
constexpr StateInfo rsi(std::string_view name, T type, A area, F field, uint16_t count,
                        const EnumSet* enums = nullptr) {
  return row(name, StateBlock::pass, type, M::maps_to_vulkan, area, field, enums, count);
}
// The colour write mask of one render target: `ColorWriteEnable1` writes target 1.
constexpr StateInfo write_mask(std::string_view name, uint8_t target, uint16_t count = 0) {
  StateInfo s = rsi(name, T::flags, A::color_blend, F::write_mask, count, &kColorWrite);
  s.target = target;
  return s;
}
// A render state Vulkan lacks that fxkit reproduces (alpha test as a discard, sRGB views).
constexpr StateInfo emulated(std::string_view name, T type, A area, F field, const EnumSet* enums = nullptr) {
  return row(name, StateBlock::pass, type, M::emulated, area, field, enums);
}
// A state fxkit parses and checks but never applies, and why.
constexpr StateInfo unsupported(std::string_view name, T type, M meaning, A area, std::string_view reason,
                                uint16_t count = 0) {
  StateInfo s = row(name, StateBlock::pass, type, meaning, area, F::none, nullptr, count);
  s.reason = reason;
  return s;
}
// A shader state: the code of `stage` (`compile ps_2_0 PS()`, `asm { }`, GLSL blocks).
constexpr StateInfo shader(std::string_view name, PassStage stage) {
  StateInfo s = rs(name, T::shader, A::shader_stage, F::shader);
  s.stage = stage;
  return s;
}
// Fixed-function state (texture stages, fog, lighting, transforms): parsed, never applied.
constexpr StateInfo ff(std::string_view name, T type, const EnumSet* enums = nullptr, uint16_t count = 0,
                       F field = F::none) {
  StateInfo s = row(name, StateBlock::pass, type, M::fixed_function, A::none, field, enums, count);
  s.lands = StateLanding::fixed_function;
  s.reason = "Direct3D 9 fixed-function state with no Vulkan equivalent; use a pixel shader";
  return s;
}
// Texture-stage state: `ColorOp[0..7]`.
constexpr StateInfo stage(std::string_view name, T type, const EnumSet* enums = nullptr, F field = F::none) {
  return ff(name, type, enums, 8, field);
}
// Shader constant registers: the index is the first register and is required.
constexpr StateInfo constants(std::string_view name, uint16_t registers) {
  return row(name, StateBlock::pass, T::shader_constant, M::maps_to_vulkan, A::shader_constants, F::shader_constants,
             nullptr, registers, true);
}
// `StateBlock = <sb>;` applies the states of `stateblock sb = stateblock_state { ... };`,
// which fxkit expands into the pass rather than recording a D3D9 state block.
constexpr StateInfo state_block_row() {
  StateInfo s = row("StateBlock", StateBlock::pass, T::state_object, M::emulated, A::none, F::state_object);
  s.object_kind = "stateblock";
  return s;
}
constexpr StateInfo sampler(std::string_view name, T type, M meaning, F field, const EnumSet* enums = nullptr) {
  return row(name, StateBlock::sampler_state, type, meaning, A::sampler, field, enums);
}
constexpr StateInfo sampler_unsupported(std::string_view name, T type, std::string_view reason) {
  StateInfo s = row(name, StateBlock::sampler_state, type, M::ignored, A::sampler, F::none);
  s.reason = reason;
  return s;
}

}  // namespace

std::span<const StateInfo> d3d9_pass_states() {
  static const StateInfo rows[] = {
      // Depth and stencil.
      rs("ZEnable", T::enumeration, A::depth_stencil, F::depth_test, &kZBuffer),
      rs("ZWriteEnable", T::boolean, A::depth_stencil, F::depth_write),
      rs("ZFunc", T::enumeration, A::depth_stencil, F::depth_compare, &kCompare),
      rs("StencilEnable", T::boolean, A::depth_stencil, F::stencil_test),
      rs("StencilFail", T::enumeration, A::depth_stencil, F::stencil_front_fail, &kStencilOp),
      rs("StencilZFail", T::enumeration, A::depth_stencil, F::stencil_front_depth_fail, &kStencilOp),
      rs("StencilPass", T::enumeration, A::depth_stencil, F::stencil_front_pass, &kStencilOp),
      rs("StencilFunc", T::enumeration, A::depth_stencil, F::stencil_front_compare, &kCompare),
      rs("StencilRef", T::integer, A::depth_stencil, F::stencil_ref),
      rs("StencilMask", T::integer, A::depth_stencil, F::stencil_read_mask),
      rs("StencilWriteMask", T::integer, A::depth_stencil, F::stencil_write_mask),
      rs("TwoSidedStencilMode", T::boolean, A::depth_stencil, F::stencil_two_sided),
      rs("CCW_StencilFail", T::enumeration, A::depth_stencil, F::stencil_back_fail, &kStencilOp),
      rs("CCW_StencilZFail", T::enumeration, A::depth_stencil, F::stencil_back_depth_fail, &kStencilOp),
      rs("CCW_StencilPass", T::enumeration, A::depth_stencil, F::stencil_back_pass, &kStencilOp),
      rs("CCW_StencilFunc", T::enumeration, A::depth_stencil, F::stencil_back_compare, &kCompare),
      // Rasterization.
      rs("FillMode", T::enumeration, A::rasterization, F::fill, &kFill9),
      rs("CullMode", T::enumeration, A::rasterization, F::cull, &kCull9),
      rs("DepthBias", T::floating, A::rasterization, F::depth_bias_d3d9),
      rs("SlopeScaleDepthBias", T::floating, A::rasterization, F::depth_bias_slope),
      rs("ScissorTestEnable", T::boolean, A::rasterization, F::scissor),
      rs("AntialiasedLineEnable", T::boolean, A::rasterization, F::antialiased_lines),
      // Clip planes become gl_ClipDistance writes the shader must make.
      unsupported("ClipPlaneEnable", T::flags, M::emulated, A::rasterization,
                  "the vertex shader writes gl_ClipDistance itself; the pass state is not applied"),
      unsupported("ClipPlane", T::float4, M::emulated, A::shader_constants,
                  "the vertex shader writes gl_ClipDistance itself; the pass state is not applied", 6),
      unsupported("Clipping", T::boolean, M::ignored, A::none, "Vulkan always clips to the view volume"),
      unsupported("LastPixel", T::boolean, M::ignored, A::none, "Vulkan has no last-pixel rule to switch off"),
      unsupported("DitherEnable", T::boolean, M::ignored, A::none, "Vulkan has no dither state"),
      // Blending and output.
      rs("AlphaBlendEnable", T::boolean, A::color_blend, F::blend_enable),
      rs("SrcBlend", T::enumeration, A::color_blend, F::src_color, &kBlend),
      rs("DestBlend", T::enumeration, A::color_blend, F::dst_color, &kBlend),
      rs("BlendOp", T::enumeration, A::color_blend, F::color_op, &kBlendOp),
      rs("SeparateAlphaBlendEnable", T::boolean, A::color_blend, F::separate_alpha),
      rs("SrcBlendAlpha", T::enumeration, A::color_blend, F::src_alpha, &kBlend),
      rs("DestBlendAlpha", T::enumeration, A::color_blend, F::dst_alpha, &kBlend),
      rs("BlendOpAlpha", T::enumeration, A::color_blend, F::alpha_op, &kBlendOp),
      rs("BlendFactor", T::color, A::color_blend, F::blend_constants),
      write_mask("ColorWriteEnable", 0, 4),
      write_mask("ColorWriteEnable1", 1),
      write_mask("ColorWriteEnable2", 2),
      write_mask("ColorWriteEnable3", 3),
      // sRGB writes select an sRGB attachment view; alpha test becomes a discard.
      emulated("SRGBWriteEnable", T::boolean, A::color_blend, F::srgb_write),
      emulated("AlphaTestEnable", T::boolean, A::shader_stage, F::alpha_test),
      emulated("AlphaFunc", T::enumeration, A::shader_stage, F::alpha_compare, &kCompare),
      emulated("AlphaRef", T::integer, A::shader_stage, F::alpha_ref),
      rs("MultiSampleAntialias", T::boolean, A::multisample, F::multisample),
      rs("MultiSampleMask", T::integer, A::multisample, F::sample_mask),
      // Shaders, constants and resources.
      shader("VertexShader", PassStage::vertex),
      shader("PixelShader", PassStage::pixel),
      // The GLSL blocks' spellings (`FragmentShader = { Common, HairFS };`), and nvFX's.
      shader("FragmentShader", PassStage::pixel),
      shader("VertexProgram", PassStage::vertex),
      shader("FragmentProgram", PassStage::pixel),
      shader("GeometryProgram", PassStage::geometry),
      shader("ComputeProgram", PassStage::compute),
      constants("VertexShaderConstant", 256),
      constants("VertexShaderConstantF", 256),
      constants("VertexShaderConstantB", 16),
      constants("VertexShaderConstantI", 16),
      constants("VertexShaderConstant1", 256),
      constants("VertexShaderConstant2", 256),
      constants("VertexShaderConstant3", 256),
      constants("VertexShaderConstant4", 256),
      constants("PixelShaderConstant", 224),
      constants("PixelShaderConstantF", 224),
      constants("PixelShaderConstantB", 16),
      constants("PixelShaderConstantI", 16),
      constants("PixelShaderConstant1", 224),
      constants("PixelShaderConstant2", 224),
      constants("PixelShaderConstant3", 224),
      constants("PixelShaderConstant4", 224),
      rsi("Texture", T::texture, A::resource_binding, F::texture, kSamplerStages),
      rsi("Sampler", T::sampler, A::resource_binding, F::sampler, kSamplerStages),
      unsupported("FVF", T::integer, M::ignored, A::input_assembly, "the vertex layout comes from the shader's inputs"),
      state_block_row(),
      // Cylindrical texture-coordinate wrapping per coordinate set.
      ff("Wrap0", T::flags, &kWrap),
      ff("Wrap1", T::flags, &kWrap),
      ff("Wrap2", T::flags, &kWrap),
      ff("Wrap3", T::flags, &kWrap),
      ff("Wrap4", T::flags, &kWrap),
      ff("Wrap5", T::flags, &kWrap),
      ff("Wrap6", T::flags, &kWrap),
      ff("Wrap7", T::flags, &kWrap),
      ff("Wrap8", T::flags, &kWrap),
      ff("Wrap9", T::flags, &kWrap),
      ff("Wrap10", T::flags, &kWrap),
      ff("Wrap11", T::flags, &kWrap),
      ff("Wrap12", T::flags, &kWrap),
      ff("Wrap13", T::flags, &kWrap),
      ff("Wrap14", T::flags, &kWrap),
      ff("Wrap15", T::flags, &kWrap),
      // Fixed-function shading, fog and lighting.
      ff("ShadeMode", T::enumeration, &kShade),
      ff("FogEnable", T::boolean),
      ff("FogColor", T::color),
      ff("FogTableMode", T::enumeration, &kFogMode),
      ff("FogVertexMode", T::enumeration, &kFogMode),
      ff("FogStart", T::floating),
      ff("FogEnd", T::floating),
      ff("FogDensity", T::floating),
      ff("RangeFogEnable", T::boolean),
      ff("Lighting", T::boolean),
      ff("Ambient", T::color),
      ff("SpecularEnable", T::boolean),
      ff("ColorVertex", T::boolean),
      ff("LocalViewer", T::boolean),
      ff("NormalizeNormals", T::boolean),
      ff("DiffuseMaterialSource", T::enumeration, &kMaterialSource),
      ff("SpecularMaterialSource", T::enumeration, &kMaterialSource),
      ff("AmbientMaterialSource", T::enumeration, &kMaterialSource),
      ff("EmissiveMaterialSource", T::enumeration, &kMaterialSource),
      ff("VertexBlend", T::enumeration, &kVertexBlend),
      ff("IndexedVertexBlendEnable", T::boolean),
      ff("TweenFactor", T::floating),
      ff("TextureFactor", T::color),
      ff("PointSize", T::floating),
      ff("PointSize_Min", T::floating),
      ff("PointSize_Max", T::floating),
      ff("PointSpriteEnable", T::boolean),
      ff("PointScaleEnable", T::boolean),
      ff("PointScale_A", T::floating),
      ff("PointScale_B", T::floating),
      ff("PointScale_C", T::floating),
      // N-patch and adaptive tessellation (D3D9 fixed function).
      ff("PatchEdgeStyle", T::enumeration, &kPatchEdge),
      ff("PositionDegree", T::enumeration, &kDegree),
      ff("NormalDegree", T::enumeration, &kDegree),
      ff("EnableAdaptiveTessellation", T::boolean),
      ff("MinTessellationLevel", T::floating),
      ff("MaxTessellationLevel", T::floating),
      ff("AdaptiveTess_X", T::floating),
      ff("AdaptiveTess_Y", T::floating),
      ff("AdaptiveTess_Z", T::floating),
      ff("AdaptiveTess_W", T::floating),
      // Transforms, lights and material.
      ff("WorldTransform", T::matrix, nullptr, 256),
      ff("ViewTransform", T::matrix),
      ff("ProjectionTransform", T::matrix),
      ff("TextureTransform", T::matrix, nullptr, 8),
      ff("LightEnable", T::boolean, nullptr, 8),
      ff("LightType", T::enumeration, &kLightType, 8),
      ff("LightDiffuse", T::float4, nullptr, 8),
      ff("LightSpecular", T::float4, nullptr, 8),
      ff("LightAmbient", T::float4, nullptr, 8),
      ff("LightPosition", T::float4, nullptr, 8),
      ff("LightDirection", T::float4, nullptr, 8),
      ff("LightRange", T::floating, nullptr, 8),
      ff("LightFalloff", T::floating, nullptr, 8),
      ff("LightAttenuation0", T::floating, nullptr, 8),
      ff("LightAttenuation1", T::floating, nullptr, 8),
      ff("LightAttenuation2", T::floating, nullptr, 8),
      ff("LightTheta", T::floating, nullptr, 8),
      ff("LightPhi", T::floating, nullptr, 8),
      ff("MaterialDiffuse", T::float4),
      ff("MaterialAmbient", T::float4),
      ff("MaterialSpecular", T::float4),
      ff("MaterialEmissive", T::float4),
      ff("MaterialPower", T::floating),
      // Texture stages.
      stage("ColorOp", T::enumeration, &kTextureOp, F::stage_color_op),
      stage("ColorArg0", T::flags, &kTextureArg),
      stage("ColorArg1", T::flags, &kTextureArg),
      stage("ColorArg2", T::flags, &kTextureArg),
      stage("AlphaOp", T::enumeration, &kTextureOp, F::stage_alpha_op),
      stage("AlphaArg0", T::flags, &kTextureArg),
      stage("AlphaArg1", T::flags, &kTextureArg),
      stage("AlphaArg2", T::flags, &kTextureArg),
      stage("ResultArg", T::flags, &kTextureArg),
      stage("BumpEnvMat00", T::floating),
      stage("BumpEnvMat01", T::floating),
      stage("BumpEnvMat10", T::floating),
      stage("BumpEnvMat11", T::floating),
      stage("BumpEnvLScale", T::floating),
      stage("BumpEnvLOffset", T::floating),
      stage("TexCoordIndex", T::flags, &kTexCoordIndex),
      stage("TextureTransformFlags", T::flags, &kTextureTransform),
      stage("Constant", T::color),
#ifdef FXKIT_EXTRA_PASS_STATE_ROWS  // tests/state_row: one more row, to show one row is enough
#include FXKIT_EXTRA_PASS_STATE_ROWS
#endif
  };
  return rows;
}

std::span<const StateInfo> d3d9_sampler_states() {
  static const StateInfo rows[] = {
      row("Texture", StateBlock::sampler_state, T::texture, M::maps_to_vulkan, A::resource_binding, F::texture),
      sampler("AddressU", T::enumeration, M::maps_to_vulkan, F::address_u, &kTextureAddress),
      sampler("AddressV", T::enumeration, M::maps_to_vulkan, F::address_v, &kTextureAddress),
      sampler("AddressW", T::enumeration, M::maps_to_vulkan, F::address_w, &kTextureAddress),
      sampler("BorderColor", T::color, M::maps_to_vulkan, F::border_color),
      sampler("MagFilter", T::enumeration, M::maps_to_vulkan, F::mag_filter, &kTextureFilter),
      sampler("MinFilter", T::enumeration, M::maps_to_vulkan, F::min_filter, &kTextureFilter),
      sampler("MipFilter", T::enumeration, M::maps_to_vulkan, F::mip_filter, &kTextureFilter),
      sampler("MipMapLodBias", T::floating, M::maps_to_vulkan, F::lod_bias),
      sampler("MaxMipLevel", T::integer, M::maps_to_vulkan, F::max_mip_level),
      sampler("MaxAnisotropy", T::integer, M::maps_to_vulkan, F::max_anisotropy),
      // sRGB decoding is a property of the image view format on Vulkan.
      sampler("SRGBTexture", T::boolean, M::emulated, F::srgb_texture),
      sampler_unsupported("ElementIndex", T::integer, "multi-element textures do not exist on Vulkan"),
      sampler_unsupported("DMapOffset", T::integer, "displacement-map sampling does not exist on Vulkan"),
  };
  return rows;
}

}  // namespace fx::state_data
