// The Vulkan-facing pass summary and sampler descriptions: D3D9 render/sampler states and
// D3D10/11 state objects mapped onto one set of structures (see docs/effect-model.md for
// the defaults and the mapping rules).
#include <algorithm>

#include "model_build.h"

namespace fx::model_detail {
namespace {

// D3D blend / compare / stencil-op / address enums are Vulkan's plus one (D3DBLEND_ZERO
// = 1 vs VK_BLEND_FACTOR_ZERO = 0 ...), except for the few blend values remapped here.
BlendFactor blend_factor(int64_t d3d) {
  switch (d3d) {
    case 1: return BlendFactor::zero;
    case 2: return BlendFactor::one;
    case 3: return BlendFactor::src_color;
    case 4: return BlendFactor::one_minus_src_color;
    case 5: return BlendFactor::src_alpha;
    case 6: return BlendFactor::one_minus_src_alpha;
    case 7: return BlendFactor::dst_alpha;
    case 8: return BlendFactor::one_minus_dst_alpha;
    case 9: return BlendFactor::dst_color;
    case 10: return BlendFactor::one_minus_dst_color;
    case 11: return BlendFactor::src_alpha_saturate;
    case 12: return BlendFactor::src_alpha;            // BOTHSRCALPHA: dest is fixed below
    case 13: return BlendFactor::one_minus_src_alpha;  // BOTHINVSRCALPHA
    case 14: return BlendFactor::constant_color;
    case 15: return BlendFactor::one_minus_constant_color;
    case 16: return BlendFactor::src1_color;
    case 17: return BlendFactor::one_minus_src1_color;
    case 18: return BlendFactor::src1_alpha;
    case 19: return BlendFactor::one_minus_src1_alpha;
    default: return BlendFactor::one;
  }
}
CompareOp compare_op(int64_t d3d) { return d3d >= 1 && d3d <= 8 ? static_cast<CompareOp>(d3d - 1) : CompareOp::always; }
BlendOp blend_op(int64_t d3d) { return d3d >= 1 && d3d <= 5 ? static_cast<BlendOp>(d3d - 1) : BlendOp::add; }
StencilOp stencil_op(int64_t d3d) { return d3d >= 1 && d3d <= 8 ? static_cast<StencilOp>(d3d - 1) : StencilOp::keep; }
AddressMode3 address_mode(int64_t d3d) {
  return d3d >= 1 && d3d <= 5 ? static_cast<AddressMode3>(d3d - 1) : AddressMode3::repeat;
}

// The number a state carries; for a parameter reference, the parameter's default.
double number(const ResolvedState& s, const EffectModel& model) {
  if (s.kind == StateValueKind::parameter && s.target < model.parameters.size()) {
    const auto& d = model.parameters[s.target].default_value;
    return d && d->is_numeric() ? d->number() : 0.0;
  }
  if (s.kind == StateValueKind::floating) return s.floating;
  return static_cast<double>(s.integer);
}

struct Summarizer {
  const EffectModel& model;
  PassStateSummary out;
  bool separate_alpha = false, two_sided = false;
  // D3D9 BOTH(INV)SRCALPHA overrides DestBlend.
  void set_src_blend(TargetBlend& t, int64_t v, bool alpha) {
    (alpha ? t.src_alpha : t.src_color) = blend_factor(v);
    if (v == 12) (alpha ? t.dst_alpha : t.dst_color) = BlendFactor::one_minus_src_alpha;
    if (v == 13) (alpha ? t.dst_alpha : t.dst_color) = BlendFactor::src_alpha;
  }
  template <class F>
  void each_target(F&& f) {
    for (TargetBlend& t : out.blend) f(t);
  }

