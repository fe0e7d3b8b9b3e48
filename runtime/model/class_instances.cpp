// implements `fx/model/class_instances.h`: the class instances an interface variable can be bound to.
#include "fx/model/class_instances.h"

#include <algorithm>

namespace fx {
namespace {

const ast::Struct* find_struct(const ast::Effect& effect, std::string_view name, ast::StructKind kind) {
  for (const ast::Decl& d : effect.decls)
    if (d.kind == ast::DeclKind::structure && d.structure && d.structure->kind == kind && d.structure->name == name)
      return d.structure;
  return nullptr;
}

}  // namespace

const ast::Struct* find_interface(const ast::Effect& effect, std::string_view name) {
  return find_struct(effect, name, ast::StructKind::interface_type);
}

std::vector<BindableInstance> bindable_instances(const ast::Effect& effect, std::string_view iface) {
  std::vector<BindableInstance> out;
  for (const ast::Decl& d : effect.decls) {
    if (d.kind != ast::DeclKind::variable || !d.variable) continue;
    const ast::Variable& v = *d.variable;
    const ast::Struct* cls = find_struct(effect, v.type.name, ast::StructKind::class_type);
    if (!cls || std::find(cls->bases.begin(), cls->bases.end(), iface) == cls->bases.end()) continue;
    if (v.array_dims.empty()) {
      out.push_back({std::string(v.name), cls});
      continue;
    }
    const ast::Expr* dim = v.array_dims.size() == 1 ? v.array_dims[0] : nullptr;
    if (!dim || dim->kind != ast::ExprKind::int_literal) continue;
    for (int64_t i = 0; i < static_cast<int64_t>(dim->number); ++i)
      out.push_back({std::string(v.name) + "[" + std::to_string(i) + "]", cls});
  }
  return out;
}

}  // namespace fx
