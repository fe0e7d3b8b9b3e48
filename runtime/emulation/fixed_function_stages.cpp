// Which texture stages run and what they read.
#include "fixed_function_stages.h"

namespace fx::ff_detail {

namespace ta = texture_arg;

bool uses_arg0(TextureOp op) { return op == TextureOp::multiply_add || op == TextureOp::lerp; }
bool uses_arg2(TextureOp op) {
  return op != TextureOp::select_arg1 && op != TextureOp::disable && op != TextureOp::premodulate &&
         op != TextureOp::bump_env_map && op != TextureOp::bump_env_map_luminance;
}
bool uses_arg1(TextureOp op) {
  return op != TextureOp::select_arg2 && op != TextureOp::disable && op != TextureOp::bump_env_map &&
         op != TextureOp::bump_env_map_luminance;
}
bool is_bump(TextureOp op) { return op == TextureOp::bump_env_map || op == TextureOp::bump_env_map_luminance; }

int active_stages(const FixedFunctionState& s) {
  int n = 0;
  while (n < kTextureStages && s.stages[n].color_op != TextureOp::disable) ++n;
  return n;
}

bool reads_register(const TextureStageState& st, uint32_t reg) {
  auto in = [&](TextureOp op, const std::array<uint32_t, 3>& args) {
    if (op == TextureOp::disable) return false;
    return (uses_arg0(op) && (args[0] & ta::select_mask) == reg) ||
           (uses_arg1(op) && (args[1] & ta::select_mask) == reg) ||
           (uses_arg2(op) && (args[2] & ta::select_mask) == reg);
  };
  return in(st.color_op, st.color_arg) || in(st.alpha_op, st.alpha_arg);
}

bool reads_texture(const FixedFunctionState& s, int i) {
  const TextureStageState& st = s.stages[i];
  auto op_reads_texture = [](TextureOp op) {
    return op == TextureOp::blend_texture_alpha || op == TextureOp::blend_texture_alpha_pm || is_bump(op);
  };
  if (reads_register(st, ta::texture) || op_reads_texture(st.color_op) || op_reads_texture(st.alpha_op)) return true;
  return i > 0 && s.stages[i - 1].color_op == TextureOp::premodulate;
}

bool samples(const FixedFunctionState& s, int i) {
  return s.stages[i].texture != StageTexture::none && reads_texture(s, i);
}

}  // namespace fx::ff_detail
