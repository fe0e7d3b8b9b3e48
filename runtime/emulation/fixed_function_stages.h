// Which texture stages run and what they read: shared by the pixel shader (which samples)
// and the vertex shader (which texture coordinates it must write).
#pragma once
#include <cstdint>

#include "fx/emulation/fixed_function.h"

namespace fx::ff_detail {

// Arguments an operation reads (Arg0 for MultiplyAdd and Lerp only).
bool uses_arg0(TextureOp op);
bool uses_arg1(TextureOp op);
bool uses_arg2(TextureOp op);
bool is_bump(TextureOp op);
// The stages that run: the first whose ColorOp is Disable ends the cascade.
int active_stages(const FixedFunctionState& s);
// Whether an enabled colour or alpha operation of `st` reads register `reg` (texture_arg).
bool reads_register(const TextureStageState& st, uint32_t reg);
// Whether stage `i` reads its texture's value (as an argument, its alpha, a bump map, or
// for the premodulating stage before it), bound or not.
bool reads_texture(const FixedFunctionState& s, int i);
// Whether stage `i` samples its texture: it reads it and one is bound.
bool samples(const FixedFunctionState& s, int i);

}  // namespace fx::ff_detail
