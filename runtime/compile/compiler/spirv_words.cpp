#include "spirv_words.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace fx::spirv {
namespace {

// Opcodes and decorations from the SPIR-V 1.6 specification (stable numbers).
constexpr uint32_t kOpExtension = 10;
constexpr uint32_t kOpDecorate = 71;
constexpr uint32_t kOpVariable = 59;
constexpr uint32_t kOpDecorateId = 332;
constexpr uint32_t kOpDecorateString = 5632;
constexpr uint32_t kOpMemberDecorateString = 5633;
constexpr uint32_t kDecorationLocation = 30;
constexpr uint32_t kDecorationBinding = 33;
constexpr uint32_t kDecorationDescriptorSet = 34;
constexpr uint32_t kDecorationHlslCounterBuffer = 5634;
constexpr uint32_t kDecorationUserSemantic = 5635;
constexpr uint32_t kDecorationUserTypeGOOGLE = 5636;
constexpr uint32_t kStorageInput = 1;
constexpr uint32_t kStorageOutput = 3;
constexpr uint32_t kDecorationBuiltIn = 11;
constexpr uint32_t kBuiltInPosition = 0;
constexpr size_t kHeaderWords = 5;

// Calls f(offset, opcode, word_count) per instruction; stops at a malformed one.
template <class F>
bool for_each_instruction(const std::vector<uint32_t>& w, F&& f) {
  if (w.size() < kHeaderWords || w[0] != kMagic) return false;
  for (size_t i = kHeaderWords; i < w.size();) {
    uint32_t count = w[i] >> 16, op = w[i] & 0xffff;
    if (count == 0 || i + count > w.size()) return false;
    f(i, op, count);
    i += count;
  }
  return true;
}

std::string literal_string(const std::vector<uint32_t>& w, size_t begin, size_t end) {
  std::string s;
  for (size_t i = begin; i < end; ++i)
    for (int b = 0; b < 4; ++b) {
      char c = static_cast<char>((w[i] >> (8 * b)) & 0xff);
      if (c == 0) return s;
      s.push_back(c);
    }
  return s;
}

}  // namespace

namespace {

// Locations and semantics of one side's variables, by result id.
struct InterfaceVariables {
  std::map<uint32_t, uint32_t> location_of;     // id -> location
  std::map<uint32_t, std::string> semantic_of;  // id -> upper-case semantic
  std::map<uint32_t, size_t> location_word;     // id -> index of the Location literal
};

InterfaceVariables interface_variables(const std::vector<uint32_t>& w, Interface side) {
  InterfaceVariables v;
  std::map<uint32_t, bool> on_side;
  const uint32_t storage = side == Interface::input ? kStorageInput : kStorageOutput;
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if (op == kOpVariable && count >= 4 && w[i + 3] == storage) on_side[w[i + 2]] = true;
  });
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if (count < 4 || !on_side.count(w[i + 1])) return;
    if (op == kOpDecorateString && w[i + 2] == kDecorationUserSemantic) {
      std::string s = literal_string(w, i + 3, i + count);
      for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      v.semantic_of[w[i + 1]] = s;
    } else if (op == kOpDecorate && w[i + 2] == kDecorationLocation) {
      v.location_of[w[i + 1]] = w[i + 3];
      v.location_word[w[i + 1]] = i + 3;
    }
  });
  return v;
}

}  // namespace

std::map<uint32_t, std::string> interface_semantics(const std::vector<uint32_t>& w, Interface side) {
  InterfaceVariables v = interface_variables(w, side);
  std::map<uint32_t, std::string> out;
  for (auto& [id, semantic] : v.semantic_of)
    if (auto loc = v.location_of.find(id); loc != v.location_of.end()) out[loc->second] = semantic;
  return out;
}

