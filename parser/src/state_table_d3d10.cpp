// Direct3D 10/11 state-object fields (BlendState, DepthStencilState, RasterizerState,
// SamplerState) and the pass calls of technique10/technique11 (SetVertexShader(...),
// SetBlendState(...)). These map onto Vulkan pipeline and sampler state almost one to one.
#include "state_table_data.h"

namespace fx::state_data {
namespace {

using T = StateValueType;
using M = VulkanMeaning;
using A = VulkanArea;
using F = StateField;

constexpr StateInfo field(std::string_view name, StateBlock block, T type, A area, F to, const EnumSet* enums = nullptr,
                          uint16_t index_count = 0) {
  StateInfo s;
  s.name = name;
  s.block = block;
  s.type = type;
  s.enums = enums;
  s.index_count = index_count;
  s.api = StateApi::d3d10;
  s.vulkan = M::maps_to_vulkan;
  s.area = area;
  s.field = to;
  s.lands = landing_of(to);
  return s;
}
// One field per render target (D3D10.1/11 independent blending): `BlendEnable[0..7]`. An
// unindexed factor or operation writes every target, an unindexed enable or mask target 0
// (the object then copies target 0 to the others unless it indexes one).
constexpr StateInfo blend(std::string_view name, T type, F to, const EnumSet* enums = nullptr,
                          uint8_t target = kEveryTarget) {
  StateInfo s = field(name, StateBlock::blend_state, type, A::color_blend, to, enums, 8);
  s.target = target;
  return s;
}
constexpr StateInfo depth(std::string_view name, T type, F to, const EnumSet* enums = nullptr) {
  return field(name, StateBlock::depth_stencil_state, type, A::depth_stencil, to, enums);
}
constexpr StateInfo raster(std::string_view name, T type, F to, const EnumSet* enums = nullptr) {
  return field(name, StateBlock::rasterizer_state, type, A::rasterization, to, enums);
}
constexpr StateInfo sampler(std::string_view name, T type, F to, const EnumSet* enums = nullptr) {
  return field(name, StateBlock::sampler_object, type, A::sampler, to, enums);
}
// A pass call: `SetPixelShader(shader)`, `SetBlendState(state, factor, mask)`; with no
// arguments, a D3D10 pass assignment (`BlendState = b;`). `extra` are the fields the
// arguments after the first write.
constexpr StateInfo call(std::string_view name, T type, A area, F to, uint8_t args, StateApi api = StateApi::d3d10,
                         std::string_view object_kind = {}, std::array<F, 2> extra = {F::none, F::none}) {
  StateInfo s = field(name, StateBlock::pass, type, area, to);
  s.call_args = args;
  s.api = api;
  s.object_kind = object_kind;
  s.call_fields = extra;
  return s;
}

// A pass call or assignment that binds the shader of `stage`.
constexpr StateInfo shader_call(std::string_view name, PassStage stage, uint8_t args, StateApi api = StateApi::d3d10) {
  StateInfo s = call(name, T::shader, A::shader_stage, F::shader, args, api);
  s.stage = stage;
  return s;
}

}  // namespace

std::span<const StateInfo> d3d10_states() {
  static const StateInfo rows[] = {
      field("AlphaToCoverageEnable", StateBlock::blend_state, T::boolean, A::multisample, F::alpha_to_coverage),
      blend("BlendEnable", T::boolean, F::blend_enable, nullptr, 0),
      blend("SrcBlend", T::enumeration, F::src_color, &kBlend),
      blend("DestBlend", T::enumeration, F::dst_color, &kBlend),
      blend("BlendOp", T::enumeration, F::color_op, &kBlendOp),
      blend("SrcBlendAlpha", T::enumeration, F::src_alpha, &kBlend),
      blend("DestBlendAlpha", T::enumeration, F::dst_alpha, &kBlend),
      blend("BlendOpAlpha", T::enumeration, F::alpha_op, &kBlendOp),
      blend("RenderTargetWriteMask", T::flags, F::write_mask, &kColorWrite, 0),

      depth("DepthEnable", T::boolean, F::depth_test),
      depth("DepthWriteMask", T::enumeration, F::depth_write, &kDepthWriteMask),
      depth("DepthFunc", T::enumeration, F::depth_compare, &kCompare),
      depth("StencilEnable", T::boolean, F::stencil_test),
      depth("StencilReadMask", T::integer, F::stencil_read_mask),
      depth("StencilWriteMask", T::integer, F::stencil_write_mask),
      depth("FrontFaceStencilFail", T::enumeration, F::stencil_front_fail, &kStencilOp),
      depth("FrontFaceStencilDepthFail", T::enumeration, F::stencil_front_depth_fail, &kStencilOp),
      depth("FrontFaceStencilPass", T::enumeration, F::stencil_front_pass, &kStencilOp),
      depth("FrontFaceStencilFunc", T::enumeration, F::stencil_front_compare, &kCompare),
      depth("BackFaceStencilFail", T::enumeration, F::stencil_back_fail, &kStencilOp),
      depth("BackFaceStencilDepthFail", T::enumeration, F::stencil_back_depth_fail, &kStencilOp),
      depth("BackFaceStencilPass", T::enumeration, F::stencil_back_pass, &kStencilOp),
      depth("BackFaceStencilFunc", T::enumeration, F::stencil_back_compare, &kCompare),

      raster("FillMode", T::enumeration, F::fill, &kFill10),
      raster("CullMode", T::enumeration, F::cull, &kCull10),
      raster("FrontCounterClockwise", T::boolean, F::front_face_ccw),
      raster("DepthBias", T::integer, F::depth_bias_units),
      raster("DepthBiasClamp", T::floating, F::depth_bias_clamp),
      raster("SlopeScaledDepthBias", T::floating, F::depth_bias_slope),
      // Vulkan clips to depth by default; turning it off needs depthClampEnable.
      raster("DepthClipEnable", T::boolean, F::depth_clip),
      raster("ScissorEnable", T::boolean, F::scissor),
      raster("MultisampleEnable", T::boolean, F::multisample),
      raster("AntialiasedLineEnable", T::boolean, F::antialiased_lines),

      sampler("Filter", T::enumeration, F::filter_bits, &kFilter11),
      sampler("AddressU", T::enumeration, F::address_u, &kTextureAddress),
      sampler("AddressV", T::enumeration, F::address_v, &kTextureAddress),
      sampler("AddressW", T::enumeration, F::address_w, &kTextureAddress),
      sampler("MipLODBias", T::floating, F::lod_bias),
      sampler("MaxAnisotropy", T::integer, F::max_anisotropy),
      sampler("ComparisonFunc", T::enumeration, F::compare, &kCompare),
      sampler("BorderColor", T::float4, F::border_color),
      sampler("MinLOD", T::floating, F::min_lod),
      sampler("MaxLOD", T::floating, F::max_lod),
      field("Texture", StateBlock::sampler_object, T::texture, A::resource_binding, F::texture),

      shader_call("SetVertexShader", PassStage::vertex, 1),
      shader_call("SetPixelShader", PassStage::pixel, 1),
      shader_call("SetGeometryShader", PassStage::geometry, 1),
      shader_call("SetHullShader", PassStage::hull, 1, StateApi::d3d11),
      shader_call("SetDomainShader", PassStage::domain, 1, StateApi::d3d11),
      shader_call("SetComputeShader", PassStage::compute, 1, StateApi::d3d11),
      // (state, blend factor float4, sample mask)
      call("SetBlendState", T::state_object, A::color_blend, F::state_object, 3, StateApi::d3d10, "BlendState",
           {F::blend_constants, F::sample_mask}),
      // (state, stencil reference)
      call("SetDepthStencilState", T::state_object, A::depth_stencil, F::state_object, 2, StateApi::d3d10,
           "DepthStencilState", {F::stencil_ref, F::none}),
      call("SetRasterizerState", T::state_object, A::rasterization, F::state_object, 1, StateApi::d3d10,
           "RasterizerState"),
      // FX10/FX11 also accept the assignment form of the pass calls (EffectStates11.h).
      shader_call("GeometryShader", PassStage::geometry, 0),
      shader_call("HullShader", PassStage::hull, 0, StateApi::d3d11),
      shader_call("DomainShader", PassStage::domain, 0, StateApi::d3d11),
      shader_call("ComputeShader", PassStage::compute, 0, StateApi::d3d11),
      call("BlendState", T::state_object, A::color_blend, F::state_object, 0, StateApi::d3d10, "BlendState"),
      call("DepthStencilState", T::state_object, A::depth_stencil, F::state_object, 0, StateApi::d3d10,
           "DepthStencilState"),
      call("RasterizerState", T::state_object, A::rasterization, F::state_object, 0, StateApi::d3d10,
           "RasterizerState"),
      call("AB_BlendFactor", T::float4, A::color_blend, F::blend_constants, 0),
      call("AB_SampleMask", T::integer, A::multisample, F::sample_mask, 0),
      call("DS_StencilRef", T::integer, A::depth_stencil, F::stencil_ref, 0),
  };
  return rows;
}

}  // namespace fx::state_data
