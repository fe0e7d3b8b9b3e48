// The patch sizes of a tessellation control shader, read from its SPIR-V.
#include "tessellation_patch.h"

#include <map>
#include <set>
#include <utility>
#include <vector>

namespace fx::vk {

PatchSizes tessellation_patch_sizes(std::span<const uint32_t> w) {
  constexpr uint32_t kOpEntryPoint = 15, kOpExecutionMode = 16, kOpTypeArray = 28, kOpTypePointer = 32,
                     kOpConstant = 43, kOpVariable = 59, kOpDecorate = 71;
  constexpr uint32_t kTessellationControl = 1, kOutputVertices = 26, kDecorationPatch = 15, kInput = 1;
  constexpr uint32_t kMaxPatchVertices = 32;  // glslang's default gl_MaxPatchVertices
  bool control = false;
  PatchSizes sizes;
  std::set<uint32_t> per_patch;                       // variables decorated Patch
  std::map<uint32_t, uint32_t> constants;             // id -> 32-bit value
  std::map<uint32_t, uint32_t> array_lengths;         // array type id -> length constant id
  std::map<uint32_t, uint32_t> input_pointees;        // Input pointer type id -> pointee
  std::vector<std::pair<uint32_t, uint32_t>> inputs;  // (variable, pointer type)
  for (size_t i = 5; i < w.size();) {
    const uint32_t words = w[i] >> 16, op = w[i] & 0xffffu;
    if (words == 0 || i + words > w.size()) break;
    if (op == kOpEntryPoint && words >= 3 && w[i + 1] == kTessellationControl) control = true;
    if (op == kOpExecutionMode && words >= 4 && w[i + 2] == kOutputVertices) sizes.output = w[i + 3];
    if (op == kOpDecorate && words >= 3 && w[i + 2] == kDecorationPatch) per_patch.insert(w[i + 1]);
    if (op == kOpConstant && words >= 4) constants[w[i + 2]] = w[i + 3];
    if (op == kOpTypeArray && words >= 4) array_lengths[w[i + 1]] = w[i + 3];
    if (op == kOpTypePointer && words >= 4 && w[i + 2] == kInput) input_pointees[w[i + 1]] = w[i + 3];
    if (op == kOpVariable && words >= 4 && w[i + 3] == kInput) inputs.emplace_back(w[i + 2], w[i + 1]);
    i += words;
  }
  if (!control) return {};
  for (const auto& [variable, pointer] : inputs) {
    if (per_patch.count(variable)) continue;
    auto pointee = input_pointees.find(pointer);
    if (pointee == input_pointees.end()) continue;
    auto length = array_lengths.find(pointee->second);  // scalars: InvocationId, PrimitiveId...
    if (length == array_lengths.end()) continue;
    auto value = constants.find(length->second);
    if (value == constants.end() || value->second == 0 || value->second == kMaxPatchVertices) continue;
    sizes.input = value->second;
    break;
  }
  if (!sizes.input) sizes.input = sizes.output;
  return sizes;
}

}  // namespace fx::vk
