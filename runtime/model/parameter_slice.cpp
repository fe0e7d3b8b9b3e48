// find_slice: a reflected member path walked through the model's parameter types.
#include "fx/model/parameter_slice.h"

namespace fx {
namespace {

// The end of the name starting at `from`: the next '.' or '['.
size_t name_end(std::string_view path, size_t from) {
  size_t e = from;
  while (e < path.size() && path[e] != '.' && path[e] != '[') ++e;
  return e;
}

// Moves `s` to element `k` of its array type; false when out of range.
bool step_element(ParameterSlice& s, uint32_t k) {
  if (!s.type.is_array() || k >= s.type.array_dims[0]) return false;
  s.type = s.type.element_type();
  s.first_word += k * s.type.component_count();
  return true;
}

// Moves `s` to its struct member `name`; false when it has none.
bool step_member(ParameterSlice& s, std::string_view name) {
  if (s.type.is_array() || s.type.cls != TypeClass::structure || !s.type.structure) return false;
  const StructMember* m = s.type.structure->find(name);
  if (!m) return false;
  s.first_word += m->component_offset;
  s.type = m->type;
  return true;
}

// The index between '[' at `open` and the next ']'; nullopt when malformed.
std::optional<uint32_t> parse_index(std::string_view path, size_t open, size_t& close) {
  close = path.find(']', open);
  if (close == std::string_view::npos) return std::nullopt;
  uint32_t k = 0;
  for (size_t c = open + 1; c < close; ++c) {
    if (path[c] < '0' || path[c] > '9') return std::nullopt;
    k = k * 10 + static_cast<uint32_t>(path[c] - '0');
    if (k > (1u << 24)) return std::nullopt;
  }
  return k;
}

}  // namespace

std::optional<ParameterSlice> find_slice(const EffectModel& model, std::string_view path, bool* implied) {
  size_t i = name_end(path, 0);
  ParameterSlice s;
  s.parameter = model.find_parameter(path.substr(0, i));
  if (s.parameter == kNoIndex) return std::nullopt;
  s.type = model.parameters[s.parameter].type;
  if (!s.type.is_numeric() && s.type.cls != TypeClass::structure) return std::nullopt;
  while (i < path.size()) {
    if (path[i] == '[') {
      size_t close = 0;
      std::optional<uint32_t> k = parse_index(path, i, close);
      if (!k || !step_element(s, *k)) return std::nullopt;
      i = close + 1;
    } else if (path[i] == '.') {
      if (s.type.is_array() && s.type.array_dims[0] > 0) {
        step_element(s, 0);
        if (implied) *implied = true;
      }
      const size_t e = name_end(path, i + 1);
      if (!step_member(s, path.substr(i + 1, e - i - 1))) return std::nullopt;
      i = e;
    } else {
      return std::nullopt;
    }
  }
  if (s.type.cls == TypeClass::structure || s.type.component_count() == 0) return std::nullopt;
  return s;
}

}  // namespace fx