  void reset_blend_d3d10() {
    out.blend.fill(TargetBlend{});
    out.alpha_to_coverage = false;
    out.blend_constants = {1, 1, 1, 1};
    out.sample_mask = 0xFFFFFFFF;
  }
  void reset_depth_stencil_d3d10() {
    out.depth_test = true;
    out.depth_write = true;
    out.depth_compare = CompareOp::less;
    out.stencil = false;
    out.stencil_front = out.stencil_back = StencilFace{};
    out.stencil_read_mask = out.stencil_write_mask = 0xFF;
    out.stencil_ref = 0;
  }
  void reset_rasterizer_d3d10() {
    out.fill = FillMode::solid;
    out.cull = CullMode::back;
    out.front_face = FrontFace::clockwise;
    out.depth_bias = 0;
    out.depth_bias_normalized = false;
    out.depth_bias_slope = out.depth_bias_clamp = 0;
    out.depth_clip = true;
    out.scissor = false;
    out.multisample = false;
    out.antialiased_lines = false;
  }

  void apply_object(const StateObjectInfo& obj) {
    bool per_target = false;
    for (const ResolvedState& s : obj.states) {
      if (s.indexed && s.index > 0) per_target = true;
      apply_field(s);
    }
    // D3D11 with IndependentBlendEnable off (and any object naming target 0 only): every
    // render target blends as target 0.
    if (obj.block == StateBlock::blend_state && !per_target) std::fill(out.blend.begin() + 1, out.blend.end(), out.blend[0]);
  }

  void apply_field(const ResolvedState& s) {
    const std::string_view n = s.info->name;
    const int64_t v = static_cast<int64_t>(number(s, model));
    const double f = number(s, model);
    TargetBlend& t = out.blend[std::min<uint32_t>(s.index, kMaxRenderTargets - 1)];
    // Unindexed colour/alpha factors apply to every target (D3D10 shares them).
    auto targets = [&](auto&& fn) {
      if (s.indexed) fn(t);
      else each_target(fn);
    };
    if (n == "AlphaToCoverageEnable") out.alpha_to_coverage = v != 0;
    else if (n == "BlendEnable") t.enable = v != 0;
    else if (n == "SrcBlend") targets([&](TargetBlend& b) { b.src_color = blend_factor(v); });
    else if (n == "DestBlend") targets([&](TargetBlend& b) { b.dst_color = blend_factor(v); });
    else if (n == "BlendOp") targets([&](TargetBlend& b) { b.color_op = blend_op(v); });
    else if (n == "SrcBlendAlpha") targets([&](TargetBlend& b) { b.src_alpha = blend_factor(v); });
    else if (n == "DestBlendAlpha") targets([&](TargetBlend& b) { b.dst_alpha = blend_factor(v); });
    else if (n == "BlendOpAlpha") targets([&](TargetBlend& b) { b.alpha_op = blend_op(v); });
    else if (n == "RenderTargetWriteMask") t.write_mask = static_cast<uint8_t>(v & 0xF);
    else if (n == "DepthEnable") out.depth_test = v != 0;
    else if (n == "DepthWriteMask") out.depth_write = v != 0;
    else if (n == "DepthFunc") out.depth_compare = compare_op(v);
    else if (n == "StencilEnable") out.stencil = v != 0;
    else if (n == "StencilReadMask") out.stencil_read_mask = static_cast<uint32_t>(v);
    else if (n == "StencilWriteMask") out.stencil_write_mask = static_cast<uint32_t>(v);
    else if (n == "FrontFaceStencilFail") out.stencil_front.fail = stencil_op(v);
    else if (n == "FrontFaceStencilDepthFail") out.stencil_front.depth_fail = stencil_op(v);
    else if (n == "FrontFaceStencilPass") out.stencil_front.pass = stencil_op(v);
    else if (n == "FrontFaceStencilFunc") out.stencil_front.compare = compare_op(v);
    else if (n == "BackFaceStencilFail") out.stencil_back.fail = stencil_op(v);
    else if (n == "BackFaceStencilDepthFail") out.stencil_back.depth_fail = stencil_op(v);
    else if (n == "BackFaceStencilPass") out.stencil_back.pass = stencil_op(v);
    else if (n == "BackFaceStencilFunc") out.stencil_back.compare = compare_op(v);
    else if (n == "FillMode") out.fill = v == 2 ? FillMode::wireframe : v == 1 ? FillMode::point : FillMode::solid;
    else if (n == "CullMode") out.cull = v == 2 ? CullMode::front : v == 3 ? CullMode::back : CullMode::none;
    else if (n == "FrontCounterClockwise") out.front_face = v ? FrontFace::counter_clockwise : FrontFace::clockwise;
    else if (n == "DepthBias") out.depth_bias = static_cast<float>(f), out.depth_bias_normalized = false;
    else if (n == "DepthBiasClamp") out.depth_bias_clamp = static_cast<float>(f);
    else if (n == "SlopeScaledDepthBias") out.depth_bias_slope = static_cast<float>(f);
    else if (n == "DepthClipEnable") out.depth_clip = v != 0;
    else if (n == "ScissorEnable") out.scissor = v != 0;
    else if (n == "MultisampleEnable") out.multisample = v != 0;
    else if (n == "AntialiasedLineEnable") out.antialiased_lines = v != 0;
  }

