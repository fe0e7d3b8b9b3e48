#include "fx/pass_states.h"

#include "fx/ascii_case.h"

namespace fx {

namespace {

// The states of the stateblock variable `name` declares, or null.
const ast::List<ast::StateAssignment>* stateblock_states(const ast::Effect& effect, std::string_view name) {
  for (const ast::Decl& d : effect.decls) {
    if (d.kind != ast::DeclKind::variable || !d.variable || d.variable->name != name) continue;
    const ast::Variable& v = *d.variable;
    if (!iequals(v.type.name, "stateblock") || !v.initializer || v.initializer->kind != ast::ExprKind::state_block)
      return nullptr;
    return &v.initializer->states;
  }
  return nullptr;
}

}  // namespace

std::vector<const ast::StateAssignment*> applied_pass_states(const ast::Effect& effect, const ast::Pass& pass) {
  std::vector<const ast::StateAssignment*> out;
  for (const ast::StateAssignment& a : pass.states) {
    const ast::Expr* value = a.value;
    const bool names_one =
        value && (value->kind == ast::ExprKind::identifier || value->kind == ast::ExprKind::reference);
    const ast::List<ast::StateAssignment>* block =
        iequals(a.name, "StateBlock") && !a.index && names_one ? stateblock_states(effect, value->text) : nullptr;
    if (!block) {
      out.push_back(&a);
      continue;
    }
    for (const ast::StateAssignment& s : *block) out.push_back(&s);
  }
  return out;
}

}  // namespace fx
