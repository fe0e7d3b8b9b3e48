// A double-precision CPU model of the Direct3D 9 texture-stage cascade and fixed-function
// lighting and fog, written from the D3D documentation's formulas (docs/fixed-function.md
// quotes them), independent of the HLSL generator: the tests compare the two.
#pragma once
#include <array>
#include <cmath>

#include "fx/emulation/fixed_function.h"

namespace fx::ff_model {

using Color = std::array<double, 4>;

// What the cascade reads at one pixel: the interpolated colours and each stage's texel.
struct PixelInputs {
  Color diffuse{1, 1, 1, 1}, specular{0, 0, 0, 0};
  std::array<Color, kTextureStages> texel{};  // the value stage N's texture gives
  double fog = 1;                             // fog factor (1: no fog)
};

inline double sat(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

// D3DTA argument: the register, then Complement (1 - x), then AlphaReplicate (x.aaaa).
inline Color argument(uint32_t a, const Color& diffuse, const Color& current, const Color& texture,
                      const Color& tfactor, const Color& specular, const Color& temp, const Color& constant) {
  Color v{};
  switch (a & texture_arg::select_mask) {
    case texture_arg::diffuse: v = diffuse; break;
    case texture_arg::current: v = current; break;
    case texture_arg::texture: v = texture; break;
    case texture_arg::tfactor: v = tfactor; break;
    case texture_arg::specular: v = specular; break;
    case texture_arg::temp: v = temp; break;
    case texture_arg::constant: v = constant; break;
    default: break;
  }
  if (a & texture_arg::complement)
    for (double& c : v) c = 1 - c;
  if (a & texture_arg::alpha_replicate) v = {v[3], v[3], v[3], v[3]};
  return v;
}

// One D3DTOP on one channel c (0..2 colour, 3 alpha). `blend` is the alpha the Blend*Alpha
// operations use; `next` the next stage's texel for PreModulate.
inline double operation(TextureOp op, int c, const Color& a0, const Color& a1, const Color& a2, double blend,
                        const Color& current, const Color& next, bool has_next) {
  switch (op) {
    case TextureOp::disable:
    case TextureOp::bump_env_map:
    case TextureOp::bump_env_map_luminance: return current[c];
    case TextureOp::select_arg1: return a1[c];
    case TextureOp::select_arg2: return a2[c];
    case TextureOp::modulate: return a1[c] * a2[c];
    case TextureOp::modulate_2x: return 2 * a1[c] * a2[c];
    case TextureOp::modulate_4x: return 4 * a1[c] * a2[c];
    case TextureOp::add: return a1[c] + a2[c];
    case TextureOp::add_signed: return a1[c] + a2[c] - 0.5;
    case TextureOp::add_signed_2x: return 2 * (a1[c] + a2[c] - 0.5);
    case TextureOp::subtract: return a1[c] - a2[c];
    case TextureOp::add_smooth: return a1[c] + a2[c] * (1 - a1[c]);
    case TextureOp::blend_diffuse_alpha:
    case TextureOp::blend_texture_alpha:
    case TextureOp::blend_factor_alpha:
    case TextureOp::blend_current_alpha: return a1[c] * blend + a2[c] * (1 - blend);
    case TextureOp::blend_texture_alpha_pm: return a1[c] + a2[c] * (1 - blend);
    case TextureOp::premodulate: return has_next ? a1[c] * next[c] : a1[c];
    case TextureOp::modulate_alpha_add_color: return a1[c] + a1[3] * a2[c];
    case TextureOp::modulate_color_add_alpha: return a1[c] * a2[c] + a1[3];
    case TextureOp::modulate_inv_alpha_add_color: return a1[c] + (1 - a1[3]) * a2[c];
    case TextureOp::modulate_inv_color_add_alpha: return (1 - a1[c]) * a2[c] + a1[3];
    case TextureOp::dot_product3: {
      double d = 0;
      for (int k = 0; k < 3; ++k) d += (a1[k] - 0.5) * (a2[k] - 0.5);
      return 4 * d;
    }
    case TextureOp::multiply_add: return a0[c] + a1[c] * a2[c];
    case TextureOp::lerp: return a0[c] * a1[c] + (1 - a0[c]) * a2[c];
  }
  return current[c];
}

// The cascade over the stages that run, then specular add, fog and (returned separately)
// the alpha test. Texels are taken as given: bump mapping changes coordinates, which the
// caller models when it fills `texel`.
inline Color texture_stages(const FixedFunctionState& s, const PixelInputs& in, bool* passes_alpha_test = nullptr) {
  const Color tfactor{s.texture_factor.value[0], s.texture_factor.value[1], s.texture_factor.value[2],
                      s.texture_factor.value[3]};
  Color current = in.diffuse, temp{0, 0, 0, 0};
  for (int i = 0; i < kTextureStages; ++i) {
    const TextureStageState& st = s.stages[i];
    if (st.color_op == TextureOp::disable) break;
    if (st.color_op == TextureOp::bump_env_map || st.color_op == TextureOp::bump_env_map_luminance) continue;
    const Color tex = st.texture == StageTexture::none ? Color{1, 1, 1, 1} : in.texel[i];
    const bool has_next = i + 1 < kTextureStages && s.stages[i + 1].color_op != TextureOp::disable &&
                          s.stages[i + 1].texture != StageTexture::none;
    const Color next = has_next ? in.texel[i + 1] : Color{1, 1, 1, 1};
    const Color constant{st.constant.value[0], st.constant.value[1], st.constant.value[2], st.constant.value[3]};
    auto args = [&](const std::array<uint32_t, 3>& a, Color& a0, Color& a1, Color& a2) {
      a0 = argument(a[0], in.diffuse, current, tex, tfactor, in.specular, temp, constant);
      a1 = argument(a[1], in.diffuse, current, tex, tfactor, in.specular, temp, constant);
      a2 = argument(a[2], in.diffuse, current, tex, tfactor, in.specular, temp, constant);
    };
    auto blend_alpha = [&](TextureOp op) {
      switch (op) {
        case TextureOp::blend_diffuse_alpha: return in.diffuse[3];
        case TextureOp::blend_texture_alpha:
        case TextureOp::blend_texture_alpha_pm: return tex[3];
        case TextureOp::blend_factor_alpha: return tfactor[3];
        case TextureOp::blend_current_alpha: return current[3];
        default: return 0.0;
      }
    };
    Color a0, a1, a2, result;
    args(st.color_arg, a0, a1, a2);
    for (int c = 0; c < 3; ++c)
      result[c] = sat(operation(st.color_op, c, a0, a1, a2, blend_alpha(st.color_op), current, next, has_next));
    if (st.color_op == TextureOp::dot_product3) {
      result[3] = result[0];  // D3D9: replicated into alpha as well
    } else if (st.alpha_op == TextureOp::disable || st.alpha_op == TextureOp::bump_env_map ||
               st.alpha_op == TextureOp::bump_env_map_luminance) {
      result[3] = current[3];
    } else {
      args(st.alpha_arg, a0, a1, a2);
      result[3] = sat(operation(st.alpha_op, st.alpha_op == TextureOp::dot_product3 ? 0 : 3, a0, a1, a2,
                                blend_alpha(st.alpha_op), current, next, has_next));
    }
    ((st.result_arg & texture_arg::select_mask) == texture_arg::temp ? temp : current) = result;
  }
  if (s.specular_enable)
    for (int c = 0; c < 3; ++c) current[c] = sat(current[c] + in.specular[c]);
  if (s.fog) {
    const double f = sat(in.fog);
    for (int c = 0; c < 3; ++c) current[c] = f * current[c] + (1 - f) * s.fog_color.value[c];
  }
  if (passes_alpha_test) {
    const double a = std::floor(sat(current[3]) * 255 + 0.5), ref = s.alpha_ref.value;
    bool pass = true;
    if (s.alpha_test) switch (s.alpha_func) {
        case CompareOp::never: pass = false; break;
        case CompareOp::less: pass = a < ref; break;
        case CompareOp::equal: pass = a == ref; break;
        case CompareOp::less_or_equal: pass = a <= ref; break;
        case CompareOp::greater: pass = a > ref; break;
        case CompareOp::not_equal: pass = a != ref; break;
        case CompareOp::greater_or_equal: pass = a >= ref; break;
        case CompareOp::always: pass = true; break;
      }
    *passes_alpha_test = pass;
  }
  return current;
}

// D3D9 fog factors ("Fog Formulas"): linear (end - d) / (end - start), exp e^-(d*density),
// exp2 e^-((d*density)^2), clamped to [0, 1].
inline double fog_factor(FogMode mode, double d, double start, double end, double density) {
  switch (mode) {
    case FogMode::linear: return sat((end - d) / (end - start));
    case FogMode::exp: return sat(std::exp(-d * density));
    case FogMode::exp2: return sat(std::exp(-(d * density) * (d * density)));
    default: return 1;
  }
}

}  // namespace fx::ff_model