  void apply_object_ref(const ResolvedState& s, StateBlock want) {
    if (s.kind == StateValueKind::null) {
      if (want == StateBlock::blend_state) reset_blend_d3d10();
      if (want == StateBlock::depth_stencil_state) reset_depth_stencil_d3d10();
      if (want == StateBlock::rasterizer_state) reset_rasterizer_d3d10();
      return;
    }
    if (s.kind != StateValueKind::state_object || s.target >= model.state_objects.size()) return;
    const StateObjectInfo& obj = model.state_objects[s.target];
    if (obj.block != want) return;
    if (want == StateBlock::blend_state) {
      reset_blend_d3d10();
      apply_object(obj);
      if (s.call_args.size() >= 1 && s.call_args[0].is_numeric())
        for (size_t i = 0; i < 4 && i < s.call_args[0].components.size(); ++i)
          out.blend_constants[i] = static_cast<float>(s.call_args[0].components[i]);
      if (s.call_args.size() >= 2 && s.call_args[1].is_numeric())
        out.sample_mask = static_cast<uint32_t>(static_cast<int64_t>(s.call_args[1].number()));
    } else if (want == StateBlock::depth_stencil_state) {
      reset_depth_stencil_d3d10();
      apply_object(obj);
      if (!s.call_args.empty() && s.call_args[0].is_numeric())
        out.stencil_ref = static_cast<uint32_t>(static_cast<int64_t>(s.call_args[0].number()));
    } else {
      reset_rasterizer_d3d10();
      apply_object(obj);
    }
  }

