// Declarations: storage classes, types, declarators (parameters, state objects), functions,
// structs, typedefs and constant buffers.
#include <utility>

#include "parse_internal.h"

namespace fx::detail {

uint32_t Parser::parse_storage() {
  uint32_t bits = 0, bit = 0;
  // A modifier is always followed by the type name; the look-ahead keeps a type or
  // variable that happens to be called `line` or `sample` from being swallowed.
  while (at(TokenKind::identifier) && peek().is(TokenKind::identifier) && is_storage_keyword(tok().text(), bit)) {
    bits |= bit;
    advance();
  }
  return bits;
}

bool Parser::parse_type(ast::TypeRef& type) {
  if (!at(TokenKind::identifier)) {
    error_here("expected-type", "expected a type, found " + describe(tok()));
    return false;
  }
  uint32_t first = pos_;
  // `struct { float4 color; } g;` at file scope (or in a typedef): an anonymous struct type.
  if (at_ident("struct") && peek().is(TokenKind::l_brace)) return parse_member_struct(type);
  // `struct InnerStruct member;`: the C spelling of a struct type names the same type.
  if (at_ident("struct") && peek().is(TokenKind::identifier)) advance();
  // Compared as the token's string_view, which tests the length first: std::string's
  // compare with a literal calls memcmp for every type name.
  std::string_view word = advance().text();
  if ((word == "unsigned" || word == "signed") && at(TokenKind::identifier)) {
    std::string name(word);
    (name += ' ') += advance().text();
    type.name = keep(name);
  } else {
    type.name = keep(word);
  }
  if (at(TokenKind::less)) {
    std::string args;
    if (!parse_template_args(args)) return false;
    type.template_arg = keep(args);
  }
  type.range = range_from(first);
  return true;
}

bool Parser::parse_template_args(std::string& out) {
  Token open = tok();
  advance();
  size_t open_count = 1;
  for (;;) {
    switch (tok().kind) {
      case TokenKind::greater:
      case TokenKind::greatergreater:
      case TokenKind::greaterequal:
      case TokenKind::greatergreaterequal:
        split_greater();  // `Texture2D<vector<float,4>>`: the `>>` closes two lists
        advance();
        if (--open_count == 0) return true;
        out.push_back('>');
        continue;
      case TokenKind::less:
        if (++open_count > options_.max_nesting) {
          error_here("nesting-too-deep", "template arguments nested too deeply");
          return false;
        }
        break;
      case TokenKind::eof:
      case TokenKind::semi:
      case TokenKind::l_brace:
      case TokenKind::r_brace:
        if (Diagnostic* d = error_here("expected-token",
                                       "expected '>' to close the template argument list, "
                                       "found " +
                                           describe(tok())))
          d->notes.push_back({open.loc, "to match this '<'"});
        return false;
      default: break;
    }
    append_spelling(out, tok());
    advance();
  }
}

bool Parser::parse_array_dims(ast::List<ast::ExprPtr>& dims) {
  while (at(TokenKind::l_square)) {
    advance();
    if (accept(TokenKind::r_square)) {
      dims.push_back(arena_, nullptr);  // `float a[] = {...}`: size from the initializer
      continue;
    }
    ast::ExprPtr size = parse_expression();
    if (failed_) return false;
    dims.push_back(arena_, size);
    if (!expect(TokenKind::r_square, "after array size")) return false;
  }
  return true;
}

bool Parser::parse_semantics(ast::Variable& v) {
  while (accept(TokenKind::colon)) {
    if (!at(TokenKind::identifier)) {
      error_here("expected-semantic", "expected a semantic or register after ':', found " + describe(tok()));
      return false;
    }
    std::string_view word = tok().text();
    if ((word == "register" || word == "packoffset") && peek().is(TokenKind::l_paren)) {
      ast::Text& kept = word == "register" ? v.register_binding : v.packoffset;
      std::string target;
      Token open = advance();
      advance();
      while (!at(TokenKind::r_paren)) {
        if (at_eof() || at(TokenKind::semi) || at(TokenKind::l_brace)) {
          if (Diagnostic* d =
                  error_here("expected-token", "expected ')' after register binding, found " + describe(tok())))
            d->notes.push_back({open.loc, "in this binding"});
          return false;
        }
        append_spelling(target, tok());
        advance();
      }
      advance();
      kept = keep(target);
    } else {
      v.semantic = keep(word);
      advance();
    }
  }
  return true;
}

bool Parser::parse_declarator_head(ast::Variable& v) {
  if (!at(TokenKind::identifier)) {
    error_here("expected-identifier", "expected a name for the declaration, found " + describe(tok()));
    return false;
  }
  if (!check_name(tok(), "a variable")) return false;
  v.name = keep(tok().text());
  v.name_range = tok().range();
  advance();
  if (!parse_array_dims(v.array_dims) || !parse_semantics(v)) return false;
  if (at(TokenKind::less) && !parse_annotations(v.annotations)) return false;
  return true;
}

bool Parser::parse_initializer(ast::Variable& v) {
  if (!accept(TokenKind::equal)) return true;
  v.initializer = parse_assignment();
  return !failed_;
}

void Parser::parse_variable_or_function(std::vector<ast::Decl>& out, uint32_t first,
                                        std::vector<std::string> attributes) {
  uint32_t storage = parse_storage();
  ast::TypeRef type;
  if (!parse_type(type)) return;
  if (attributes.empty() && at(TokenKind::identifier) && peek().is(TokenKind::coloncolon) &&
      peek(2).is(TokenKind::identifier) && peek(3).is(TokenKind::l_paren)) {
    parse_method_definition(out, first, storage, type);
    return;
  }
  if (at(TokenKind::identifier) && peek().is(TokenKind::l_paren)) {
    ast::Function* f = declarations_.make<ast::Function>();
    f->storage = storage;
    f->return_type = type;
    f->attributes.reserve(arena_, attributes.size());
    for (const std::string& a : attributes) f->attributes.push_back(arena_, keep(a));
    if (!check_name(tok(), "a function")) return;
    f->name = keep(tok().text());
    f->name_range = tok().range();
    advance();
    if (!parse_function(*f)) return;
    f->range = range_from(first);
    f->tokens = span_from(first);
    ast::Decl d;
    d.kind = ast::DeclKind::function;
    d.function = f;
    out.push_back(d);
    return;
  }
  if (!attributes.empty()) {
    error("unexpected-attribute", tokens_[first].range(),
          "attributes such as [" + attributes.front() + "] apply only to functions");
    return;
  }
  size_t first_decl = out.size();
  bool state_object_kind = is_state_object_kind(type.name);
  for (;;) {
    uint32_t start = out.size() == first_decl ? first : pos_;
    ast::Variable* v = declarations_.make<ast::Variable>();
    v->storage = storage;
    v->type = type;
    if (!parse_declarator_head(*v)) return;
    if (state_object_kind && at(TokenKind::l_brace) && out.size() == first_decl) {
      finish_state_object(out, *v, first);
      return;
    }
    if (!parse_initializer(*v)) return;
    v->range = range_from(start);
    ast::Decl d;
    d.kind = ast::DeclKind::variable;
    d.variable = v;
    out.push_back(d);
    if (!accept(TokenKind::comma)) break;
  }
  if (!expect_semi("after declaration")) return;
  // Declarators of one declaration share its token span: the shader compiler emits a
  // span once (see docs/effect-format.md).
  for (size_t i = first_decl; i < out.size(); ++i) out[i].variable->tokens = span_from(first);
}

namespace {

bool same_parameter_types(const ast::Function& a, const ast::Function& b) {
  if (a.params.size() != b.params.size()) return false;
  for (size_t i = 0; i < a.params.size(); ++i)
    if (a.params[i].type.name != b.params[i].type.name) return false;
  return true;
}

}  // namespace

void Parser::parse_method_definition(std::vector<ast::Decl>& out, uint32_t first, uint32_t storage,
                                     const ast::TypeRef& return_type) {
  const Token owner = tok();
  advance();  // C
  advance();  // ::
  if (!check_name(tok(), "a function")) return;
  ast::Function f;
  f.storage = storage;
  f.return_type = return_type;
  f.owner = keep(owner.text());
  f.name = keep(tok().text());
  f.name_range = tok().range();
  advance();
  if (!parse_function(f)) return;
  f.range = range_from(first);
  f.tokens = span_from(first);
  std::string qualified(f.owner);
  qualified.append("::").append(f.name);
  if (tokens_[pos_ - 1].is(TokenKind::semi)) {
    // `float3 C::M(float3 n);` repeats the prototype: nothing to attach.
    diags_.error("method-outside-class", f.name_range, "'" + qualified + "' outside its class needs a body");
    return;
  }
  ast::Struct* cls = nullptr;
  for (auto d = out.rbegin(); d != out.rend() && !cls; ++d)
    if (d->kind == ast::DeclKind::structure && d->structure->name == f.owner) cls = d->structure;
  if (!cls || cls->kind != ast::StructKind::class_type) {
    std::string message = "'";
    message.append(f.owner).append("' is not a class declared before the definition of '").append(qualified) += '\'';
    diags_.error("method-outside-class", owner.range(), std::move(message));
    return;
  }
  // The prototype it completes: same name and parameter types, else the only one of that
  // name and arity (the types may be spelled through a typedef).
  ast::Function* proto = nullptr;
  for (int exact = 1; exact >= 0 && !proto; --exact)
    for (ast::Function& m : cls->methods)
      if (m.name == f.name && m.body.empty() && m.params.size() == f.params.size() &&
          (!exact || same_parameter_types(m, f))) {
        proto = &m;
        break;
      }
  if (!proto) {
    Diagnostic& d = diags_.error("method-outside-class", f.name_range,
                                 "class '" + std::string(f.owner) + "' declares no method '" + std::string(f.name) +
                                     "' with " + std::to_string(f.params.size()) + " parameters left to define");
    d.notes.push_back({cls->name_range.begin, "class '" + std::string(f.owner) + "' declared here"});
    return;
  }
  f.prototype = proto->tokens;
  *proto = f;
}

void Parser::finish_state_object(std::vector<ast::Decl>& out, ast::Variable& head, uint32_t first) {
  ast::StateObject* so = declarations_.make<ast::StateObject>();
  so->kind = head.type.name;
  so->name = head.name;
  so->name_range = head.name_range;
  so->array_dims = head.array_dims;
  so->annotations = head.annotations;
  so->register_binding = head.register_binding;
  if (peek().is(TokenKind::l_brace) ? !parse_element_states(so->element_states)
                                    : !parse_state_list(so->states, "state object"))
    return;
  accept(TokenKind::semi);
  so->range = range_from(first);
  ast::Decl d;
  d.kind = ast::DeclKind::state_object;
  d.state_object = so;
  out.push_back(d);
}

bool Parser::parse_element_states(ast::List<ast::List<ast::StateAssignment>>& out) {
  return parse_braced_list("after a state object element",
                           [&] { return parse_state_list(out.emplace_back(arena_), "state object element"); });
}

bool Parser::parse_function(ast::Function& f) {
  Token open = tok();
  advance();  // (
  if (at_ident("void") && peek().is(TokenKind::r_paren)) advance();
  if (!accept(TokenKind::r_paren)) {
    f.params.reserve(arena_, 4);
    for (;;) {
      ast::Variable& p = f.params.emplace_back(arena_);  // in place, see parse_annotations
      if (!parse_parameter(p)) {
        f.params.pop_back();
        return false;
      }
      if (accept(TokenKind::comma)) continue;
      if (!at(TokenKind::r_paren)) {
        if (Diagnostic* d =
                error_here("expected-token", "expected ')' or ',' in parameter list, found " + describe(tok())))
          d->notes.push_back({open.loc, "to match this '('"});
        return false;
      }
      advance();
      break;
    }
  }
  if (accept(TokenKind::colon)) {
    if (!at(TokenKind::identifier)) {
      error_here("expected-semantic", "expected a semantic after ':', found " + describe(tok()));
      return false;
    }
    f.semantic = keep(advance().text());
  }
  if (at(TokenKind::l_brace)) return skip_braced(f.body, "function body");
  return expect_semi("after function declaration");
}

bool Parser::parse_parameter(ast::Variable& p) {
  uint32_t first = pos_;
  p.storage = parse_storage();
  if (!parse_type(p.type)) return false;
  if (!at(TokenKind::identifier)) {
    error_here("expected-identifier", "expected a parameter name, found " + describe(tok()));
    return false;
  }
  if (!check_name(tok(), "a parameter")) return false;
  p.name = keep(tok().text());
  p.name_range = tok().range();
  advance();
  if (!parse_array_dims(p.array_dims) || !parse_semantics(p)) return false;
  if (accept(TokenKind::equal)) {
    p.initializer = parse_assignment();
    if (failed_) return false;
  }
  p.range = range_from(first);
  p.tokens = span_from(first);
  return true;
}

bool Parser::parse_member_list(ast::List<ast::Variable>& members, std::string_view what,
                               ast::List<ast::Function>* methods) {
  if (!at(TokenKind::l_brace)) {
    std::string context = "to begin ";
    context.append(what);
    return expect(TokenKind::l_brace, context);
  }
  Token open = tok();
  advance();
  members.reserve(arena_, 4);
  while (!at(TokenKind::r_brace)) {
    if (at_eof()) {
      unterminated(open, what);
      return false;
    }
    if (accept(TokenKind::semi)) continue;
    if (at(TokenKind::directive)) {
      advance();
      continue;
    }
    uint32_t depth = depth_, first = pos_;
    size_t first_member = members.size();
    uint32_t storage = parse_storage();
    ast::TypeRef type;
    const bool defines_struct =
        at_ident("struct") &&
        (peek().is(TokenKind::l_brace) || (peek().is(TokenKind::identifier) && peek(2).is(TokenKind::l_brace)));
    if (defines_struct ? parse_member_struct(type) : parse_type(type)) {
      if (methods && at(TokenKind::identifier) && peek().is(TokenKind::l_paren)) {
        parse_method(*methods, storage, type, first);
        if (failed_) recover(depth);
        continue;
      }
      for (;;) {
        ast::Variable& v = members.emplace_back(arena_);  // in place, see parse_annotations
        v.storage = storage;
        v.type = type;
        if (!parse_declarator_head(v) || !parse_initializer(v)) {
          members.pop_back();
          break;
        }
        v.range = range_from(first);
        if (!accept(TokenKind::comma)) {
          if (expect_semi("after member declaration"))
            for (size_t i = first_member; i < members.size(); ++i) members[i].tokens = span_from(first);
          break;
        }
      }
    }
    if (failed_) recover(depth);
  }
  advance();
  return true;
}

void Parser::parse_method(ast::List<ast::Function>& methods, uint32_t storage, const ast::TypeRef& return_type,
                          uint32_t first) {
  if (!check_name(tok(), "a function")) return;
  ast::Function& f = methods.emplace_back(arena_);  // in place, see parse_annotations
  f.storage = storage;
  f.return_type = return_type;
  f.name = keep(tok().text());
  f.name_range = tok().range();
  advance();
  if (!parse_function(f)) {
    methods.pop_back();
    return;
  }
  f.range = range_from(first);
  f.tokens = span_from(first);
}

bool Parser::parse_member_struct(ast::TypeRef& type) {
  uint32_t first = pos_;
  advance();  // struct
  ast::Struct* s = declarations_.make<ast::Struct>();
  if (at(TokenKind::identifier)) {
    if (!check_name(tok(), "a struct")) return false;
    s->name = keep(tok().text());
    s->name_range = tok().range();
    advance();
  }
  if (!enter_nesting()) return false;  // structs in structs recurse
  bool ok = parse_member_list(s->members, "struct");
  leave_nesting();
  if (!ok) return false;
  s->range = range_from(first);
  s->tokens = span_from(first);
  type.name = s->name;
  type.range = s->range;
  type.definition = s;
  return true;
}

void Parser::parse_struct(std::vector<ast::Decl>& out) {
  uint32_t first = pos_;
  const std::string_view keyword = advance().text();  // struct, interface or class
  ast::Struct* s = declarations_.make<ast::Struct>();
  s->kind = keyword == "class"       ? ast::StructKind::class_type
            : keyword == "interface" ? ast::StructKind::interface_type
                                     : ast::StructKind::structure;
  if (!at(TokenKind::identifier)) {
    error_here("expected-identifier", "expected a " + std::string(keyword) + " name, found " + describe(tok()));
    return;
  }
  if (!check_name(tok(), "a type")) return;
  s->name = keep(tok().text());
  s->name_range = tok().range();
  advance();
  if (s->kind == ast::StructKind::class_type && accept(TokenKind::colon)) {
    do {
      if (!at(TokenKind::identifier)) {
        error_here("expected-identifier", "expected an interface name, found " + describe(tok()));
        return;
      }
      s->bases.push_back(arena_, keep(advance().text()));
    } while (accept(TokenKind::comma));
  }
  const bool has_methods = s->kind != ast::StructKind::structure;
  if (!parse_member_list(s->members, keyword, has_methods ? &s->methods : nullptr)) return;
  if (!expect_semi("after " + std::string(keyword))) return;
  s->range = range_from(first);
  s->tokens = span_from(first);
  ast::Decl d;
  d.kind = ast::DeclKind::structure;
  d.structure = s;
  out.push_back(d);
}

void Parser::parse_typedef(std::vector<ast::Decl>& out) {
  uint32_t first = pos_;
  advance();        // typedef
  parse_storage();  // `typedef const float4 c4;`: the qualifier is not kept on aliases
  ast::TypeRef type;
  if (!parse_type(type)) return;
  size_t first_decl = out.size();
  for (;;) {
    ast::Typedef* t = declarations_.make<ast::Typedef>();
    t->type = type;
    if (!at(TokenKind::identifier)) {
      error_here("expected-identifier", "expected a typedef name, found " + describe(tok()));
      return;
    }
    if (!check_name(tok(), "a type")) return;
    t->name = keep(advance().text());
    if (!parse_array_dims(t->array_dims)) return;
    ast::Decl d;
    d.kind = ast::DeclKind::type_alias;
    d.type_alias = t;
    out.push_back(d);
    if (!accept(TokenKind::comma)) break;
  }
  if (!expect_semi("after typedef")) return;
  for (size_t i = first_decl; i < out.size(); ++i) {
    out[i].type_alias->range = range_from(first);
    out[i].type_alias->tokens = span_from(first);
  }
}

void Parser::parse_constant_buffer(std::vector<ast::Decl>& out, uint32_t first) {
  uint32_t keyword = pos_;
  ast::ConstantBuffer* cb = declarations_.make<ast::ConstantBuffer>();
  cb->shared = keyword != first;
  cb->texture_buffer = advance().text() == "tbuffer";
  cb->name = keep(tok().text());
  cb->name_range = tok().range();
  advance();
  ast::Variable binding;
  if (!parse_semantics(binding)) return;
  cb->register_binding = binding.register_binding;
  if (!parse_member_list(cb->members, "constant buffer")) return;
  accept(TokenKind::semi);
  cb->range = range_from(first);
  cb->tokens = span_from(keyword);
  ast::Decl d;
  d.kind = ast::DeclKind::constant_buffer;
  d.constant_buffer = cb;
  out.push_back(d);
}

}  // namespace fx::detail