std::optional<uint32_t> promote_position(std::vector<uint32_t>& w, Interface side,
                                         std::initializer_list<std::string_view> semantics) {
  constexpr uint32_t kOpTypeFloat = 22, kOpTypeVector = 23, kOpTypePointer = 32;
  constexpr uint32_t kBuiltInFragCoord = 15;
  InterfaceVariables v = interface_variables(w, side);
  // FragCoord is a float4: the input's variable -> pointer -> vector of 4 -> 32-bit float.
  std::map<uint32_t, uint32_t> type_of, pointee_of, vec4_component;
  std::set<uint32_t> float32;
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if (op == kOpVariable && count >= 4) type_of[w[i + 2]] = w[i + 1];
    if (op == kOpTypePointer && count >= 4) pointee_of[w[i + 1]] = w[i + 3];
    if (op == kOpTypeVector && count >= 4 && w[i + 3] == 4) vec4_component[w[i + 1]] = w[i + 2];
    if (op == kOpTypeFloat && count >= 3 && w[i + 2] == 32) float32.insert(w[i + 1]);
  });
  auto is_float4 = [&](uint32_t id) {
    auto component = vec4_component.find(pointee_of[type_of[id]]);
    return component != vec4_component.end() && float32.count(component->second);
  };
  for (auto& [id, semantic] : v.semantic_of) {
    if (std::find(semantics.begin(), semantics.end(), semantic) == semantics.end()) continue;
    auto word = v.location_word.find(id);
    if (word == v.location_word.end() || (side == Interface::input && !is_float4(id))) continue;
    // OpDecorate %id Location N  ->  OpDecorate %id BuiltIn Position|FragCoord (same length).
    uint32_t old_location = w[word->second];
    w[word->second - 1] = kDecorationBuiltIn;
    w[word->second] = side == Interface::output ? kBuiltInPosition : kBuiltInFragCoord;
    return old_location;
  }
  return std::nullopt;
}

size_t remap_locations(std::vector<uint32_t>& w, Interface side, const std::map<uint32_t, uint32_t>& remap) {
  InterfaceVariables v = interface_variables(w, side);
  size_t changed = 0;
  for (auto& [id, word] : v.location_word)
    if (auto it = remap.find(w[word]); it != remap.end() && it->second != w[word]) {
      w[word] = it->second;
      ++changed;
    }
  return changed;
}

bool strip_hlsl_semantics(std::vector<uint32_t>& w) {
  std::vector<uint32_t> kept;
  kept.reserve(w.size());
  bool ok = for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    bool drop = false;
    if (op == kOpExtension) {
      std::string name = literal_string(w, i + 1, i + count);
      drop = name == "SPV_GOOGLE_hlsl_functionality1" || name == "SPV_GOOGLE_decorate_string" ||
             name == "SPV_GOOGLE_user_type";
    } else if (op == kOpDecorateString || op == kOpMemberDecorateString) {
      drop = true;  // only UserSemantic / UserTypeGOOGLE use string decorations
    } else if (op == kOpDecorateId && count >= 3) {
      drop = w[i + 2] == kDecorationHlslCounterBuffer;
    } else if (op == kOpDecorate && count >= 3) {
      drop = w[i + 2] == kDecorationUserTypeGOOGLE;
    }
    if (!drop) kept.insert(kept.end(), w.begin() + static_cast<long>(i), w.begin() + static_cast<long>(i + count));
  });
  if (!ok) return false;
  std::vector<uint32_t> out(w.begin(), w.begin() + kHeaderWords);
  out.insert(out.end(), kept.begin(), kept.end());
  w = std::move(out);
  return true;
}

size_t variable_image_offsets(const std::vector<uint32_t>& w) {
  constexpr uint32_t kOpConstant = 43, kOpConstantComposite = 44, kOpConstantNull = 46;
  constexpr uint32_t kImageOperandsOffset = 0x10;
  std::vector<bool> constant;
  // The word of the image operands mask, by opcode: after result type, result, image,
  // coordinate (and the depth reference where there is one). Gathers may keep Offset.
  auto mask_word = [](uint32_t op) -> uint32_t {
    switch (op) {
      case 87:
      case 88:
      case 91:
      case 92:
      case 95: return 5;  // Sample(Proj)(Implicit|Explicit)Lod, Fetch
      case 89:
      case 90:
      case 93:
      case 94: return 6;  // Sample(Proj)Dref...
      default: return 0;
    }
  };
  size_t found = 0;
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if ((op == kOpConstant || op == kOpConstantComposite || op == kOpConstantNull) && count >= 3) {
      if (constant.size() <= w[i + 2]) constant.resize(w[i + 2] + 1, false);
      constant[w[i + 2]] = true;
      return;
    }
    const uint32_t at = mask_word(op);
    if (!at || count <= at || !(w[i + at] & kImageOperandsOffset)) return;
    // Operands follow the mask in bit order: Bias, Lod, Grad (two ids), then Offset.
    const uint32_t mask = w[i + at];
    const uint32_t operand = at + 1 + ((mask & 0x1) ? 1 : 0) + ((mask & 0x2) ? 1 : 0) + ((mask & 0x4) ? 2 : 0);
    if (operand < count && !(w[i + operand] < constant.size() && constant[w[i + operand]])) ++found;
  });
  return found;
}

