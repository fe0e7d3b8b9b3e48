// Direct3D 10/11 state-object fields (BlendState, DepthStencilState, RasterizerState,
// SamplerState) and the pass calls of technique10/technique11 (SetVertexShader(...),
// SetBlendState(...)). These map onto Vulkan pipeline and sampler state almost one to one.
#include "state_table_data.h"

namespace fx::state_data {
namespace {

using T = StateValueType;
using M = VulkanMeaning;
using A = VulkanArea;

constexpr StateInfo field(std::string_view name, StateBlock block, T type, A area,
                          const EnumSet* enums = nullptr, uint16_t index_count = 0) {
  StateInfo s;
  s.name = name;
  s.block = block;
  s.type = type;
  s.enums = enums;
  s.index_count = index_count;
  s.api = StateApi::d3d10;
  s.vulkan = M::maps_to_vulkan;
  s.area = area;
  return s;
}
// One field per render target (D3D10.1/11 independent blending): `BlendEnable[0..7]`.
constexpr StateInfo blend(std::string_view name, T type, const EnumSet* enums = nullptr) {
  return field(name, StateBlock::blend_state, type, A::color_blend, enums, 8);
}
constexpr StateInfo depth(std::string_view name, T type, const EnumSet* enums = nullptr) {
  return field(name, StateBlock::depth_stencil_state, type, A::depth_stencil, enums);
}
constexpr StateInfo raster(std::string_view name, T type, const EnumSet* enums = nullptr) {
  return field(name, StateBlock::rasterizer_state, type, A::rasterization, enums);
}
constexpr StateInfo sampler(std::string_view name, T type, const EnumSet* enums = nullptr) {
  return field(name, StateBlock::sampler_object, type, A::sampler, enums);
}
// A pass call: `SetPixelShader(shader)`, `SetBlendState(state, factor, mask)`; with no
// arguments, a D3D10 pass assignment (`BlendState = b;`).
constexpr StateInfo call(std::string_view name, T type, A area, uint8_t args,
                         StateApi api = StateApi::d3d10, std::string_view object_kind = {}) {
  StateInfo s = field(name, StateBlock::pass, type, area);
  s.call_args = args;
  s.api = api;
  s.object_kind = object_kind;
  return s;
}

// A pass call or assignment that binds the shader of `stage`.
constexpr StateInfo shader_call(std::string_view name, PassStage stage, uint8_t args,
                                StateApi api = StateApi::d3d10) {
  StateInfo s = call(name, T::shader, A::shader_stage, args, api);
  s.stage = stage;
  return s;
}

}  // namespace

std::span<const StateInfo> d3d10_states() {
  static const StateInfo rows[] = {
      field("AlphaToCoverageEnable", StateBlock::blend_state, T::boolean, A::multisample),
      blend("BlendEnable", T::boolean),
      blend("SrcBlend", T::enumeration, &kBlend),
      blend("DestBlend", T::enumeration, &kBlend),
      blend("BlendOp", T::enumeration, &kBlendOp),
      blend("SrcBlendAlpha", T::enumeration, &kBlend),
      blend("DestBlendAlpha", T::enumeration, &kBlend),
      blend("BlendOpAlpha", T::enumeration, &kBlendOp),
      blend("RenderTargetWriteMask", T::flags, &kColorWrite),

      depth("DepthEnable", T::boolean),
      depth("DepthWriteMask", T::enumeration, &kDepthWriteMask),
      depth("DepthFunc", T::enumeration, &kCompare),
      depth("StencilEnable", T::boolean),
      depth("StencilReadMask", T::integer),
      depth("StencilWriteMask", T::integer),
      depth("FrontFaceStencilFail", T::enumeration, &kStencilOp),
      depth("FrontFaceStencilDepthFail", T::enumeration, &kStencilOp),
      depth("FrontFaceStencilPass", T::enumeration, &kStencilOp),
      depth("FrontFaceStencilFunc", T::enumeration, &kCompare),
      depth("BackFaceStencilFail", T::enumeration, &kStencilOp),
      depth("BackFaceStencilDepthFail", T::enumeration, &kStencilOp),
      depth("BackFaceStencilPass", T::enumeration, &kStencilOp),
      depth("BackFaceStencilFunc", T::enumeration, &kCompare),

      raster("FillMode", T::enumeration, &kFill10),
      raster("CullMode", T::enumeration, &kCull10),
      raster("FrontCounterClockwise", T::boolean),
      raster("DepthBias", T::integer),
      raster("DepthBiasClamp", T::floating),
      raster("SlopeScaledDepthBias", T::floating),
      // Vulkan clips to depth by default; turning it off needs depthClampEnable.
      raster("DepthClipEnable", T::boolean),
      raster("ScissorEnable", T::boolean),
      raster("MultisampleEnable", T::boolean),
      raster("AntialiasedLineEnable", T::boolean),

      sampler("Filter", T::enumeration, &kFilter11),
      sampler("AddressU", T::enumeration, &kTextureAddress),
      sampler("AddressV", T::enumeration, &kTextureAddress),
      sampler("AddressW", T::enumeration, &kTextureAddress),
      sampler("MipLODBias", T::floating),
      sampler("MaxAnisotropy", T::integer),
      sampler("ComparisonFunc", T::enumeration, &kCompare),
      sampler("BorderColor", T::float4),
      sampler("MinLOD", T::floating),
      sampler("MaxLOD", T::floating),
      field("Texture", StateBlock::sampler_object, T::texture, A::resource_binding),

      shader_call("SetVertexShader", PassStage::vertex, 1),
      shader_call("SetPixelShader", PassStage::pixel, 1),
      shader_call("SetGeometryShader", PassStage::geometry, 1),
      shader_call("SetHullShader", PassStage::hull, 1, StateApi::d3d11),
      shader_call("SetDomainShader", PassStage::domain, 1, StateApi::d3d11),
      shader_call("SetComputeShader", PassStage::compute, 1, StateApi::d3d11),
      // (state, blend factor float4, sample mask)
      call("SetBlendState", T::state_object, A::color_blend, 3, StateApi::d3d10, "BlendState"),
      // (state, stencil reference)
      call("SetDepthStencilState", T::state_object, A::depth_stencil, 2, StateApi::d3d10,
           "DepthStencilState"),
      call("SetRasterizerState", T::state_object, A::rasterization, 1, StateApi::d3d10,
           "RasterizerState"),
      // FX10/FX11 also accept the assignment form of the pass calls (EffectStates11.h).
      shader_call("GeometryShader", PassStage::geometry, 0),
      shader_call("HullShader", PassStage::hull, 0, StateApi::d3d11),
      shader_call("DomainShader", PassStage::domain, 0, StateApi::d3d11),
      shader_call("ComputeShader", PassStage::compute, 0, StateApi::d3d11),
      call("BlendState", T::state_object, A::color_blend, 0, StateApi::d3d10, "BlendState"),
      call("DepthStencilState", T::state_object, A::depth_stencil, 0, StateApi::d3d10,
           "DepthStencilState"),
      call("RasterizerState", T::state_object, A::rasterization, 0, StateApi::d3d10,
           "RasterizerState"),
      call("AB_BlendFactor", T::float4, A::color_blend, 0),
      call("AB_SampleMask", T::integer, A::multisample, 0),
      call("DS_StencilRef", T::integer, A::depth_stencil, 0),
  };
  return rows;
}

}  // namespace fx::state_data
