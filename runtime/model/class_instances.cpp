// implements `fx/model/class_instances.h`: the class instances an interface variable can be bound to.
#include "fx/model/class_instances.h"

namespace fx {
namespace {

const ast::Struct* find_struct(const ast::Effect& effect, std::string_view name, ast::StructKind kind) {
  for (const ast::Decl& d : effect.decls)
    if (d.kind == ast::DeclKind::structure && d.structure && d.structure->kind == kind && d.structure->name == name)
      return d.structure;
  return nullptr;
}

// Whether `cls` implements `iface`: itself or through the classes it derives from
// (`class Hemi : Ambient`, `class Ambient : ILight`). `depth` stops a cycle.
bool implements(const ast::Effect& effect, const ast::Struct& cls, std::string_view iface, int depth = 0) {
  if (depth > 16) return false;
  for (const ast::Text& base : cls.bases) {
    if (base == iface) return true;
    const ast::Struct* parent = find_struct(effect, base, ast::StructKind::class_type);
    if (parent && implements(effect, *parent, iface, depth + 1)) return true;
  }
  return false;
}

}  // namespace

const ast::Struct* find_interface(const ast::Effect& effect, std::string_view name) {
  return find_struct(effect, name, ast::StructKind::interface_type);
}

std::vector<BindableInstance> bindable_instances(const ast::Effect& effect, std::string_view iface) {
  std::vector<BindableInstance> out;
  // Globals, and the members of constant buffers (the SDK's instances live in a cbuffer).
  std::vector<const ast::Variable*> globals;
  for (const ast::Decl& d : effect.decls)
    if (d.kind == ast::DeclKind::variable && d.variable) globals.push_back(d.variable);
    else if (d.kind == ast::DeclKind::constant_buffer && d.constant_buffer)
      for (const ast::Variable& m : d.constant_buffer->members) globals.push_back(&m);
  for (const ast::Variable* global : globals) {
    const ast::Variable& v = *global;
    const ast::Struct* cls = find_struct(effect, v.type.name, ast::StructKind::class_type);
    if (!cls || !implements(effect, *cls, iface)) continue;
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
