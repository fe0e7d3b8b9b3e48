// The model's global symbols and its queries (fx/semantic_model.h); function bodies are
// resolved by body_resolver.cpp.
#include "fx/semantic_model.h"

#include <algorithm>

#include "body_resolver.h"

namespace fx::semantic {

std::string_view to_string(SymbolKind kind) {
  switch (kind) {
    case SymbolKind::parameter: return "parameter";
    case SymbolKind::cbuffer_member: return "cbuffer member";
    case SymbolKind::constant_buffer: return "cbuffer";
    case SymbolKind::function: return "function";
    case SymbolKind::function_parameter: return "function parameter";
    case SymbolKind::local: return "local variable";
    case SymbolKind::structure: return "struct";
    case SymbolKind::member: return "member";
    case SymbolKind::type_alias: return "typedef";
    case SymbolKind::state_object: return "state object";
    case SymbolKind::glsl_block: return "GLSL block";
  }
  return "symbol";
}

namespace {

Symbol declared(SymbolKind kind, std::string_view name, SourceRange name_range, SourceRange range) {
  Symbol s;
  s.kind = kind;
  s.name = name;
  s.name_range = name_range;
  s.range = range;
  return s;
}

}  // namespace

SemanticModel::SemanticModel(const ast::Effect& effect, const SourceManager& sm) : effect_(effect), sm_(sm) {
  add_globals();
  resolve_bodies();
}

Symbol& SemanticModel::add(Symbol s) { return symbols_.emplace_back(std::move(s)); }

Symbol& SemanticModel::add_global(Symbol s) {
  Symbol& added = add(std::move(s));
  globals_.push_back(&added);
  global_index_.emplace(added.name, &added);
  return added;
}

void SemanticModel::add_variable(SymbolKind kind, const ast::Variable& v, std::string_view container) {
  Symbol s;
  s.kind = kind;
  s.name = v.name;
  s.name_range = v.name_range;
  s.range = v.range;
  s.container = container;
  s.variable = &v;
  if (kind == SymbolKind::member) add(std::move(s));
  else add_global(std::move(s));
}

void SemanticModel::add_struct(const ast::Struct& st) {
  Symbol s;
  s.kind = SymbolKind::structure;
  s.name = st.name;
  s.name_range = st.name_range;
  s.range = st.range;
  s.structure = &st;
  s.type.kind = TypeClass::structure;
  s.type.name = std::string(st.name);
  s.type.structure = &st;
  if (!st.name.empty()) add_global(std::move(s));
  std::vector<const Symbol*>& members = members_[&st];
  for (const ast::Variable& m : st.members) {
    add_variable(SymbolKind::member, m, st.name);
    members.push_back(&symbols_.back());
    if (m.type.definition) add_struct(*m.type.definition);
  }
  for (const ast::Function& f : st.methods) {
    Symbol& fs = add(declared(SymbolKind::function, f.name, f.name_range, f.range));
    fs.container = st.name;
    fs.function = &f;
    function_symbols_.emplace(&f, &fs);
  }
}

void SemanticModel::add_globals() {
  for (const ast::Decl& d : effect_.decls) {
    switch (d.kind) {
      case ast::DeclKind::variable:
        add_variable(SymbolKind::parameter, *d.variable, {});
        if (d.variable->type.definition) add_struct(*d.variable->type.definition);
        break;
      case ast::DeclKind::structure: add_struct(*d.structure); break;
      case ast::DeclKind::type_alias: {
        const ast::Typedef& t = *d.type_alias;
        Symbol& s = add_global(declared(SymbolKind::type_alias, t.name, t.range, t.range));
        s.type_alias = &t;
        break;
      }
      case ast::DeclKind::function: {
        const ast::Function& f = *d.function;
        Symbol s = declared(SymbolKind::function, f.name, f.name_range, f.range);
        s.container = f.owner;
        s.function = &f;
        // `C::M` is a method, no global name; of overloads, the index keeps the first.
        function_symbols_.emplace(&f, f.owner.empty() ? &add_global(std::move(s)) : &add(std::move(s)));
        break;
      }
      case ast::DeclKind::state_object: {
        const ast::StateObject& o = *d.state_object;
        Symbol& s = add_global(declared(SymbolKind::state_object, o.name, o.name_range, o.range));
        s.state_object = &o;
        s.type.kind = TypeClass::object;
        s.type.name = std::string(o.kind);
        s.type.array_rank = static_cast<uint32_t>(o.array_dims.size());
        break;
      }
      case ast::DeclKind::constant_buffer: {
        const ast::ConstantBuffer& c = *d.constant_buffer;
        Symbol& s = add_global(declared(SymbolKind::constant_buffer, c.name, c.name_range, c.range));
        s.constant_buffer = &c;
        for (const ast::Variable& m : c.members) {
          add_variable(SymbolKind::cbuffer_member, m, c.name);
          symbols_.back().constant_buffer = &c;
          if (m.type.definition) add_struct(*m.type.definition);
        }
        break;
      }
      case ast::DeclKind::glsl_block: {
        const ast::GlslBlock& g = *d.glsl_block;
        add_global(declared(SymbolKind::glsl_block, g.name, g.name_range, g.range));
        break;
      }
      default: break;
    }
  }
  // Types need every struct and typedef declared first: a parameter may name a struct the
  // file declares later (fxc refuses it; the model need not).
  for (Symbol& s : symbols_) {
    if (s.variable) s.type = resolve_type(s.variable->type, s.variable->array_dims.size());
    else if (s.function) s.type = resolve_type(s.function->return_type, 0);
  }
}

void SemanticModel::resolve_bodies() {
  std::vector<const ast::Function*> bodies;
  for (const auto& [f, symbol] : function_symbols_)
    if (!f->body.empty()) bodies.push_back(f);
  std::sort(bodies.begin(), bodies.end(),
            [](const ast::Function* a, const ast::Function* b) { return a->body.first < b->body.first; });
  for (const ast::Function* f : bodies) BodyResolver(*this, *f).run();
  std::sort(references_.begin(), references_.end(),
            [](const Reference& a, const Reference& b) { return a.token < b.token; });
}

void SemanticModel::report(DiagnosticSink& sink) const {
  for (const Diagnostic& d : diagnostics_) {
    Diagnostic& out = sink.report(d.severity, d.id, d.range, d.message);
    out.notes = d.notes;
    out.fixits = d.fixits;
  }
}

const Symbol* SemanticModel::global(std::string_view name) const {
  auto it = global_index_.find(name);
  return it == global_index_.end() ? nullptr : it->second;
}

std::span<const Symbol* const> SemanticModel::members(const ast::Struct& s) const {
  auto it = members_.find(&s);
  if (it == members_.end()) return {};
  return it->second;
}

const Symbol* SemanticModel::member(const ast::Struct& s, std::string_view name) const {
  for (const Symbol* m : members(s))
    if (m->name == name) return m;
  return nullptr;
}

const Reference* SemanticModel::reference_at(uint32_t token) const {
  auto it = std::lower_bound(references_.begin(), references_.end(), token,
                             [](const Reference& r, uint32_t t) { return r.token < t; });
  return it != references_.end() && it->token == token ? &*it : nullptr;
}

const Symbol* SemanticModel::function_at(uint32_t token) const {
  for (const auto& [f, symbol] : function_symbols_)
    if (token >= f->body.first && token < f->body.last) return symbol;
  return nullptr;
}

std::vector<const Symbol*> SemanticModel::visible_at(uint32_t token) const {
  std::vector<const Symbol*> out;
  for (auto it = locals_.rbegin(); it != locals_.rend(); ++it)
    if (token >= (*it)->visible.first && token < (*it)->visible.last) out.push_back(*it);
  out.insert(out.end(), globals_.begin(), globals_.end());
  return out;
}

ShaderType SemanticModel::resolve_type_name(std::string_view name) const {
  // Follows typedefs (a bounded number: a cycle of them names no type).
  uint32_t alias_rank = 0;
  for (int depth = 0; depth < 16; ++depth) {
    // `matrix` and `vector` alone are HLSL's float4x4 and float4.
    const std::string_view spelled = name == "matrix" ? "float4x4" : name == "vector" ? "float4" : name;
    if (auto numeric = builtin_numeric_type(spelled)) {
      numeric->array_rank += alias_rank;
      return *numeric;
    }
    if (is_object_type_name(name)) {
      ShaderType t;
      t.kind = TypeClass::object;
      t.name = std::string(name);
      t.array_rank = alias_rank;
      return t;
    }
    const Symbol* s = global(name);
    if (s && s->kind == SymbolKind::structure) {
      ShaderType t = s->type;
      t.array_rank += alias_rank;
      return t;
    }
    if (!s || s->kind != SymbolKind::type_alias) return {};
    const ast::Typedef& t = *s->type_alias;
    alias_rank += static_cast<uint32_t>(t.array_dims.size());
    if (t.type.definition || !t.type.template_arg.empty()) return resolve_type(t.type, alias_rank);
    name = t.type.name;
  }
  return {};
}

ShaderType SemanticModel::resolve_type(const ast::TypeRef& type, size_t array_rank) const {
  ShaderType t;
  if (type.definition) {
    t.kind = TypeClass::structure;
    t.structure = type.definition;
    t.name = type.definition->name.empty() ? std::string("struct") : std::string(type.definition->name);
  } else if (!type.template_arg.empty()) {
    t.kind = is_object_type_name(type.name) ? TypeClass::object : TypeClass::unknown;
    t.name = type.name + "<" + type.template_arg + ">";
  } else {
    t = resolve_type_name(type.name);
    if (!t.known()) t.name = std::string(type.name);
  }
  t.array_rank += static_cast<uint32_t>(array_rank);
  return t;
}

}  // namespace fx::semantic
