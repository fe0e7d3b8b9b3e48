// The HLSL text and GLSL blocks of an effect's units: declarations re-spelled from the
// preprocessed tokens without effect-only syntax, each declaration a range a unit can leave out.
#include <algorithm>
#include <cctype>
#include <unordered_set>

#include "array_cast.h"
#include "double_bits.h"
#include "effect_unit_builder.h"
#include "flat_initializer.h"
#include "fx/ascii_case.h"
#include "fx/compile/hlsl_compat.h"
#include "lvalue_constructor.h"

namespace fx {

using namespace detail;

namespace {
// The declaration that defines every interface's dispatchers (class_linkage.h).
constexpr const char* kDispatchers = "interface_dispatchers__fx";
}  // namespace

void EffectUnitBuilder::emit_hlsl() {
  detail::ShaderTextWriter w(sm_);
  if (!effect_.profile_header.empty()) w.out() += pre_release_hlsl_prelude();
  uint32_t last_span = UINT32_MAX;
  // Each declaration is a range of the text that a unit can leave out: it starts with its
  // own #line, and what follows it starts with one too.
  auto begin = [&] {
    w.end_line();
    w.desync();
    return w.out().size();
  };
  auto end = [&](size_t from, std::vector<std::string> names, ast::TokenSpan span) {
    w.end_line();
    w.desync();
    if (w.out().size() == from) return;
    EffectUnits::DeclText text;
    text.names = std::move(names);
    text.begin = from;
    text.end = w.out().size();
    text.refs = identifiers_in(span);
    u_.decls_.push_back(std::move(text));
  };
  // Declarators sharing one declaration (`float a, b;`) are one range that declares each.
  auto shares_last = [&](uint32_t first, const std::string& name) {
    if (first != last_span) return false;
    if (!u_.decls_.empty()) u_.decls_.back().names.push_back(name);
    return true;
  };
  // Methods defined outside their classes go where they are defined: before the first
  // function that follows them.
  const std::vector<MethodFunction> methods = method_functions();
  size_t next_method = 0;
  auto methods_before = [&](uint32_t token) {
    for (; next_method < methods.size() && methods[next_method].method->tokens.first < token; ++next_method)
      emit_method_function(w, methods[next_method]);
  };
  if (detail::calls_asuint_of_a_double(toks_)) {
    const size_t from = begin();
    w.out() += detail::asuint_of_a_double();
    end(from, {"asuint"}, {});
  }
  for (const ast::Decl& d : effect_.decls) {
    switch (d.kind) {
      case ast::DeclKind::variable: {
        const ast::Variable& v = *d.variable;
        if (v.tokens.empty() || is_effect_only_type(v.type.name)) break;
        if (shares_last(v.tokens.first, v.name)) break;
        last_span = v.tokens.first;
        const size_t from = begin();
        const bool lowered = lowered_statics_.count(v.tokens.first) > 0;
        const bool dropped = dropped_initializers_.count(v.tokens.first) > 0;
        std::string initialization;
        if (lowered) initialization = emit_lowered_static(w, v.tokens);
        else emit_filtered(w, v.tokens, !is_shader_object_type(v.type.name), dropped);
        end(from, {v.name}, v.tokens);
        if (!initialization.empty() && !u_.decls_.empty() && u_.decls_.back().begin == from)
          u_.decls_.back().initialization = std::move(initialization);
        break;
      }
      case ast::DeclKind::type_alias: {
        if (shares_last(d.type_alias->tokens.first, d.type_alias->name)) break;
        last_span = d.type_alias->tokens.first;
        const size_t from = begin();
        emit_tokens(w, d.type_alias->tokens);
        end(from, {d.type_alias->name}, d.type_alias->tokens);
        break;
      }
      case ast::DeclKind::structure: {
        const size_t from = begin(), count = u_.decls_.size();
        emit_structure(w, *d.structure);
        end(from, {d.structure->name}, d.structure->tokens);
        if (u_.decls_.size() == count) break;
        // An interface's dispatchers are defined after every class instance (see below).
        if (d.structure->kind == ast::StructKind::interface_type) u_.decls_.back().refs.push_back(kDispatchers);
        // Methods defined outside the class are functions of their own (emit_method_function):
        // what they use comes along with them.
        if (d.structure->kind == ast::StructKind::class_type)
          for (const ast::Function* m : linkage_.methods_of(*d.structure))
            if (!m->owner.empty())
              u_.decls_.back().refs.push_back(detail::method_function_name(d.structure->name, m->name));
        break;
      }
      case ast::DeclKind::function:
        methods_before(d.function->tokens.first);
        emit_function(w, *d.function);
        break;
      case ast::DeclKind::constant_buffer: {
        const ast::ConstantBuffer& cb = *d.constant_buffer;
        std::vector<std::string> names{cb.name};
        for (const ast::Variable& m : cb.members) names.emplace_back(m.name);
        const size_t from = begin();
        // A static member is a constant of the shader, not of the buffer: fxc lets it size a
        // member array (`static const int N = 4; float4 a[N];`). glslang drops a member's
        // initializer, so it is written before the buffer, whole.
        std::vector<ast::TokenSpan> statics;
        for (const ast::Variable& m : cb.members)
          if ((m.storage & ast::kStatic) && (statics.empty() || statics.back().first != m.tokens.first)) {
            emit_filtered(w, m.tokens);
            statics.push_back(m.tokens);
          }
        emit_filtered(w, cb.tokens, false, false, statics);
        end(from, std::move(names), cb.tokens);
        break;
      }
      case ast::DeclKind::state_object: {
        const size_t from = begin();
        emit_sampler_object(w, *d.state_object);
        end(from, {d.state_object->name}, {});
        break;
      }
      case ast::DeclKind::directive:
        // #version/#extension belong to GLSL; HLSL gets the #pragma lines (pack_matrix, ...).
        if (d.directive->text.rfind("#pragma", 0) == 0) {
          const size_t from = begin();
          emit_tokens(w, d.directive->tokens);
          end(from, {}, {});
          if (!u_.decls_.empty() && u_.decls_.back().begin == from) u_.decls_.back().always = true;
        }
        break;
      case ast::DeclKind::technique:
      case ast::DeclKind::group:
      case ast::DeclKind::glsl_block: break;
    }
  }
  methods_before(UINT32_MAX);
  if (!linkage_.empty()) {
    const size_t from = begin();
    w.out() += detail::interface_dispatchers(toks_, linkage_);
    end(from, {kDispatchers}, {});
    if (!u_.decls_.empty() && u_.decls_.back().begin == from)
      for (const auto* list : {&linkage_.instances, &linkage_.buffered_instances})
        for (const ast::Variable* v : *list) u_.decls_.back().refs.emplace_back(v->name);
  }
  w.end_line();
  u_.hlsl_ = std::move(w.out());
}

void EffectUnitBuilder::emit_structure(detail::ShaderTextWriter& w, const ast::Struct& s) {
  if (s.kind == ast::StructKind::interface_type) return w.line(detail::interface_prototypes(toks_, s));
  if (s.kind == ast::StructKind::structure) return emit_tokens(w, s.tokens);
  const std::vector<const ast::Function*> methods = linkage_.methods_of(s);
  bool in_bases = false, body = false;
  for (uint32_t i = s.tokens.first; i < s.tokens.last && i < toks_.size(); ++i) {
    const Token& t = toks_[i];
    if (i == s.tokens.first && t.is(TokenKind::identifier)) {
      w.token(t, "struct");
      continue;
    }
    if (std::optional<uint32_t> last = emit_method_at(w, s, i, methods)) {
      i = *last;
      continue;
    }
    if (!body && t.is(TokenKind::colon)) in_bases = true;
    if (t.is(TokenKind::l_brace) && !body) {
      body = true, in_bases = false;
      put_hlsl(w, i, s.tokens.last);
      // glslang has no inheritance: the members of the classes it derives from come first,
      // and the methods it inherits without overriding them.
      for (const ast::Struct* base : linkage_.base_classes(s)) emit_inherited(w, *base, methods);
      continue;
    }
    if (!in_bases) put_hlsl(w, i, s.tokens.last);
  }
  w.end_line();
  w.line(detail::class_method_wrappers(toks_, s, methods));
}

std::optional<uint32_t> EffectUnitBuilder::emit_method_at(detail::ShaderTextWriter& w, const ast::Struct& cls,
                                                          uint32_t i,
                                                          const std::vector<const ast::Function*>& methods) {
  for (const ast::Function& m : cls.methods) {
    // glslang takes member functions only with their bodies: a prototype whose definition
    // follows the class (`float3 C::M(...) { }`) becomes that definition, without `C::`.
    const bool outside = !m.owner.empty();
    const ast::TokenSpan span = outside ? m.prototype : m.tokens;
    if (span.first != i || span.last <= i) continue;
    // One defined outside the class is written where it is defined (emit_method_function).
    const bool reached = std::find(methods.begin(), methods.end(), &m) != methods.end();
    if (reached && !outside)
      for (uint32_t k = span.first; k < span.last && k < toks_.size(); ++k) put_hlsl(w, k, span.last);
    return span.last - 1;
  }
  return std::nullopt;
}

void EffectUnitBuilder::emit_inherited(detail::ShaderTextWriter& w, const ast::Struct& base,
                                       const std::vector<const ast::Function*>& methods) {
  uint32_t open = base.tokens.first, close = base.tokens.last;
  while (open < close && !toks_[open].is(TokenKind::l_brace)) ++open;
  while (close > open && !toks_[close - 1].is(TokenKind::r_brace)) --close;
  for (uint32_t i = open + 1; i + 1 < close && i < toks_.size(); ++i) {
    if (std::optional<uint32_t> last = emit_method_at(w, base, i, methods)) i = *last;
    else put_hlsl(w, i, close - 1);
  }
  w.end_line();
}

std::vector<EffectUnitBuilder::MethodFunction> EffectUnitBuilder::method_functions() const {
  std::vector<MethodFunction> out;
  for (const ast::Struct* cls : linkage_.classes)
    for (const ast::Function* m : linkage_.methods_of(*cls))
      if (!m->owner.empty()) out.push_back({cls, m});
  std::stable_sort(out.begin(), out.end(), [](const MethodFunction& a, const MethodFunction& b) {
    return a.method->tokens.first < b.method->tokens.first;
  });
  return out;
}

void EffectUnitBuilder::emit_method_function(detail::ShaderTextWriter& w, const MethodFunction& f) {
  w.end_line();
  w.desync();
  EffectUnits::DeclText text;
  text.names = {detail::method_function_name(f.cls->name, f.method->name)};
  text.function = true;
  text.begin = w.out().size();
  w.line(detail::method_function_signature(toks_, *f.cls, *f.method));
  // The body's spellings for this class, beside the effect's (which win where both spell a token).
  std::vector<uint32_t> added;
  for (auto& [i, spelling] : detail::method_body_spellings(toks_, linkage_, *f.cls, *f.method))
    if (respelled_.emplace(i, std::move(spelling)).second) added.push_back(i);
  emit_function_tokens(w, {f.method->body.first - 1, f.method->tokens.last});
  for (uint32_t i : added) respelled_.erase(i);
  w.end_line();
  w.desync();
  text.end = w.out().size();
  text.refs = identifiers_in(f.method->tokens);
  text.refs.push_back(f.cls->name);  // `self`'s type: an inherited method names its base class only
  for (const ast::Function* m : linkage_.methods_of(*f.cls))
    if (!m->owner.empty()) text.refs.push_back(detail::method_function_name(f.cls->name, m->name));
  u_.decls_.push_back(std::move(text));
}

std::string EffectUnitBuilder::dynamic_linkage_in(ast::TokenSpan span) const {
  for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) {
    if (!toks_[i].is(TokenKind::identifier)) continue;
    const std::string_view word = toks_[i].text();
    for (const ast::Struct* iface : linkage_.interfaces)
      if (word == iface->name && linkage_.bindable(*iface).empty()) return "interface '" + iface->name + "'";
    for (const ast::Variable* v : linkage_.interface_variables)
      if (word == v->name && linkage_.bindable(*linkage_.interface_named(v->type.name)).empty())
        return "interface variable '" + v->name + "' of interface '" + v->type.name + "'";
  }
  return {};
}

