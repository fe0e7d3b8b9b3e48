// fx_5_0 dynamic linkage (interfaces, classes, class instances) written as HLSL glslang takes,
// which has no interfaces. An interface variable becomes an `int` uniform, the class-instance
// id the application sets (FX11's SetClassInstance); each call through an interface becomes a
// call of a dispatcher that switches over the class instances of the classes implementing
// it; a call on a class instance passes a copy of it to a wrapper (glslang writes invalid
// SPIR-V for a method called on a uniform). docs/fx11-parity.md has the mapping. Private to
// runtime/compile.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "fx/ast.h"
#include "fx/model/class_instances.h"

namespace fx::detail {

// The interfaces, classes and their instances of an effect.
struct ClassLinkage {
  std::vector<const ast::Struct*> interfaces;
  std::vector<const ast::Struct*> classes;
  std::vector<const ast::Variable*> interface_variables;  // globals of an interface type
  std::vector<const ast::Variable*> instances;            // globals of a class type
  std::vector<const ast::Variable*> buffered_instances;   // members of a class type of constant buffers
  const ast::Effect* effect = nullptr;

  bool empty() const { return interfaces.empty(); }
  const ast::Struct* interface_named(std::string_view name) const;
  const ast::Struct* class_named(std::string_view name) const;
  // The class instances an interface variable of `iface` can be bound to: the index is the
  // class-instance id.
  std::vector<BindableInstance> bindable(const ast::Struct& iface) const;
  // The id of `instance` (a class instance variable or element, spelled `g` or `g[1]`)
  // among those bindable to `iface`, or nullopt.
  std::optional<int> instance_id(const ast::Struct& iface, std::string_view instance) const;
  // The methods a call on an instance of `cls` reaches: its own, then those it inherits from
  // the classes it derives from (`class Hemi : Ambient`) and does not override.
  std::vector<const ast::Function*> methods_of(const ast::Struct& cls) const;
  // The classes `cls` derives from, the farthest first: their members come first in it.
  std::vector<const ast::Struct*> base_classes(const ast::Struct& cls) const;
};

ClassLinkage class_linkage(const ast::Effect& effect);

// Whether a function parameter is of an interface type (a uniform bound by BindInterfaces).
bool is_interface_parameter(const ClassLinkage& linkage, const ast::Variable& param);

// The spellings, by token index, that write interface-typed declarations as `int` and calls
// through interfaces and on class instances as dispatcher and wrapper calls, keeping every
// other token's column.
std::unordered_map<uint32_t, std::string> class_linkage_spellings(const std::vector<Token>& toks,
                                                                  const ClassLinkage& linkage,
                                                                  const std::vector<const ast::Function*>& functions);

// The name a call through `iface`'s method `method` is written as.
std::string dispatcher_name(std::string_view iface, std::string_view method);

// What stands in an interface's place: the prototypes of its dispatchers (defined after every
// class instance by interface_dispatchers).
std::string interface_prototypes(const std::vector<Token>& toks, const ast::Struct& iface);
// A class's method wrappers, `R C__M__fx(C self, params) { return self.M(args); }`, written
// after the class, one per method of `methods` (ClassLinkage::methods_of). A method defined
// outside its class is a function of its own (method_function_name), declared here first:
// the wrapper calls it, `return C__M__fxm(self, args);`.
std::string class_method_wrappers(const std::vector<Token>& toks, const ast::Struct& cls,
                                  const std::vector<const ast::Function*>& methods);

// A method defined outside its class (`float3 C::M(float3 n) { ... }`) is written where it is
// defined, as fxc reads it (it sees the globals declared between the class and it), as a
// function of an instance: `R C__M__fxm(inout C self, params) { ... }`, one per class that
// reaches it (a derived class gets its own copy). glslang takes member functions only
// inside their struct.
std::string method_function_name(std::string_view cls, std::string_view method);
// That function's signature, `R C__M__fxm(inout C self, params)`.
std::string method_function_signature(const std::vector<Token>& toks, const ast::Struct& cls, const ast::Function& m);
// The spellings, by token index, of `m`'s body written for class `cls`: the members of `cls`
// (and of the classes it derives from) as `self.x`, unless a parameter or local of that name
// hides them, and calls of its methods as `self.M(...)` or, for one defined outside the class
// too, `C__M__fxm(self, ...)`.
std::unordered_map<uint32_t, std::string> method_body_spellings(const std::vector<Token>& toks,
                                                                const ClassLinkage& linkage, const ast::Struct& cls,
                                                                const ast::Function& m);
// The dispatchers' definitions of every interface: a switch over the class-instance id.
std::string interface_dispatchers(const std::vector<Token>& toks, const ClassLinkage& linkage);

}  // namespace fx::detail