  void apply_pass(const ResolvedState& s) {
    const std::string_view n = s.info->name;
    const int64_t v = static_cast<int64_t>(number(s, model));
    const double f = number(s, model);
    if (n == "ZEnable") out.depth_test = v != 0;
    else if (n == "ZWriteEnable") out.depth_write = v != 0;
    else if (n == "ZFunc") out.depth_compare = compare_op(v);
    else if (n == "StencilEnable") out.stencil = v != 0;
    else if (n == "StencilFail") out.stencil_front.fail = stencil_op(v);
    else if (n == "StencilZFail") out.stencil_front.depth_fail = stencil_op(v);
    else if (n == "StencilPass") out.stencil_front.pass = stencil_op(v);
    else if (n == "StencilFunc") out.stencil_front.compare = compare_op(v);
    else if (n == "CCW_StencilFail") out.stencil_back.fail = stencil_op(v);
    else if (n == "CCW_StencilZFail") out.stencil_back.depth_fail = stencil_op(v);
    else if (n == "CCW_StencilPass") out.stencil_back.pass = stencil_op(v);
    else if (n == "CCW_StencilFunc") out.stencil_back.compare = compare_op(v);
    else if (n == "TwoSidedStencilMode") two_sided = v != 0;
    else if (n == "StencilRef" || n == "DS_StencilRef") out.stencil_ref = static_cast<uint32_t>(v);
    else if (n == "StencilMask") out.stencil_read_mask = static_cast<uint32_t>(v);
    else if (n == "StencilWriteMask") out.stencil_write_mask = static_cast<uint32_t>(v);
    // D3D9 culls by window-space winding with clockwise front faces: CW culls the front.
    else if (n == "CullMode") out.cull = v == 2 ? CullMode::front : v == 3 ? CullMode::back : CullMode::none;
    else if (n == "FillMode") out.fill = v == 1 ? FillMode::point : v == 2 ? FillMode::wireframe : FillMode::solid;
    else if (n == "DepthBias") out.depth_bias = static_cast<float>(f), out.depth_bias_normalized = true;
    else if (n == "SlopeScaleDepthBias") out.depth_bias_slope = static_cast<float>(f);
    else if (n == "ScissorTestEnable") out.scissor = v != 0;
    else if (n == "AntialiasedLineEnable") out.antialiased_lines = v != 0;
    else if (n == "AlphaBlendEnable") each_target([&](TargetBlend& t) { t.enable = v != 0; });
    else if (n == "SrcBlend") each_target([&](TargetBlend& t) { set_src_blend(t, v, false); });
    else if (n == "DestBlend") each_target([&](TargetBlend& t) { t.dst_color = blend_factor(v); });
    else if (n == "BlendOp") each_target([&](TargetBlend& t) { t.color_op = blend_op(v); });
    else if (n == "SeparateAlphaBlendEnable") separate_alpha = v != 0;
    else if (n == "SrcBlendAlpha") each_target([&](TargetBlend& t) { set_src_blend(t, v, true); });
    else if (n == "DestBlendAlpha") each_target([&](TargetBlend& t) { t.dst_alpha = blend_factor(v); });
    else if (n == "BlendOpAlpha") each_target([&](TargetBlend& t) { t.alpha_op = blend_op(v); });
    else if (n == "BlendFactor" || n == "AB_BlendFactor") out.blend_constants = s.vector;
    else if (n == "ColorWriteEnable") out.blend[std::min<uint32_t>(s.index, 3)].write_mask = static_cast<uint8_t>(v & 0xF);
    else if (n == "ColorWriteEnable1") out.blend[1].write_mask = static_cast<uint8_t>(v & 0xF);
    else if (n == "ColorWriteEnable2") out.blend[2].write_mask = static_cast<uint8_t>(v & 0xF);
    else if (n == "ColorWriteEnable3") out.blend[3].write_mask = static_cast<uint8_t>(v & 0xF);
    else if (n == "SRGBWriteEnable") out.srgb_write = v != 0;
    else if (n == "AlphaTestEnable") out.alpha_test = v != 0;
    else if (n == "AlphaFunc") out.alpha_compare = compare_op(v);
    else if (n == "AlphaRef") out.alpha_ref = static_cast<uint32_t>(v & 0xFF);
    else if (n == "MultiSampleAntialias") out.multisample = v != 0;
    else if (n == "MultiSampleMask" || n == "AB_SampleMask") out.sample_mask = static_cast<uint32_t>(v);
    else if (n == "SetBlendState" || n == "BlendState") apply_object_ref(s, StateBlock::blend_state);
    else if (n == "SetDepthStencilState" || n == "DepthStencilState") apply_object_ref(s, StateBlock::depth_stencil_state);
    else if (n == "SetRasterizerState" || n == "RasterizerState") apply_object_ref(s, StateBlock::rasterizer_state);
  }
};

}  // namespace

PassStateSummary summarize_pass(const std::vector<ResolvedState>& states, const EffectModel& model) {
  Summarizer s{model, {}};
  bool d3d9_alpha_states = false;
  for (const ResolvedState& r : states) {
    if (!r.info || r.kind == StateValueKind::invalid) continue;
    std::string_view n = r.info->name;
    if (r.info->api == StateApi::d3d9 &&
        (n == "SrcBlend" || n == "DestBlend" || n == "BlendOp" || n == "SrcBlendAlpha" || n == "DestBlendAlpha" ||
         n == "BlendOpAlpha" || n == "SeparateAlphaBlendEnable"))
      d3d9_alpha_states = true;
    s.apply_pass(r);
  }
  // D3D9 blends alpha like colour unless SeparateAlphaBlendEnable is set.
  if (d3d9_alpha_states && !s.separate_alpha)
    for (TargetBlend& t : s.out.blend) {
      t.src_alpha = t.src_color;
      t.dst_alpha = t.dst_color;
      t.alpha_op = t.color_op;
    }
  bool had_d3d9_stencil = std::any_of(states.begin(), states.end(), [](const ResolvedState& r) {
    return r.info && r.info->api == StateApi::d3d9 && r.info->area == VulkanArea::depth_stencil;
  });
  if (had_d3d9_stencil && !s.two_sided) s.out.stencil_back = s.out.stencil_front;
  return s.out;
}

SamplerDesc describe_sampler(const std::vector<ResolvedState>& states, bool d3d10_object, uint32_t& texture) {
  SamplerDesc d;
  texture = kNoIndex;
  if (d3d10_object) {  // D3D11_SAMPLER_DESC defaults
    d.address = {AddressMode3::clamp_to_edge, AddressMode3::clamp_to_edge, AddressMode3::clamp_to_edge};
    d.min_filter = d.mag_filter = TexelFilter::linear;
    d.mip_filter = MipFilter::linear;
    d.border_color = {1, 1, 1, 1};
  }
  for (const ResolvedState& s : states) {
    if (!s.info || s.kind == StateValueKind::invalid) continue;
    const std::string_view n = s.info->name;
    const int64_t v = s.integer;
    auto texel = [](int64_t f) { return f >= 2 ? TexelFilter::linear : TexelFilter::nearest; };
    if (n == "Texture") texture = s.kind == StateValueKind::parameter ? s.target : kNoIndex;
    else if (n == "AddressU") d.address[0] = address_mode(v);
    else if (n == "AddressV") d.address[1] = address_mode(v);
    else if (n == "AddressW") d.address[2] = address_mode(v);
    else if (n == "BorderColor") d.border_color = s.vector;
    else if (n == "MagFilter") d.mag_filter = texel(v), d.anisotropic = d.anisotropic || v == 3;
    else if (n == "MinFilter") d.min_filter = texel(v), d.anisotropic = d.anisotropic || v == 3;
    else if (n == "MipFilter") d.mip_filter = v == 0 ? MipFilter::none : v == 1 ? MipFilter::nearest : MipFilter::linear;
    else if (n == "MipMapLodBias" || n == "MipLODBias") d.lod_bias = static_cast<float>(s.floating);
    else if (n == "MaxMipLevel") d.max_mip_level = static_cast<uint32_t>(v), d.min_lod = static_cast<float>(v);
    else if (n == "MaxAnisotropy") d.max_anisotropy = static_cast<uint32_t>(std::max<int64_t>(1, v));
    else if (n == "SRGBTexture") d.srgb = v != 0;
    else if (n == "MinLOD") d.min_lod = static_cast<float>(s.floating);
    else if (n == "MaxLOD") d.max_lod = static_cast<float>(std::min(s.floating, 1000.0));
    else if (n == "ComparisonFunc") d.compare = compare_op(v);
    else if (n == "Filter") {
      // D3D11_FILTER bits: 0x01 mip linear, 0x04 mag linear, 0x10 min linear, 0x40 anisotropic,
      // 0x80 comparison. Min/max reduction (0x100, 0x180) has no field here.
      d.mip_filter = (v & 0x01) ? MipFilter::linear : MipFilter::nearest;
      d.mag_filter = (v & 0x04) ? TexelFilter::linear : TexelFilter::nearest;
      d.min_filter = (v & 0x10) ? TexelFilter::linear : TexelFilter::nearest;
      d.anisotropic = (v & 0x40) != 0;
      d.compare_enable = (v & 0x80) != 0;
    }
  }
  if (!d.anisotropic) d.max_anisotropy = 1;
  return d;
}

}  // namespace fx::model_detail