void EffectUnitBuilder::emit_function(detail::ShaderTextWriter& w, const ast::Function& f) {
  w.end_line();
  w.desync();
  EffectUnits::DeclText text;
  text.names = {std::string(f.name)};
  text.function = true;
  text.begin = w.out().size();
  if (!lowered_statics_.empty() && !f.body.empty() && f.body.first > f.tokens.first) {
    // The body's first token starts a line of its own, so initializations can go before it.
    emit_function_tokens(w, {f.tokens.first, f.body.first});
    w.end_line();
    w.desync();
    text.prologue = w.out().size();
    emit_function_tokens(w, {f.body.first, f.tokens.last});
  } else {
    emit_function_tokens(w, f.tokens);
  }
  w.end_line();
  w.desync();
  text.end = w.out().size();
  text.refs = identifiers_in(f.tokens);
  // A hull shader names its patch-constant function in an attribute, not a call.
  constexpr std::string_view kPatchConstant = "patchconstantfunc";
  for (const ast::Text& attribute : f.attributes) {
    const std::string_view a = attribute;
    const size_t open = a.find('"'), close = a.rfind('"');
    if (iequals(a.substr(0, kPatchConstant.size()), kPatchConstant) && open != std::string_view::npos && close > open)
      text.refs.emplace_back(a.substr(open + 1, close - open - 1));
  }
  text.dynamic_linkage = dynamic_linkage_in(f.tokens);
  for (const ast::Variable& param : f.params)
    for (std::string_view t : {"PointStream", "LineStream", "TriangleStream", "InputPatch", "OutputPatch"})
      text.stage_only = text.stage_only || param.type.name == t;
  u_.decls_.push_back(std::move(text));
}

