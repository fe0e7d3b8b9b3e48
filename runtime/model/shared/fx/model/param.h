// fxkit::Param: the handle of a parameter, an array element or a struct member of one
// parameter store, shared by the store (fx::ParameterStore) and the public API (fxkit::Effect).
#pragma once
#include <cstdint>
#include <limits>

namespace fxkit {

// `generation` is the store generation it was issued in; handles from before a reload (a
// remap of the store) are translated, so a handle stays valid across reloads. Invalid handles
// make every set() return false and change nothing.
struct Param {
  uint32_t index = std::numeric_limits<uint32_t>::max();
  uint32_t generation = 0;
  bool valid() const { return index != std::numeric_limits<uint32_t>::max(); }
  friend bool operator==(Param, Param) = default;
};

}  // namespace fxkit