size_t request_loop_unroll(std::vector<uint32_t>& w) {
  constexpr uint32_t kOpLoopMerge = 246, kUnroll = 0x1, kDontUnroll = 0x2;
  std::vector<size_t> controls;  // word index of each loop's control mask
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if (op == kOpLoopMerge && count >= 4) controls.push_back(i + 3);
  });
  for (size_t at : controls) w[at] = (w[at] | kUnroll) & ~kDontUnroll;
  return controls.size();
}

size_t scalar_any_all(std::vector<uint32_t>& w) {
  constexpr uint32_t kOpTypeBool = 20, kOpConstantTrue = 41, kOpConstantFalse = 42, kOpSpecConstantTrue = 48,
                     kOpSpecConstantFalse = 49, kOpFunction = 54, kOpCopyObject = 83, kOpAny = 154, kOpAll = 155;
  std::set<uint32_t> bool_type, bool_value;
  std::vector<size_t> rewrite;
  bool in_function = false;
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if (op == kOpFunction) in_function = true;
    if (op == kOpTypeBool && count == 2) bool_type.insert(w[i + 1]);
    // Inside functions every instruction whose first operand is the bool type has it as its
    // result type; outside, only the constants do (OpName or OpDecorate may name the type).
    const bool typed = in_function || op == kOpConstantTrue || op == kOpConstantFalse || op == kOpSpecConstantTrue ||
                       op == kOpSpecConstantFalse;
    if (typed && count >= 3 && bool_type.count(w[i + 1])) {
      if ((op == kOpAny || op == kOpAll) && count == 4 && bool_value.count(w[i + 3])) rewrite.push_back(i);
      bool_value.insert(w[i + 2]);
    }
  });
  for (size_t at : rewrite) w[at] = (4u << 16) | kOpCopyObject;
  return rewrite.size();
}

bool opaque_values_in_memory(const std::vector<uint32_t>& w) {
  constexpr uint32_t kOpTypeImage = 25, kOpTypeSampler = 26, kOpTypeSampledImage = 27, kOpTypeArray = 28,
                     kOpTypeRuntimeArray = 29, kOpTypeStruct = 30, kOpTypePointer = 32, kOpFunctionParameter = 55,
                     kOpTypeAccelerationStructure = 5341, kStorageUniformConstant = 0;
  std::set<uint32_t> opaque, opaque_pointer;  // types; pointers to opaque types outside UniformConstant
  bool found = false;
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if (found || count < 2) return;
    const uint32_t result = w[i + 1];
    switch (op) {
      case kOpTypeImage:
      case kOpTypeSampler:
      case kOpTypeSampledImage:
      case kOpTypeAccelerationStructure: opaque.insert(result); break;
      case kOpTypeArray:
      case kOpTypeRuntimeArray:
        if (count >= 3 && opaque.count(w[i + 2])) opaque.insert(result);
        break;
      case kOpTypeStruct:
        for (uint32_t k = 2; k < count; ++k)
          if (opaque.count(w[i + k])) opaque.insert(result);
        break;
      case kOpTypePointer:
        if (count >= 4 && w[i + 2] != kStorageUniformConstant && opaque.count(w[i + 3])) opaque_pointer.insert(result);
        break;
      case kOpVariable: found = count >= 4 && opaque_pointer.count(w[i + 1]); break;
      case kOpFunctionParameter:
        found = count >= 3 && (opaque_pointer.count(w[i + 1]) || opaque.count(w[i + 1]));
        break;
      default: break;
    }
  });
  return found;
}