void EffectUnitBuilder::emit_function_tokens(detail::ShaderTextWriter& w, ast::TokenSpan span) {
  std::vector<detail::LvalueConstructor> rewrites = detail::find_lvalue_constructors(toks_, span);
  std::vector<detail::ArrayCast> casts = detail::find_array_casts(toks_, span);
  auto next = rewrites.begin();
  auto cast = casts.begin();
  for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) {
    if (cast != casts.end() && i >= cast->open) {  // the initializer list, then the cast's tokens blank
      w.token(toks_[i], i == cast->open
                            ? detail::array_cast_initializer(*cast, join_tokens(toks_, {cast->operand, cast->end}))
                            : " ");
      if (i + 1 == cast->end) ++cast;
      continue;
    }
    if (next == rewrites.end() || i < next->type) {
      put_hlsl(w, i, span.last);
    } else if (i == next->type) {
      w.token(toks_[i], "{ " + std::string(toks_[i].text()) + " " + next->temporary);
    } else if (i < next->equal) {
      w.token(toks_[i], " ");  // the constructor's parts, assigned after the value
    } else if (i < next->semi) {
      put_hlsl(w, i, span.last);
    } else {
      w.token(toks_[i], ";" + next->assignments + " }");
      ++next;
    }
  }
}

std::vector<std::string> EffectUnitBuilder::identifiers_in(ast::TokenSpan span) const {
  std::vector<std::string> out;
  std::unordered_set<std::string_view> seen;
  for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i)
    if (toks_[i].is(TokenKind::identifier) && seen.insert(toks_[i].text()).second) out.emplace_back(toks_[i].text());
  return out;
}

