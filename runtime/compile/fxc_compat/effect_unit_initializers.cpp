// Global initializers that call a function of the effect, written as fxc runs them. glslang
// evaluates a global's initializer outside every function: one that calls a user function
// makes it report a false "Recursion detected" at link time, or crash in
// spv::Builder::accessChainLoad when that value reaches a second user function (fxkit issue
// #32). fxc runs a static global's initializer at the start of the shader, so the unit
// declares the static without it, and the entry point's body starts with the assignment
// (EffectUnits::code_for). A parameter's (uniform's) initializer is its default value, which
// the effect model owns: the unit leaves it out.
#include <algorithm>

#include "effect_unit_builder.h"

namespace fx {

using namespace detail;

namespace {

constexpr std::string_view kInitialValue = "__fx_init";

bool opens(TokenKind k) { return k == TokenKind::l_paren || k == TokenKind::l_square || k == TokenKind::l_brace; }
bool closes(TokenKind k) { return k == TokenKind::r_paren || k == TokenKind::r_square || k == TokenKind::r_brace; }

}  // namespace

bool EffectUnitBuilder::initializer_calls(ast::TokenSpan span) const {
  int depth = 0;
  bool in_init = false;
  for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) {
    const Token& t = toks_[i];
    if (opens(t.kind)) ++depth;
    if (closes(t.kind)) --depth;
    if (depth == 0 && t.is(TokenKind::equal)) in_init = true;
    if (depth == 0 && (t.is(TokenKind::comma) || t.is(TokenKind::semi))) in_init = false;
    if (!in_init || !t.is(TokenKind::identifier)) continue;
    const std::string_view name = t.text();
    const bool call = i + 1 < span.last && toks_[i + 1].is(TokenKind::l_paren) &&
                      std::any_of(functions_.begin(), functions_.end(),
                                  [&](const ast::Function* f) { return std::string_view(f->name) == name; });
    if (call || lowered_names_.count(std::string(name))) return true;
  }
  return false;
}

void EffectUnitBuilder::find_lowered_globals() {
  for (const ast::Decl& d : effect_.decls) {
    if (d.kind != ast::DeclKind::variable) continue;
    const ast::Variable& v = *d.variable;
    if (!v.initializer || v.tokens.empty() || is_effect_only_type(v.type.name)) continue;
    if (!initializer_calls(v.tokens)) continue;
    if (v.storage & ast::kStatic) {
      lowered_statics_.insert(v.tokens.first);
      lowered_names_.insert(std::string(v.name));
    } else {
      dropped_initializers_.insert(v.tokens.first);
    }
  }
}

std::string EffectUnitBuilder::emit_lowered_static(detail::ShaderTextWriter& w, ast::TokenSpan span) {
  // The declaration without `const` and its initializers. The initialization, one block per
  // declarator with an initializer, in order (a later one may read an earlier one): a local
  // of the same type, then the assignment, `{ float3 K__fx_init = f(a); K = K__fx_init; }`
  // (arrays and structs take their initializer lists as locals).
  struct Declarator {
    uint32_t name = 0, equal = 0, end = 0;  // token indices; equal == 0: no initializer
  };
  std::vector<Declarator> declarators;
  uint32_t type_first = span.first, type_last = span.first;  // [type_first, type_last): the type
  int depth = 0;
  bool in_init = false;
  for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) {
    const Token& t = toks_[i];
    if (closes(t.kind)) --depth;
    const bool top = depth == 0;
    if (opens(t.kind)) ++depth;
    const bool storage = declarators.empty() && t.is(TokenKind::identifier) &&
                         (t.text() == "static" || t.text() == "const" || t.text() == "uniform" ||
                          t.text() == "volatile" || t.text() == "extern");
    if (storage) type_first = i + 1;
    const bool declarator =
        top && !in_init && !storage && t.is(TokenKind::identifier) && i + 1 < span.last &&
        !(i > span.first && toks_[i - 1].is(TokenKind::less)) &&
        (toks_[i + 1].is(TokenKind::equal) || toks_[i + 1].is(TokenKind::l_square) ||
         toks_[i + 1].is(TokenKind::comma) || toks_[i + 1].is(TokenKind::semi) || toks_[i + 1].is(TokenKind::colon));
    if (declarator) {
      if (declarators.empty()) type_last = i;
      declarators.push_back({i, 0, span.last});
    }
    if (top && t.is(TokenKind::equal) && !declarators.empty()) {
      in_init = true;
      declarators.back().equal = i;
    }
    if (top && (t.is(TokenKind::comma) || t.is(TokenKind::semi))) {
      in_init = false;
      if (!declarators.empty() && declarators.back().end == span.last) declarators.back().end = i;
    }
    if (storage && t.text() == "const") continue;  // assigned once, in the prologue
    if (in_init || (top && t.is(TokenKind::equal))) continue;
    put_hlsl(w, i, span.last);
  }
  detail::ShaderTextWriter init(sm_);
  for (const Declarator& d : declarators) {
    if (!d.equal) continue;
    const std::string name(toks_[d.name].text());
    init.line("{");
    for (uint32_t i = type_first; i < type_last; ++i) put_hlsl(init, i, span.last);
    init.token(toks_[d.name], name + std::string(kInitialValue));
    for (uint32_t i = d.name + 1; i < d.end; ++i) put_hlsl(init, i, span.last);
    init.text(";");
    init.line(name + " = " + name + std::string(kInitialValue) + ";");
    init.line("}");
  }
  return std::move(init.out());
}

}  // namespace fx