std::set<uint32_t> read_input_locations(const std::vector<uint32_t>& w) {
  constexpr uint32_t kOpExtInst = 12, kOpFunctionCall = 57, kOpLoad = 61, kOpCopyMemory = 63, kOpAccessChain = 65,
                     kOpInBoundsAccessChain = 66, kOpCopyObject = 83;
  InterfaceVariables inputs = interface_variables(w, Interface::input);
  std::set<uint32_t> read;
  auto note = [&](uint32_t id) {
    if (auto it = inputs.location_of.find(id); it != inputs.location_of.end()) read.insert(it->second);
  };
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    // The word where the id operands start: after the result type and id (and for OpExtInst
    // the set and instruction number); OpCopyMemory has no result.
    uint32_t first = 0;
    switch (op) {
      case kOpLoad:
      case kOpAccessChain:
      case kOpInBoundsAccessChain:
      case kOpCopyObject: first = 3, count = std::min(count, 4u); break;
      case kOpCopyMemory: first = 2, count = std::min(count, 3u); break;
      case kOpFunctionCall: first = 4; break;
      case kOpExtInst: first = 5; break;
      default: return;
    }
    for (uint32_t k = first; k < count; ++k) note(w[i + k]);
  });
  return read;
}

std::map<uint32_t, SetBinding> variable_bindings(const std::vector<uint32_t>& w) {
  std::map<uint32_t, SetBinding> out;
  std::map<uint32_t, bool> has_binding;
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if (op != kOpDecorate || count < 4) return;
    if (w[i + 2] == kDecorationDescriptorSet) out[w[i + 1]].first = w[i + 3];
    if (w[i + 2] == kDecorationBinding) out[w[i + 1]].second = w[i + 3], has_binding[w[i + 1]] = true;
  });
  for (auto it = out.begin(); it != out.end();) it = has_binding.count(it->first) ? std::next(it) : out.erase(it);
  return out;
}

size_t remap_bindings(std::vector<uint32_t>& w, const std::map<SetBinding, SetBinding>& remap) {
  std::map<uint32_t, SetBinding> targets;
  for (auto& [id, pair] : variable_bindings(w)) {
    auto it = remap.find(pair);
    if (it != remap.end() && it->second != pair) targets[id] = it->second;
  }
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    if (op != kOpDecorate || count < 4) return;
    auto it = targets.find(w[i + 1]);
    if (it == targets.end()) return;
    if (w[i + 2] == kDecorationDescriptorSet) w[i + 3] = it->second.first;
    if (w[i + 2] == kDecorationBinding) w[i + 3] = it->second.second;
  });
  return targets.size();
}

