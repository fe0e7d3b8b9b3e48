// fx_5_0 dynamic linkage: the class instances an interface variable can be bound to. FX11's
// SetClassInstance takes a class instance variable of the effect; fxkit numbers them (array
// elements one by one) in declaration order, and an interface variable holds that number.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "fx/ast.h"

namespace fx {

struct BindableInstance {
  std::string name;                  // `g_sun`, or `g_lamps[1]` for an array element
  const ast::Struct* cls = nullptr;  // its class
};

// The class instance variables of `effect` (globals of a class type, elements of arrays
// sized by a literal) whose class implements the interface named `iface`, itself or through a
// class it derives from; the index is the instance's id.
std::vector<BindableInstance> bindable_instances(const ast::Effect& effect, std::string_view iface);

// The interface named `name` declared in `effect`, or null.
const ast::Struct* find_interface(const ast::Effect& effect, std::string_view name);

}  // namespace fx