void EffectUnitBuilder::put_hlsl(detail::ShaderTextWriter& w, uint32_t i, uint32_t last) {
  if (auto grouped = respelled_.find(i); grouped != respelled_.end()) return w.token(toks_[i], grouped->second);
  w.token(toks_[i], detail::glslang_spelling(toks_, i, last));
}

void EffectUnitBuilder::emit_tokens(detail::ShaderTextWriter& w, ast::TokenSpan span) {
  for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) put_hlsl(w, i, span.last);
}

uint32_t EffectUnitBuilder::annotation_end(uint32_t open, uint32_t last) const {
  bool semi = false;
  int depth = 0;
  for (uint32_t i = open + 1; i < last; ++i) {
    const Token& t = toks_[i];
    if (t.is(TokenKind::l_brace) || t.is(TokenKind::l_paren)) ++depth;
    if (t.is(TokenKind::r_brace) || t.is(TokenKind::r_paren)) --depth;
    if (t.is(TokenKind::semi)) semi = true;
    if (t.is(TokenKind::greater) && depth == 0) return semi || i == open + 1 ? i : 0;
  }
  return 0;
}

uint32_t EffectUnitBuilder::matching_close(uint32_t open, uint32_t last) const {
  int depth = 0;
  for (uint32_t i = open; i < last; ++i) {
    TokenKind k = toks_[i].kind;
    if (k == TokenKind::l_brace || k == TokenKind::l_paren || k == TokenKind::l_square) ++depth;
    if (k == TokenKind::r_brace || k == TokenKind::r_paren || k == TokenKind::r_square) --depth;
    if (depth == 0) return i;
  }
  return last;
}

