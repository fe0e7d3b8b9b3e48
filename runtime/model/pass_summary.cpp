// The Vulkan-facing pass summary and sampler descriptions: D3D9 render/sampler states and
// D3D10/11 state objects mapped onto one set of structures (see docs/effect-model.md for
// the defaults and the mapping rules).
#include <algorithm>
#include <optional>

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

// A state's value as the fields read it: an integer, a number, and up to four components
// (a colour or float4; a call argument may carry fewer, and writes only those).
struct FieldValue {
  int64_t integer = 0;
  double number = 0;
  std::array<float, 4> vector{0, 0, 0, 0};
  size_t components = 4;
};

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

  // The render targets a blend field writes: the indexed one, the row's own, or all.
  template <class F>
  void each_target(const StateInfo& row, uint32_t index, bool indexed, F&& f) {
    if (indexed && row.index_count > 0) {
      f(out.blend[std::min<uint32_t>(index, std::min<uint32_t>(row.index_count, kMaxRenderTargets) - 1)]);
    } else if (row.target != kEveryTarget) {
      f(out.blend[std::min<uint32_t>(row.target, kMaxRenderTargets - 1)]);
    } else {
      for (TargetBlend& t : out.blend) f(t);
    }
  }

  // Writes one value to the field its row names: the only place a field is written.
  void write(const StateInfo& row, StateField field, const FieldValue& x, uint32_t index, bool indexed) {
    const int64_t v = x.integer;
    const auto f = static_cast<float>(x.number);
    const bool d3d9 = row.api == StateApi::d3d9;
    auto targets = [&](auto&& fn) { each_target(row, index, indexed, fn); };
    switch (field) {
      case StateField::depth_test: out.depth_test = v != 0; break;
      case StateField::depth_write: out.depth_write = v != 0; break;
      case StateField::depth_compare: out.depth_compare = compare_op(v); break;
      case StateField::stencil_test: out.stencil = v != 0; break;
      case StateField::stencil_read_mask: out.stencil_read_mask = static_cast<uint32_t>(v); break;
      case StateField::stencil_write_mask: out.stencil_write_mask = static_cast<uint32_t>(v); break;
      case StateField::stencil_front_fail: out.stencil_front.fail = stencil_op(v); break;
      case StateField::stencil_front_depth_fail: out.stencil_front.depth_fail = stencil_op(v); break;
      case StateField::stencil_front_pass: out.stencil_front.pass = stencil_op(v); break;
      case StateField::stencil_front_compare: out.stencil_front.compare = compare_op(v); break;
      case StateField::stencil_back_fail: out.stencil_back.fail = stencil_op(v); break;
      case StateField::stencil_back_depth_fail: out.stencil_back.depth_fail = stencil_op(v); break;
      case StateField::stencil_back_pass: out.stencil_back.pass = stencil_op(v); break;
      case StateField::stencil_back_compare: out.stencil_back.compare = compare_op(v); break;
      case StateField::stencil_two_sided: two_sided = v != 0; break;
      case StateField::stencil_ref: out.stencil_ref = static_cast<uint32_t>(v); break;
      // D3D9 and D3D10 cull by window-space winding with clockwise front faces: 2 culls the
      // front (D3DCULL_CW, D3D10_CULL_FRONT), 3 the back.
      case StateField::cull: out.cull = v == 2 ? CullMode::front : v == 3 ? CullMode::back : CullMode::none; break;
      case StateField::fill:
        out.fill = v == 1 ? FillMode::point : v == 2 ? FillMode::wireframe : FillMode::solid;
        break;
      case StateField::front_face_ccw: out.front_face = v ? FrontFace::counter_clockwise : FrontFace::clockwise; break;
      case StateField::depth_bias_d3d9: out.depth_bias = f, out.depth_bias_normalized = true; break;
      case StateField::depth_bias_units: out.depth_bias = f, out.depth_bias_normalized = false; break;
      case StateField::depth_bias_clamp: out.depth_bias_clamp = f; break;
      case StateField::depth_bias_slope: out.depth_bias_slope = f; break;
      case StateField::depth_clip: out.depth_clip = v != 0; break;
      case StateField::scissor: out.scissor = v != 0; break;
      case StateField::multisample: out.multisample = v != 0; break;
      case StateField::antialiased_lines: out.antialiased_lines = v != 0; break;
      case StateField::blend_enable: targets([&](TargetBlend& t) { t.enable = v != 0; }); break;
      case StateField::src_color:
        targets([&](TargetBlend& t) { d3d9 ? set_src_blend(t, v, false) : void(t.src_color = blend_factor(v)); });
        break;
      case StateField::dst_color: targets([&](TargetBlend& t) { t.dst_color = blend_factor(v); }); break;
      case StateField::color_op: targets([&](TargetBlend& t) { t.color_op = blend_op(v); }); break;
      case StateField::src_alpha:
        targets([&](TargetBlend& t) { d3d9 ? set_src_blend(t, v, true) : void(t.src_alpha = blend_factor(v)); });
        break;
      case StateField::dst_alpha: targets([&](TargetBlend& t) { t.dst_alpha = blend_factor(v); }); break;
      case StateField::alpha_op: targets([&](TargetBlend& t) { t.alpha_op = blend_op(v); }); break;
      case StateField::separate_alpha: separate_alpha = v != 0; break;
      case StateField::write_mask:
        targets([&](TargetBlend& t) { t.write_mask = static_cast<uint8_t>(v & 0xF); });
        break;
      case StateField::blend_constants:
        for (size_t i = 0; i < 4 && i < x.components; ++i) out.blend_constants[i] = x.vector[i];
        break;
      case StateField::alpha_to_coverage: out.alpha_to_coverage = v != 0; break;
      case StateField::sample_mask: out.sample_mask = static_cast<uint32_t>(v); break;
      case StateField::srgb_write: out.srgb_write = v != 0; break;
      case StateField::alpha_test: out.alpha_test = v != 0; break;
      case StateField::alpha_compare: out.alpha_compare = compare_op(v); break;
      case StateField::alpha_ref: out.alpha_ref = static_cast<uint32_t>(v & 0xFF); break;
      default: break;  // bindings, sampler and fixed-function fields land elsewhere
    }
  }

  // A resolved state's value: numbers from the state or the parameter it names.
  FieldValue value_of(const ResolvedState& s) const {
    const double n = number(s, model);
    return {static_cast<int64_t>(n), n, s.vector, 4};
  }

  void apply_object(const StateObjectInfo& obj) {
    bool per_target = false;
    for (const ResolvedState& s : obj.states) {
      if (s.indexed && s.index > 0) per_target = true;
      write(*s.info, s.info->field, value_of(s), s.index, s.indexed);
    }
    // D3D11 with IndependentBlendEnable off (and any object naming target 0 only): every
    // render target blends as target 0.
    if (obj.block == StateBlock::blend_state && !per_target)
      std::fill(out.blend.begin() + 1, out.blend.end(), out.blend[0]);
  }

  void reset(StateBlock block) {
    if (block == StateBlock::blend_state) reset_blend_d3d10();
    if (block == StateBlock::depth_stencil_state) reset_depth_stencil_d3d10();
    if (block == StateBlock::rasterizer_state) reset_rasterizer_d3d10();
  }

  // `SetBlendState(b, factor, mask)` / `BlendState = b;`: the object's block is reset to
  // D3D11's defaults, the object applied, then the call's arguments written to the fields
  // the row names for them.
  void apply_object_ref(const ResolvedState& s) {
    const std::optional<StateBlock> want = state_object_block(s.info->object_kind);
    if (!want) return;
    if (s.kind == StateValueKind::null) return reset(*want);
    if (s.kind != StateValueKind::state_object || s.target >= model.state_objects.size()) return;
    const StateObjectInfo& obj = model.state_objects[s.target];
    if (obj.block != *want) return;
    reset(*want);
    apply_object(obj);
    for (size_t i = 0; i < s.info->call_fields.size() && i < s.call_args.size(); ++i) {
      const Value& arg = s.call_args[i];
      if (s.info->call_fields[i] == StateField::none || !arg.is_numeric()) continue;
      FieldValue x{static_cast<int64_t>(arg.number()), arg.number(), {}, std::min<size_t>(4, arg.components.size())};
      for (size_t c = 0; c < x.components; ++c) x.vector[c] = static_cast<float>(arg.components[c]);
      write(*s.info, s.info->call_fields[i], x, 0, false);
    }
  }

  void apply_pass(const ResolvedState& s) {
    const StateInfo& row = *s.info;
    if (row.field == StateField::state_object) return apply_object_ref(s);
    if (row.lands == StateLanding::pipeline || row.lands == StateLanding::dynamic)
      write(row, row.field, value_of(s), s.index, s.indexed);
  }
};

