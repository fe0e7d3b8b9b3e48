// fx::ParameterSlice: the words of one parameter, struct member or array element that a
// uniform block member holds, found from a reflected member path ("light.dir", "bones[3]").
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

#include "fx/model/effect_model.h"

namespace fx {

// Words [first_word, first_word + type.component_count()) of parameter `parameter`, in the
// parameter store's order (one word per scalar component, structs flattened, matrices row
// by row): what a block member packs, and its element layout (`type`: shape, array size).
struct ParameterSlice {
  uint32_t parameter = kNoIndex;  // index into EffectModel::parameters
  uint32_t first_word = 0;
  Type type;
};

// The slice a member path names: `name`, then `.member` and `[index]` steps. A `.member`
// step on an array of structs reads its element 0 (glslang lists a dynamically indexed
// member so, "lights.color" for lights[i].color); `implied`, when given, is set then.
// nullopt when the path names nothing, or names a struct, a string or an object (no
// words a block could hold).
std::optional<ParameterSlice> find_slice(const EffectModel& model, std::string_view path, bool* implied = nullptr);

}  // namespace fx