bool pad_output(std::vector<uint32_t>& w, uint32_t location, uint32_t first, uint32_t count, Scalar scalar) {
  constexpr uint32_t kOpEntryPoint = 15, kOpTypeInt = 21, kOpTypeFloat = 22, kOpTypeVector = 23, kOpTypePointer = 32,
                     kOpConstant = 43, kOpConstantComposite = 44, kOpFunction = 54, kOpStore = 62, kOpEmitVertex = 218,
                     kOpEmitStreamVertex = 220, kOpLabel = 248, kOpLine = 8, kOpNoLine = 317, kDecorationComponent = 31;
  constexpr uint32_t kVertex = 0, kTessellationEvaluation = 2, kGeometry = 3;
  if (count == 0 || first + count > 4) return false;
  size_t entry_at = 0, first_type_at = 0, first_function_at = 0;
  uint32_t scalar_type = 0;
  const bool is_float = scalar == Scalar::float32;
  bool ok = for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t n) {
    if (op == kOpEntryPoint && !entry_at && n >= 3) entry_at = i;
    if (op >= 19 && op <= 39 && !first_type_at) first_type_at = i;  // OpTypeVoid .. OpTypeForwardPointer
    if (op == kOpFunction && !first_function_at) first_function_at = i;
    if (is_float && op == kOpTypeFloat && n == 3 && w[i + 2] == 32) scalar_type = w[i + 1];
    if (!is_float && op == kOpTypeInt && n == 4 && w[i + 2] == 32 && w[i + 3] == (scalar == Scalar::int32 ? 1u : 0u))
      scalar_type = w[i + 1];
  });
  if (!ok || !entry_at || !first_type_at || !first_function_at) return false;
  const uint32_t model = w[entry_at + 1], entry = w[entry_at + 2];
  if (model != kVertex && model != kTessellationEvaluation && model != kGeometry) return false;

  uint32_t bound = w[3];
  std::vector<uint32_t> globals;  // new types, constants and the variable, before the functions
  auto emit = [](std::vector<uint32_t>& to, uint32_t op, std::initializer_list<uint32_t> operands) {
    to.push_back(uint32_t(operands.size() + 1) << 16 | op);
    to.insert(to.end(), operands);
  };
  if (!scalar_type) {
    scalar_type = bound++;
    if (is_float) emit(globals, kOpTypeFloat, {scalar_type, 32});
    else emit(globals, kOpTypeInt, {scalar_type, 32, scalar == Scalar::int32 ? 1u : 0u});
  }
  uint32_t value_type = scalar_type, pointer_type = 0;
  if (count > 1) {
    value_type = 0;
    for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t n) {
      if (op == kOpTypeVector && n == 4 && w[i + 2] == scalar_type && w[i + 3] == count) value_type = w[i + 1];
    });
    if (!value_type) emit(globals, kOpTypeVector, {value_type = bound++, scalar_type, count});
  }
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t n) {
    if (op == kOpTypePointer && n == 4 && w[i + 2] == kStorageOutput && w[i + 3] == value_type) pointer_type = w[i + 1];
  });
  if (!pointer_type) emit(globals, kOpTypePointer, {pointer_type = bound++, kStorageOutput, value_type});
  const uint32_t zero = bound++, one = bound++;
  emit(globals, kOpConstant, {scalar_type, zero, 0});
  emit(globals, kOpConstant, {scalar_type, one, is_float ? 0x3f800000u : 1u});
  std::vector<uint32_t> parts;
  for (uint32_t c = first; c < first + count; ++c) parts.push_back(c == 3 ? one : zero);
  uint32_t value = parts.front();
  if (count > 1) {
    value = bound++;
    globals.push_back(uint32_t(parts.size() + 3) << 16 | kOpConstantComposite);
    globals.insert(globals.end(), {value_type, value});
    globals.insert(globals.end(), parts.begin(), parts.end());
  }
  const uint32_t variable = bound++;
  emit(globals, kOpVariable, {pointer_type, variable, kStorageOutput});
  std::vector<uint32_t> decorations, store;
  emit(decorations, kOpDecorate, {variable, kDecorationLocation, location});
  emit(decorations, kOpDecorate, {variable, kDecorationComponent, first});
  emit(store, kOpStore, {variable, value});

  // Where the stores go: before each emitted vertex, or once where the entry's code starts.
  std::vector<size_t> store_at;
  bool in_entry = false, at_start = false;
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t) {
    if (model == kGeometry) {
      if (op == kOpEmitVertex || op == kOpEmitStreamVertex) store_at.push_back(i);
      return;
    }
    if (op == kOpFunction) in_entry = w[i + 2] == entry;
    if (!in_entry) return;
    if (op == kOpLabel && store_at.empty() && !at_start) {
      at_start = true;
      return;
    }
    if (at_start && op != kOpVariable && op != kOpLine && op != kOpNoLine) {
      store_at.push_back(i);
      at_start = false;
    }
  });
  if (store_at.empty()) return false;

  // Insert from the back so the earlier offsets stay valid.
  for (auto at = store_at.rbegin(); at != store_at.rend(); ++at)
    w.insert(w.begin() + long(*at), store.begin(), store.end());
  w.insert(w.begin() + long(first_function_at), globals.begin(), globals.end());
  w.insert(w.begin() + long(first_type_at), decorations.begin(), decorations.end());
  const uint32_t entry_words = w[entry_at] >> 16;
  w.insert(w.begin() + long(entry_at + entry_words), variable);
  w[entry_at] = (entry_words + 1) << 16 | kOpEntryPoint;
  w[3] = bound;
  return true;
}

