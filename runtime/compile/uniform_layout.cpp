// uniform_layouts: reflected uniform blocks joined to the model's parameters.
#include "fx/compile/uniform_layout.h"

#include <algorithm>

namespace fx {
namespace {

bool is_glsl(const PassProgram& program) {
  if (!program.pass) return false;
  return std::any_of(program.pass->stages.begin(), program.pass->stages.end(),
                     [](const StageUnit& s) { return s.kind == StageSourceKind::glsl; });
}

// The reflected block at `binding`, from the first stage in pipeline order that has it.
const UniformBlock* reflected_block(const PassProgram& program, uint32_t binding) {
  const UniformBlock* found = nullptr;
  ShaderStage first{};
  for (const StageProgram& s : program.stages)
    for (const UniformBlock& u : s.shader.reflection.uniform_blocks)
      if (u.binding == binding && (!found || s.shader.reflection.stage < first)) {
        found = &u;
        first = s.shader.reflection.stage;
      }
  return found;
}

bool same_words(const ParameterSlice& a, const ParameterSlice& b) {
  return a.parameter == b.parameter && a.first_word == b.first_word && a.type.same_as(b.type);
}

// The members of `reflected` placed over the parameters.
void place_members(const EffectModel& model, const UniformBlock& reflected, bool glsl, UniformBlockLayout& out) {
  struct Found {
    ParameterSlice slice;
    bool implied = false;
  };
  std::vector<std::optional<Found>> found;
  for (const BlockMember& m : reflected.members) {
    bool implied = false;
    std::optional<ParameterSlice> slice = find_slice(model, m.name, &implied);
    if (slice) found.push_back(Found{std::move(*slice), implied});
    else found.emplace_back();
  }
  for (size_t k = 0; k < found.size(); ++k) {
    const BlockMember& m = reflected.members[k];
    if (!found[k]) {
      out.unplaced.push_back(m.name);
      continue;
    }
    // An unindexed alias of words another member names (by its index, or an earlier alias).
    bool packed_elsewhere = false;
    for (size_t j = 0; j < found.size() && found[k]->implied && !packed_elsewhere; ++j)
      packed_elsewhere =
          j != k && found[j] && same_words(found[j]->slice, found[k]->slice) && (!found[j]->implied || j < k);
    if (packed_elsewhere) continue;
    const MatrixPacking order =
        glsl ? MatrixPacking::row_major : model.parameters[found[k]->slice.parameter].type.order;
    out.members.push_back(
        {std::move(found[k]->slice), m.offset, m.size, m.array_stride, m.matrix_stride ? m.matrix_stride : 16u, order});
  }
}

}  // namespace

std::vector<UniformBlockLayout> uniform_layouts(const EffectModel& model, const PassProgram& program) {
  std::vector<UniformBlockLayout> blocks;
  const bool glsl = is_glsl(program);
  for (const ProgramBinding& b : program.layout.bindings) {
    if (b.kind != DescriptorKind::uniform_buffer) continue;
    UniformBlockLayout& block = blocks.emplace_back();
    block.name = b.name;
    block.binding = b.binding;
    if (const UniformBlock* reflected = reflected_block(program, b.binding)) {
      block.size = reflected->size;
      place_members(model, *reflected, glsl, block);
    }
  }
  return blocks;
}

}  // namespace fx
