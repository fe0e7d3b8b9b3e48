// implements `class_linkage.h`: fx_5_0 interfaces and classes written as HLSL glslang takes.
#include "class_linkage.h"

#include <algorithm>
#include <unordered_set>

#include "effect_unit_builder.h"  // join_tokens

namespace fx::detail {
namespace {

const ast::Struct* named(const std::vector<const ast::Struct*>& list, std::string_view name) {
  for (const ast::Struct* s : list)
    if (s->name == name) return s;
  return nullptr;
}

// `R name(params)` for a method (its return type and parameters as written).
std::string signature(const std::vector<Token>& toks, const ast::Function& m, const std::string& name,
                      const std::string& leading) {
  std::string text(m.return_type.name);
  if (!m.return_type.template_arg.empty()) text.append("<").append(m.return_type.template_arg).append(">");
  text.append(" ").append(name).append("(").append(leading);
  for (const ast::Variable& p : m.params) {
    if (!leading.empty() || &p != &m.params.front()) text += ", ";
    text += join_tokens(toks, p.tokens);
  }
  return text + ")";
}

// The arguments that pass a method's parameters on: `a, b`.
std::string forwarded(const ast::Function& m) {
  std::string text;
  for (const ast::Variable& p : m.params) text += (text.empty() ? "" : ", ") + std::string(p.name);
  return text;
}

// The `]` closing the `[` at `open`, or 0.
size_t closing_square(const std::vector<Token>& toks, size_t open, size_t last) {
  int depth = 0;
  for (size_t i = open; i < last; ++i) {
    if (toks[i].is(TokenKind::l_square)) ++depth;
    if (toks[i].is(TokenKind::r_square) && --depth == 0) return i;
  }
  return 0;
}

// The index of the token spelling a declaration's type name.
std::optional<uint32_t> type_token(const std::vector<Token>& toks, const ast::Variable& v) {
  for (uint32_t i = v.tokens.first; i < v.tokens.last && i < toks.size(); ++i)
    if (toks[i].is_identifier(v.type.name)) return i;
  return std::nullopt;
}

// Whether a call of `name` on a value of type `s` reaches a method.
bool has_method(const ClassLinkage& linkage, const ast::Struct& s, std::string_view name) {
  if (s.kind == ast::StructKind::class_type) {
    const std::vector<const ast::Function*> methods = linkage.methods_of(s);
    return std::any_of(methods.begin(), methods.end(), [&](const ast::Function* m) { return m->name == name; });
  }
  return std::any_of(s.methods.begin(), s.methods.end(), [&](const ast::Function& m) { return m.name == name; });
}

// Whether `a` overrides `b` (or is `b`'s other declaration): the same name and parameter types.
bool same_signature(const ast::Function& a, const ast::Function& b) {
  if (a.name != b.name || a.params.size() != b.params.size()) return false;
  for (size_t i = 0; i < a.params.size(); ++i)
    if (a.params[i].type.name != b.params[i].type.name) return false;
  return true;
}

constexpr int kMaxClassDepth = 16;  // a longer chain of bases is a cycle the checker reports

}  // namespace

const ast::Struct* ClassLinkage::interface_named(std::string_view name) const { return named(interfaces, name); }

const ast::Struct* ClassLinkage::class_named(std::string_view name) const { return named(classes, name); }

std::vector<BindableInstance> ClassLinkage::bindable(const ast::Struct& iface) const {
  return effect ? bindable_instances(*effect, iface.name) : std::vector<BindableInstance>{};
}

std::optional<int> ClassLinkage::instance_id(const ast::Struct& iface, std::string_view instance) const {
  std::vector<BindableInstance> list = bindable(iface);
  for (size_t i = 0; i < list.size(); ++i)
    if (list[i].name == instance) return static_cast<int>(i);
  return std::nullopt;
}

std::vector<const ast::Function*> ClassLinkage::methods_of(const ast::Struct& cls) const {
  std::vector<const ast::Function*> out;
  const ast::Struct* c = &cls;
  for (int depth = 0; c && depth < kMaxClassDepth; ++depth) {
    for (const ast::Function& m : c->methods)
      if (std::none_of(out.begin(), out.end(), [&](const ast::Function* o) { return same_signature(*o, m); }))
        out.push_back(&m);
    const ast::Struct* parent = nullptr;
    for (const ast::Text& base : c->bases)
      if ((parent = class_named(base))) break;
    c = parent;
  }
  return out;
}

std::vector<const ast::Struct*> ClassLinkage::base_classes(const ast::Struct& cls) const {
  std::vector<const ast::Struct*> out;
  const ast::Struct* c = &cls;
  for (int depth = 0; c && depth < kMaxClassDepth; ++depth) {
    const ast::Struct* parent = nullptr;
    for (const ast::Text& base : c->bases)
      if ((parent = class_named(base))) break;
    if (parent) out.insert(out.begin(), parent);
    c = parent;
  }
  return out;
}

ClassLinkage class_linkage(const ast::Effect& effect) {
  ClassLinkage out;
  out.effect = &effect;
  for (const ast::Decl& d : effect.decls)
    if (d.kind == ast::DeclKind::structure && d.structure->kind == ast::StructKind::interface_type)
      out.interfaces.push_back(d.structure);
    else if (d.kind == ast::DeclKind::structure && d.structure->kind == ast::StructKind::class_type)
      out.classes.push_back(d.structure);
  if (out.interfaces.empty()) return out;
  auto add = [&](const ast::Variable& v, bool in_buffer) {
    if (out.interface_named(v.type.name)) out.interface_variables.push_back(&v);
    if (out.class_named(v.type.name)) (in_buffer ? out.buffered_instances : out.instances).push_back(&v);
  };
  for (const ast::Decl& d : effect.decls)
    if (d.kind == ast::DeclKind::variable && d.variable) add(*d.variable, false);
    else if (d.kind == ast::DeclKind::constant_buffer && d.constant_buffer)
      for (const ast::Variable& m : d.constant_buffer->members) add(m, true);
  return out;
}

bool is_interface_parameter(const ClassLinkage& linkage, const ast::Variable& param) {
  return linkage.interface_named(param.type.name) != nullptr;
}

std::string dispatcher_name(std::string_view iface, std::string_view method) {
  return std::string(iface) + "__" + std::string(method) + "__fx";
}

std::unordered_map<uint32_t, std::string> class_linkage_spellings(const std::vector<Token>& toks,
                                                                  const ClassLinkage& linkage,
                                                                  const std::vector<const ast::Function*>& functions) {
  std::unordered_map<uint32_t, std::string> out;
  if (linkage.classes.empty()) return out;
  // The type each name that calls go through has: interface variables, class instances.
  std::unordered_map<std::string_view, const ast::Struct*> globals;
  for (const ast::Variable* v : linkage.interface_variables) {
    globals.emplace(v->name, linkage.interface_named(v->type.name));
    if (std::optional<uint32_t> t = type_token(toks, *v)) out.emplace(*t, "int");
  }
  for (const ast::Variable* v : linkage.buffered_instances) globals.emplace(v->name, linkage.class_named(v->type.name));
  for (const ast::Variable* v : linkage.instances) {
    const ast::Struct* cls = linkage.class_named(v->type.name);
    globals.emplace(v->name, cls);
    // An instance of a class without data holds nothing to upload: left in the global
    // uniform block, an empty struct could make it a block of zero bytes.
    const std::vector<const ast::Struct*> bases = linkage.base_classes(*cls);
    const bool data = !cls->members.empty() ||
                      std::any_of(bases.begin(), bases.end(), [](const ast::Struct* b) { return !b->members.empty(); });
    std::optional<uint32_t> t = data ? std::nullopt : type_token(toks, *v);
    if (t) out.emplace(*t, "static " + std::string(v->type.name));
  }
  for (const ast::Function* f : functions) {
    std::unordered_map<std::string_view, const ast::Struct*> names = globals;
    for (const ast::Variable& p : f->params)
      if (const ast::Struct* iface = linkage.interface_named(p.type.name)) {
        names.insert_or_assign(p.name, iface);
        if (std::optional<uint32_t> t = type_token(toks, p)) out.emplace(*t, "int");
      }
    const size_t last = std::min<size_t>(f->tokens.last, toks.size());
    // Locals and parameters of a class type: a call of a method defined outside the class
    // calls its function (method_function_name) on them, in place (`inout`).
    std::unordered_map<std::string_view, const ast::Struct*> locals;
    for (const ast::Variable& p : f->params)
      if (const ast::Struct* cls = linkage.class_named(p.type.name)) locals.insert_or_assign(p.name, cls);
    for (size_t i = f->tokens.first; i + 1 < last; ++i)
      if (toks[i].is(TokenKind::identifier) && toks[i + 1].is(TokenKind::identifier))
        if (const ast::Struct* cls = linkage.class_named(toks[i].text()))
          locals.insert_or_assign(toks[i + 1].text(), cls);
    for (size_t i = f->tokens.first; i < last; ++i) {
      if (!toks[i].is(TokenKind::identifier) || (i > 0 && toks[i - 1].is(TokenKind::period))) continue;
      if (auto local = locals.find(toks[i].text()); local != locals.end()) {
        if (i + 3 < last && toks[i + 1].is(TokenKind::period) && toks[i + 2].is(TokenKind::identifier) &&
            toks[i + 3].is(TokenKind::l_paren)) {
          const std::vector<const ast::Function*> methods = linkage.methods_of(*local->second);
          const bool outside = std::any_of(methods.begin(), methods.end(), [&](const ast::Function* m) {
            return m->name == toks[i + 2].text() && !m->owner.empty();
          });
          if (outside) {
            out[i] = method_function_name(local->second->name, toks[i + 2].text()) + "(" + std::string(toks[i].text());
            out[i + 1].assign(1, ' ');
            out[i + 2].assign(1, ' ');
            out[i + 3].assign(1, i + 4 < last && toks[i + 4].is(TokenKind::r_paren) ? ' ' : ',');
          }
        }
        continue;
      }
      auto found = names.find(toks[i].text());
      if (found == names.end()) continue;
      size_t dot = i + 1;
      if (dot < last && toks[dot].is(TokenKind::l_square)) dot = closing_square(toks, dot, last) + 1;
      if (dot == 1 || dot + 2 >= last || !toks[dot].is(TokenKind::period) || !toks[dot + 1].is(TokenKind::identifier) ||
          !toks[dot + 2].is(TokenKind::l_paren) || !has_method(linkage, *found->second, toks[dot + 1].text()))
        continue;
      const ast::Struct& type = *found->second;
      // `g[1].M(a)` -> `I__M__fx(g[1], a)`: the callee goes before the name, the rest blank.
      out[i] = dispatcher_name(type.name, toks[dot + 1].text()) + "(" + std::string(toks[i].text());
      const bool no_arguments = dot + 3 < last && toks[dot + 3].is(TokenKind::r_paren);
      out[dot].assign(1, ' ');
      out[dot + 1].assign(1, ' ');
      out[dot + 2].assign(1, no_arguments ? ' ' : ',');
    }
  }
  return out;
}

std::string interface_prototypes(const std::vector<Token>& toks, const ast::Struct& iface) {
  std::string text;
  for (const ast::Function& m : iface.methods)
    text += signature(toks, m, dispatcher_name(iface.name, m.name), "int instance__fx") + ";\n";
  return text;
}

std::string class_method_wrappers(const std::vector<Token>& toks, const ast::Struct& cls,
                                  const std::vector<const ast::Function*>& methods) {
  std::string text;
  for (const ast::Function* m : methods)
    if (!m->owner.empty()) text += method_function_signature(toks, cls, *m) + ";\n";
  for (const ast::Function* m : methods) {
    const std::string call = m->owner.empty() ? "self." + std::string(m->name) + "(" + forwarded(*m) + ");"
                                              : method_function_name(cls.name, m->name) + "(self" +
                                                    (m->params.empty() ? "" : ", ") + forwarded(*m) + ");";
    text += signature(toks, *m, dispatcher_name(cls.name, m->name), std::string(cls.name) + " self") + " { " +
            (m->return_type.name == "void" ? "" : "return ") + call + " }\n";
  }
  return text;
}

std::string method_function_name(std::string_view cls, std::string_view method) {
  return std::string(cls) + "__" + std::string(method) + "__fxm";
}

std::string method_function_signature(const std::vector<Token>& toks, const ast::Struct& cls, const ast::Function& m) {
  return signature(toks, m, method_function_name(cls.name, m.name), "inout " + std::string(cls.name) + " self");
}

std::unordered_map<uint32_t, std::string> method_body_spellings(const std::vector<Token>& toks,
                                                                const ClassLinkage& linkage, const ast::Struct& cls,
                                                                const ast::Function& m) {
  std::unordered_set<std::string_view> members;
  for (const ast::Struct* base : linkage.base_classes(cls))
    for (const ast::Variable& v : base->members) members.insert(v.name);
  for (const ast::Variable& v : cls.members) members.insert(v.name);
  for (const ast::Variable& p : m.params) members.erase(p.name);
  const std::vector<const ast::Function*> methods = linkage.methods_of(cls);
  auto method_named = [&](std::string_view name) -> const ast::Function* {
    for (const ast::Function* f : methods)
      if (f->name == name) return f;
    return nullptr;
  };
  const size_t first = m.body.first, last = std::min<size_t>(m.body.last, toks.size());
  // A local of a member's name (`float3 m_vDir = ...;`) hides the member in the whole body.
  for (size_t i = first + 1; i + 1 < last; ++i)
    if (toks[i].is(TokenKind::identifier) && toks[i - 1].is(TokenKind::identifier) && toks[i - 1].text() != "return" &&
        toks[i - 1].text() != "else" &&
        (toks[i + 1].is(TokenKind::equal) || toks[i + 1].is(TokenKind::semi) || toks[i + 1].is(TokenKind::comma) ||
         toks[i + 1].is(TokenKind::l_square)))
      members.erase(toks[i].text());
  std::unordered_map<uint32_t, std::string> out;
  for (size_t i = first; i < last; ++i) {
    if (!toks[i].is(TokenKind::identifier)) continue;
    if (i > 0 && (toks[i - 1].is(TokenKind::period) || toks[i - 1].is(TokenKind::coloncolon))) continue;
    const std::string_view name = toks[i].text();
    const bool call = i + 1 < last && toks[i + 1].is(TokenKind::l_paren);
    if (const ast::Function* f = call ? method_named(name) : nullptr) {
      if (f->owner.empty()) {
        out.emplace(uint32_t(i), "self." + std::string(name));
      } else {
        out.emplace(uint32_t(i), method_function_name(cls.name, name) + "(self");
        const bool no_arguments = i + 2 < last && toks[i + 2].is(TokenKind::r_paren);
        out.emplace(uint32_t(i + 1), no_arguments ? " " : ",");
      }
    } else if (members.count(name)) {
      out.emplace(uint32_t(i), "self." + std::string(name));
    }
  }
  return out;
}

std::string interface_dispatchers(const std::vector<Token>& toks, const ClassLinkage& linkage) {
  std::string text;
  for (const ast::Struct* iface : linkage.interfaces) {
    const std::vector<BindableInstance> instances = linkage.bindable(*iface);
    for (const ast::Function& m : iface->methods) {
      const bool returns = m.return_type.name != "void";
      text += signature(toks, m, dispatcher_name(iface->name, m.name), "int instance__fx") + " {\n";
      text += "  switch (instance__fx) {\n";
      // An id out of range (an unbound variable) takes the first instance.
      for (size_t k = instances.size(); k-- > 0;) {
        const BindableInstance& instance = instances[k];
        const std::string call = dispatcher_name(instance.cls->name, m.name) + "(" + instance.name +
                                 (m.params.empty() ? "" : ", ") + forwarded(m) + ")";
        text += k == 0 ? "  default: " : "  case " + std::to_string(k) + ": ";
        text += returns ? "return " + call + ";\n" : call + "; return;\n";
      }
      text += "  }\n";
      if (returns && instances.empty()) text += "  return (" + std::string(m.return_type.name) + ")0;\n";
      text += "}\n";
    }
  }
  return text;
}

}  // namespace fx::detail