uint32_t EffectUnitBuilder::register_end(uint32_t colon, uint32_t last) const {
  if (colon + 2 >= last || !toks_[colon + 1].is_identifier("register") || !toks_[colon + 2].is(TokenKind::l_paren))
    return 0;
  uint32_t close = matching_close(colon + 2, last);
  return close < last ? close : 0;
}

void EffectUnitBuilder::emit_filtered(detail::ShaderTextWriter& w, ast::TokenSpan span, bool drop_constant_registers,
                                      bool drop_initializers, const std::vector<ast::TokenSpan>& leave_out) {
  int depth = 0, init_depth = -1;
  auto left_out = leave_out.begin();
  for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) {
    while (left_out != leave_out.end() && left_out->last <= i) ++left_out;
    if (left_out != leave_out.end() && left_out->first <= i) {
      i = left_out->last - 1;
      continue;
    }
    const Token& t = toks_[i];
    bool in_init = init_depth >= 0;
    if (drop_constant_registers && !in_init && depth == 0 && t.is(TokenKind::colon)) {
      if (uint32_t end = register_end(i, span.last)) {
        i = end;
        continue;
      }
    }
    if (!in_init && t.is(TokenKind::less)) {
      if (uint32_t end = annotation_end(i, span.last)) {
        i = end;
        continue;
      }
    }
    if (!in_init && t.is(TokenKind::equal)) {
      const Token* next = i + 1 < span.last ? &toks_[i + 1] : nullptr;
      if (next && next->is(TokenKind::identifier) &&
          (iequals(next->text(), "sampler_state") || iequals(next->text(), "stateblock_state"))) {
        uint32_t open = i + 2;
        i = open < span.last && toks_[open].is(TokenKind::l_brace) ? matching_close(open, span.last) : i + 1;
        continue;
      }
      // `sampler s[2] = { sampler_state {...}, sampler_state {...} };`: an array of them.
      if (next && next->is(TokenKind::l_brace) && i + 2 < span.last && toks_[i + 2].is(TokenKind::identifier) &&
          iequals(toks_[i + 2].text(), "sampler_state")) {
        i = matching_close(i + 1, span.last);
        continue;
      }
      if (depth > 0 || drop_initializers) {  // cbuffer member or dropped initializer: skip to its ';'
        int d = 0;
        uint32_t j = i + 1;
        for (; j < span.last; ++j) {
          TokenKind k = toks_[j].kind;
          if (k == TokenKind::l_brace || k == TokenKind::l_paren || k == TokenKind::l_square) ++d;
          if (k == TokenKind::r_brace || k == TokenKind::r_paren || k == TokenKind::r_square) --d;
          if (d == 0 && (k == TokenKind::semi || (depth == 0 && k == TokenKind::comma))) break;
        }
        i = j - 1;
        continue;
      }
      init_depth = depth;
    }
    if (t.is(TokenKind::l_brace) || t.is(TokenKind::l_paren) || t.is(TokenKind::l_square)) ++depth;
    if (t.is(TokenKind::r_brace) || t.is(TokenKind::r_paren) || t.is(TokenKind::r_square)) --depth;
    if ((t.is(TokenKind::semi) || t.is(TokenKind::comma)) && depth == init_depth) init_depth = -1;
    if (t.is(TokenKind::l_brace) && !in_init) init_depth = -1;
    put_hlsl(w, i, span.last);
  }
}