bool decorate_transform_feedback(std::vector<uint32_t>& w, const std::vector<XfbOutput>& outputs) {
  constexpr uint32_t kOpCapability = 17, kOpEntryPoint = 15, kOpExecutionMode = 16, kCapabilityTransformFeedback = 53,
                     kExecutionModeXfb = 11, kDecorationOffset = 35, kDecorationXfbBuffer = 36,
                     kDecorationXfbStride = 37;
  const InterfaceVariables v = interface_variables(w, Interface::output);
  std::set<uint32_t> outputs_declared;
  size_t capability_at = 0, entry_at = 0, first_type_at = 0;
  uint32_t position = 0;
  bool ok = for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t n) {
    if (op == kOpCapability && !capability_at) capability_at = i;
    if (op == kOpEntryPoint && !entry_at && n >= 3) entry_at = i;
    if (op >= 19 && op <= 39 && !first_type_at) first_type_at = i;  // OpTypeVoid .. OpTypeForwardPointer
    if (op == kOpVariable && n >= 4 && w[i + 3] == kStorageOutput) outputs_declared.insert(w[i + 2]);
  });
  if (!ok || !capability_at || !entry_at || !first_type_at) return false;
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t n) {
    if (op == kOpDecorate && n == 4 && w[i + 2] == kDecorationBuiltIn && w[i + 3] == kBuiltInPosition &&
        outputs_declared.count(w[i + 1]))
      position = w[i + 1];
  });
  std::vector<uint32_t> decorations;
  for (const XfbOutput& out : outputs) {
    uint32_t variable = 0;
    if (!out.location) variable = position;
    for (const auto& [id, location] : v.location_of)
      if (out.location && location == *out.location) variable = id;
    if (!variable) return false;
    for (auto [decoration, value] :
         {std::pair{kDecorationXfbBuffer, out.buffer}, std::pair{kDecorationXfbStride, out.stride},
          std::pair{kDecorationOffset, out.offset}})
      decorations.insert(decorations.end(), {4u << 16 | kOpDecorate, variable, decoration, value});
  }
  // From the back, so the earlier offsets stay valid: decorations before the first type, the
  // execution mode after the entry point, the capability beside the first.
  w.insert(w.begin() + long(first_type_at), decorations.begin(), decorations.end());
  const uint32_t entry = w[entry_at + 2];
  const std::initializer_list<uint32_t> mode = {3u << 16 | kOpExecutionMode, entry, kExecutionModeXfb};
  w.insert(w.begin() + long(entry_at + (w[entry_at] >> 16)), mode);
  const std::initializer_list<uint32_t> capability = {2u << 16 | kOpCapability, kCapabilityTransformFeedback};
  w.insert(w.begin() + long(capability_at), capability);
  return true;
}

std::set<SetBinding> depth_compared_bindings(const std::vector<uint32_t>& w) {
  constexpr uint32_t kOpLoad = 61, kOpAccessChain = 65, kOpInBoundsAccessChain = 66, kOpCopyObject = 83,
                     kOpSampledImage = 86;
  // Result id -> the ids it was made from, back to the variables.
  std::map<uint32_t, std::vector<uint32_t>> sources;
  std::vector<uint32_t> compared;  // the sampled images of depth-comparing instructions
  for_each_instruction(w, [&](size_t i, uint32_t op, uint32_t count) {
    switch (op) {
      case kOpLoad:
      case kOpAccessChain:
      case kOpInBoundsAccessChain:
      case kOpCopyObject:
        if (count >= 4) sources[w[i + 2]].push_back(w[i + 3]);
        break;
      case kOpSampledImage:
        if (count >= 5) sources[w[i + 2]] = {w[i + 3], w[i + 4]};
        break;
      case 89:
      case 90:
      case 91:
      case 92:
      case 97:  // OpImage(Proj)SampleDref*, OpImageDrefGather
      case 305:
      case 306:
      case 309:
      case 310:
      case 315:  // their sparse forms
        if (count >= 4) compared.push_back(w[i + 3]);
        break;
      default: break;
    }
  });
  const std::map<uint32_t, SetBinding> bindings = variable_bindings(w);
  std::set<SetBinding> out;
  std::set<uint32_t> seen;
  while (!compared.empty()) {
    const uint32_t id = compared.back();
    compared.pop_back();
    if (!seen.insert(id).second) continue;
    if (auto b = bindings.find(id); b != bindings.end()) out.insert(b->second);
    if (auto s = sources.find(id); s != sources.end())
      compared.insert(compared.end(), s->second.begin(), s->second.end());
  }
  return out;
}

}  // namespace fx::spirv