// D3D9 blends alpha like colour unless SeparateAlphaBlendEnable is set: the fields that
// tell whether a pass set D3D9 blending at all.
bool is_d3d9_blend_field(StateField f) {
  switch (f) {
    case StateField::src_color:
    case StateField::dst_color:
    case StateField::color_op:
    case StateField::src_alpha:
    case StateField::dst_alpha:
    case StateField::alpha_op:
    case StateField::separate_alpha: return true;
    default: return false;
  }
}

// The sampler field a row names, written from the state's own value.
void write_sampler(const ResolvedState& s, SamplerDesc& d, uint32_t& texture) {
  const int64_t v = s.integer;
  auto texel = [](int64_t f) { return f >= 2 ? TexelFilter::linear : TexelFilter::nearest; };
  switch (s.info->field) {
    case StateField::texture: texture = s.kind == StateValueKind::parameter ? s.target : kNoIndex; break;
    case StateField::address_u: d.address[0] = address_mode(v); break;
    case StateField::address_v: d.address[1] = address_mode(v); break;
    case StateField::address_w: d.address[2] = address_mode(v); break;
    case StateField::border_color: d.border_color = s.vector; break;
    case StateField::mag_filter: d.mag_filter = texel(v), d.anisotropic = d.anisotropic || v == 3; break;
    case StateField::min_filter: d.min_filter = texel(v), d.anisotropic = d.anisotropic || v == 3; break;
    case StateField::mip_filter:
      d.mip_filter = v == 0 ? MipFilter::none : v == 1 ? MipFilter::nearest : MipFilter::linear;
      break;
    case StateField::lod_bias: d.lod_bias = static_cast<float>(s.floating); break;
    case StateField::max_mip_level:
      d.max_mip_level = static_cast<uint32_t>(v), d.min_lod = static_cast<float>(v);
      break;
    case StateField::max_anisotropy: d.max_anisotropy = static_cast<uint32_t>(std::max<int64_t>(1, v)); break;
    case StateField::srgb_texture: d.srgb = v != 0; break;
    case StateField::min_lod: d.min_lod = static_cast<float>(s.floating); break;
    case StateField::max_lod: d.max_lod = static_cast<float>(std::min(s.floating, 1000.0)); break;
    case StateField::compare: d.compare = compare_op(v); break;
    case StateField::filter_bits:
      // D3D11_FILTER bits: 0x01 mip linear, 0x04 mag linear, 0x10 min linear, 0x40 anisotropic,
      // 0x80 comparison. Min/max reduction (0x100, 0x180) has no field here.
      d.mip_filter = (v & 0x01) ? MipFilter::linear : MipFilter::nearest;
      d.mag_filter = (v & 0x04) ? TexelFilter::linear : TexelFilter::nearest;
      d.min_filter = (v & 0x10) ? TexelFilter::linear : TexelFilter::nearest;
      d.anisotropic = (v & 0x40) != 0;
      d.compare_enable = (v & 0x80) != 0;
      break;
    default: break;
  }
}

}  // namespace

PassStateSummary summarize_pass(const std::vector<ResolvedState>& states, const EffectModel& model) {
  Summarizer s{model, {}};
  bool d3d9_alpha_states = false;
  for (const ResolvedState& r : states) {
    if (!r.info || r.kind == StateValueKind::invalid) continue;
    if (r.info->api == StateApi::d3d9 && is_d3d9_blend_field(r.info->field)) d3d9_alpha_states = true;
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
  for (const ResolvedState& s : states)
    if (s.info && s.kind != StateValueKind::invalid) write_sampler(s, d, texture);
  if (!d.anisotropic) d.max_anisotropy = 1;
  return d;
}

}  // namespace fx::model_detail