void EffectUnitBuilder::emit_sampler_object(detail::ShaderTextWriter& w, const ast::StateObject& so) {
  if (!iequals(so.kind, "SamplerState") && !iequals(so.kind, "SamplerComparisonState")) return;
  std::string text = so.kind + " " + so.name;
  for (const ast::ExprPtr& dim : so.array_dims) {
    text += "[";
    if (dim) spell(dim, text);
    text += "]";
  }
  if (!so.register_binding.empty()) text += " : register(" + so.register_binding + ")";
  PresumedLocation p = sm_.presumed(so.name_range.begin);
  if (p.valid()) w.line(detail::line_directive(p.line, p.file));
  w.line(text + ";");
}

void EffectUnitBuilder::collect_glsl() {
  for (const ast::Decl& d : effect_.decls) {
    if (d.kind != ast::DeclKind::glsl_block) continue;
    const ast::GlslBlock& b = *d.glsl_block;
    EffectUnits::GlslBlockText text;
    text.name = b.name;
    ast::TokenSpan code = b.code;
    if (!code.empty() && toks_[code.first].is(TokenKind::directive) &&
        toks_[code.first].text().rfind("#version", 0) == 0) {
      text.version = std::string(toks_[code.first].text());
      ++code.first;
    } else if (code.last - code.first >= 3 && toks_[code.first].is(TokenKind::hash) &&
               toks_[code.first + 1].is_identifier("version") && toks_[code.first + 2].is(TokenKind::integer)) {
      // `GLSLShader X { #version 450` : not at a line start, so the preprocessor left it as
      // tokens; a profile word (`core`, `es`) may follow on the same line.
      text.version = "#version " + std::string(toks_[code.first + 2].text());
      code.first += 3;
      PresumedLocation at = sm_.presumed(toks_[code.first - 1].loc);
      while (code.first < code.last && toks_[code.first].is(TokenKind::identifier) &&
             sm_.presumed(toks_[code.first].loc).line == at.line)
        text.version.append(" ").append(toks_[code.first++].text());
    }
    detail::ShaderTextWriter w(sm_);
    for (uint32_t i = code.first; i < code.last && i < toks_.size(); ++i) w.token(toks_[i]);
    w.end_line();
    text.body = std::move(w.out());
    u_.glsl_blocks_.push_back(std::move(text));
  }
}

}  // namespace fx
