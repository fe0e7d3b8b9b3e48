// fx::UniformBlockLayout: a linked pass program's uniform blocks laid out over the effect's
// parameters, where the compiler's reflection meets the model: per member the parameter
// slice it holds, its offset and strides and the matrix order its words are packed in.
// The Vulkan binding hands these to ParameterStore::bind_layout as they are.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "fx/compile/effect_programs.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"

namespace fx {

// One uniform block of a program (set 0).
struct UniformBlockLayout {
  std::string name;  // as reflected ("$Global", a cbuffer's name)
  uint32_t binding = 0;
  uint32_t size = 0;                       // bytes
  std::vector<BlockMemberLayout> members;  // each parameter word range once
  // Reflected members no parameter holds (a struct without member paths, a name the
  // effect does not declare): left zero in the block.
  std::vector<std::string> unplaced;
};

// The uniform blocks of `program` (compiled and linked), in its layout's binding order,
// each member's layout from the first stage in pipeline order that uses the block. An HLSL
// matrix keeps its parameter's declared order; in a GLSL program a matrix is packed row by
// row (a GLSL mat4 M * v stores HLSL's mul(v, M) transposed: column c of the GLSL matrix is
// row c of M). An unindexed alias of an array-of-structs member ("lights.color", element
// 0's) that the block also lists by its index is left out: those words are packed once.
std::vector<UniformBlockLayout> uniform_layouts(const EffectModel& model, const PassProgram& program);

}  // namespace fx
