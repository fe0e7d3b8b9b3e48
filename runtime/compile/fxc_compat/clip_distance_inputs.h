// glslang crashes on a geometry shader whose per-vertex input array is a struct with an
// SV_ClipDistance or SV_CullDistance member (KhronosGroup/glslang#2392), the way D3D10's
// FixedFuncEMU passes its vertex struct on; it compiles the same distances given as a
// parameter of their own (`in float3 clip[3] : SV_ClipDistance0`). The unit writes the
// geometry shader so: the input array becomes a struct without those members plus one
// parameter per member, and the body starts by rebuilding the array the code reads.
// Private to runtime/compile.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "fx/ast.h"
#include "fx/token.h"

namespace fx::detail {

// Whether a semantic is a clip or cull distance.
bool is_clip_or_cull_distance(std::string_view semantic);

// The spellings, by token index, that rewrite every function with a stream parameter whose
// input array's struct (found with `structure`) has clip or cull distance members, each a
// direct member, not an array, declared alone. The functions rewritten are added to
// `rewritten`; others (a nested struct carrying the distances) are left as they are.
std::unordered_map<uint32_t, std::string> clip_distance_input_spellings(
    const std::vector<Token>& toks, const std::vector<const ast::Function*>& functions,
    const std::function<const ast::Struct*(std::string_view)>& structure,
    std::unordered_set<const ast::Function*>& rewritten);

}  // namespace fx::detail
