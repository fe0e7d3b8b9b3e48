// Name resolution in function bodies (body_resolver.h): one pass over the tokens with a
// scope stack. Declarations are recognised at statement starts (`[modifiers] Type name`),
// identifiers resolved innermost scope first, and `.name` typed from the value before it.
#include "body_resolver.h"

#include <algorithm>
#include <array>

namespace fx::semantic {
namespace {

// Words of the language itself: never resolved, never counted.
constexpr std::array<std::string_view, 47> kKeywords = {"if",
                                                        "else",
                                                        "for",
                                                        "while",
                                                        "do",
                                                        "switch",
                                                        "case",
                                                        "default",
                                                        "break",
                                                        "continue",
                                                        "return",
                                                        "discard",
                                                        "true",
                                                        "false",
                                                        "TRUE",
                                                        "FALSE",
                                                        "NULL",
                                                        "this",
                                                        "struct",
                                                        "typedef",
                                                        "const",
                                                        "static",
                                                        "uniform",
                                                        "extern",
                                                        "volatile",
                                                        "precise",
                                                        "row_major",
                                                        "column_major",
                                                        "inline",
                                                        "groupshared",
                                                        "nointerpolation",
                                                        "noperspective",
                                                        "centroid",
                                                        "in",
                                                        "out",
                                                        "inout",
                                                        "register",
                                                        "packoffset",
                                                        "snorm",
                                                        "unorm",
                                                        "compile",
                                                        "sampler_state",
                                                        "stateblock_state",
                                                        "asm",
                                                        "vector",
                                                        "matrix",
                                                        "unsigned"};

// Modifiers that may precede a local declaration's type.
constexpr std::array<std::string_view, 13> kModifiers = {
    "const",  "static",      "uniform", "precise", "row_major", "column_major", "volatile",
    "extern", "groupshared", "snorm",   "unorm",   "inline",    "unsigned"};  // `unsigned int`: fxc's uint

// Loop and branch attributes: `[unroll]`, `[loop]`, `[unroll(4)]` before a statement.
constexpr std::array<std::string_view, 10> kAttributes = {
    "unroll", "loop",      "branch",  "flatten",   "fastopt", "allow_uav_condition",
    "call",   "forcecase", "isolate", "maxtempreg"};

// Constructs the model does not follow: a body holding one is resolved, but nothing in it
// is reported.
constexpr std::array<std::string_view, 9> kUnmodelled = {"struct",   "typedef", "class", "interface", "namespace",
                                                         "template", "asm",     "_asm",  "__asm"};

template <size_t N>
bool one_of(const std::array<std::string_view, N>& words, std::string_view w) {
  return std::find(words.begin(), words.end(), w) != words.end();
}

std::string quote(std::string_view s) { return "'" + std::string(s) + "'"; }

}  // namespace

BodyResolver::BodyResolver(SemanticModel& model, const ast::Function& function)
    : model_(model), function_(function), tokens_(model.effect_.tokens) {
  first_ = std::min<uint32_t>(function.body.first, static_cast<uint32_t>(tokens_.size()));
  last_ = std::min<uint32_t>(function.body.last, static_cast<uint32_t>(tokens_.size()));
  auto it = model.function_symbols_.find(&function);
  if (it != model.function_symbols_.end() && !it->second->container.empty())
    if (const Symbol* s = model.global(it->second->container); s && s->kind == SymbolKind::structure)
      owner_ = s->structure;
  modelled_ = models_body();
}

bool BodyResolver::models_body() const {
  for (uint32_t i = first_; i < last_; ++i)
    if (tokens_[i].is(TokenKind::identifier) && one_of(kUnmodelled, tokens_[i].text())) return false;
  return true;
}

void BodyResolver::declare_parameters() {
  const Symbol* fn = model_.function_symbols_.at(&function_);
  if (!fn->type.known()) modelled_ = false;
  for (const ast::Variable& p : function_.params) {
    Symbol s;
    s.kind = SymbolKind::function_parameter;
    s.name = p.name;
    s.name_range = p.name_range;
    s.range = p.range;
    s.container = fn->name;
    s.variable = &p;
    s.type = model_.resolve_type(p.type, p.array_dims.size());
    if (!s.type.known() && p.type.template_arg.empty()) modelled_ = false;  // see try_declaration
    s.visible = {first_, last_};
    Symbol& added = model_.add(std::move(s));
    model_.locals_.push_back(&added);
    scope_.push_back(&added);
  }
}

void BodyResolver::run() {
  if (first_ >= last_) return;
  declare_parameters();
  const size_t parameters = scope_.size();
  bool statement_start = true, after_case = false, skip_semantic = false;
  int ternaries = 0;
  for (uint32_t i = first_; i < last_; ++i) {
    if (i == annotations_first_ && annotations_end_ > i) {
      i = annotations_end_ - 1;  // annotation names and values are no identifiers of the code
      continue;
    }
    const Token& t = tokens_[i];
    const bool at_start = statement_start;
    statement_start = false;
    switch (t.kind) {
      case TokenKind::l_brace:
        if (declaration_.active) ++declaration_.braces;
        else open_scope();
        statement_start = !declaration_.active;
        break;
      case TokenKind::r_brace:
        if (declaration_.active && declaration_.braces > 0) {
          --declaration_.braces;
        } else {
          declaration_.active = false;
          close_scope(i);
          statement_start = true;
        }
        break;
      case TokenKind::semi:
        if (declaration_.active && parens_ <= declaration_.parens) declaration_.active = false;
        ternaries = 0;
        statement_start = parens_ == 0;
        break;
      case TokenKind::l_paren: {
        ++parens_;
        const bool is_for = i > first_ && tokens_[i - 1].is_identifier("for");
        statement_start = is_for;
        control_parens_.push_back(
            is_for || (i > first_ && (tokens_[i - 1].is_identifier("if") || tokens_[i - 1].is_identifier("while") ||
                                      tokens_[i - 1].is_identifier("switch"))));
        break;
      }
      case TokenKind::r_paren:
        parens_ = std::max(0, parens_ - 1);
        if (!control_parens_.empty()) {
          statement_start = control_parens_.back();  // `for (...) [unroll] for (...)`: a statement follows
          control_parens_.pop_back();
        }
        break;
      case TokenKind::l_square:
        if (at_start && i + 1 < last_ && tokens_[i + 1].is(TokenKind::identifier) &&
            one_of(kAttributes, tokens_[i + 1].text())) {
          int depth = 0;  // skip the attribute; a statement follows
          for (; i < last_; ++i) {
            if (tokens_[i].is(TokenKind::l_square)) ++depth;
            if (tokens_[i].is(TokenKind::r_square) && --depth == 0) break;
          }
          statement_start = true;
          break;
        }
        brackets_.push_back(i);
        break;
      case TokenKind::r_square:
        if (!brackets_.empty()) {
          const uint32_t open = brackets_.back();
          brackets_.pop_back();
          if (auto it = typed_.find(open - 1); open > first_ && it != typed_.end())
            typed_[i] = element_type(it->second);
        }
        break;
      case TokenKind::question: ++ternaries; break;
      case TokenKind::colon:
        if (ternaries > 0) {
          --ternaries;
        } else if (after_case) {
          after_case = false;
          statement_start = true;
        } else {
          skip_semantic = true;
        }
        break;
      case TokenKind::comma:
        if (declaration_.active && parens_ == declaration_.parens && declaration_.braces == 0 && i + 2 < last_ &&
            tokens_[i + 1].is(TokenKind::identifier)) {
          const TokenKind next = tokens_[i + 2].kind;
          if ((next == TokenKind::equal || next == TokenKind::comma || next == TokenKind::semi ||
               next == TokenKind::l_square || next == TokenKind::colon || next == TokenKind::less) &&
              skip_annotations_of(i + 1)) {
            ++i;
            ShaderType type = declaration_.type;
            type.array_rank += array_rank_after(i + 1);
            declare_local(i, type, declaration_.type_first);
          }
        }
        break;
      case TokenKind::identifier: {
        const std::string_view text = t.text();
        if (at_start && try_declaration(i)) break;
        if (skip_semantic) {
          skip_semantic = false;
          break;
        }
        if (text == "case" || text == "default") after_case = true;
        if (text == "else" || text == "do") statement_start = true;
        const TokenKind before = i > first_ ? tokens_[i - 1].kind : TokenKind::eof;
        if (before == TokenKind::coloncolon) break;
        if (before == TokenKind::period) {
          resolve_member(i);
          break;
        }
        if (i + 1 < last_ && tokens_[i + 1].is(TokenKind::coloncolon)) break;
        resolve_identifier(i);
        break;
      }
      default: break;
    }
  }
  for (size_t k = parameters; k < scope_.size(); ++k) scope_[k]->visible.last = last_;
}

void BodyResolver::open_scope() { scope_marks_.push_back(scope_.size()); }

void BodyResolver::close_scope(uint32_t at) {
  if (scope_marks_.empty()) return;
  const size_t mark = scope_marks_.back();
  scope_marks_.pop_back();
  for (size_t k = mark; k < scope_.size(); ++k) scope_[k]->visible.last = at;
  scope_.resize(mark);
}

bool BodyResolver::is_type_name(std::string_view name) const {
  if (builtin_numeric_type(name) || is_object_type_name(name) || name == "vector" || name == "matrix") return true;
  if (lookup(name)) {
    const Symbol* s = lookup(name);
    return s->kind == SymbolKind::structure || s->kind == SymbolKind::type_alias;
  }
  return false;
}

uint32_t BodyResolver::skip_template_arguments(uint32_t i) const {
  // i is at `<`; returns the token after the matching `>` (or i when there is none).
  int depth = 0;
  for (uint32_t k = i; k < last_; ++k) {
    const TokenKind kind = tokens_[k].kind;
    if (kind == TokenKind::less) ++depth;
    if (kind == TokenKind::greater) --depth;
    if (kind == TokenKind::greatergreater) depth -= 2;
    if (depth <= 0) return depth == 0 ? k + 1 : i;
    if (kind == TokenKind::semi || kind == TokenKind::l_brace || kind == TokenKind::r_brace) return i;
  }
  return i;
}

uint32_t BodyResolver::after_annotations(uint32_t i) const {
  // i is at `<`; returns the token after the matching `>` (or i when there is none). An
  // annotation block holds `type name = value;` entries, so `;` does not end it.
  for (uint32_t k = i + 1; k < last_; ++k) {
    const TokenKind kind = tokens_[k].kind;
    if (kind == TokenKind::greater) return k + 1;
    if (kind == TokenKind::less || kind == TokenKind::l_brace || kind == TokenKind::r_brace) return i;
  }
  return i;
}

bool BodyResolver::skip_annotations_of(uint32_t name_token) {
  // `float var < > = 0;`: annotations after a declarator's name and array sizes (fxc takes
  // an empty block on a local; the front end reports a non-empty one). False when a `<`
  // follows that opens no block: then the words are no declaration.
  const uint32_t at = after_array_sizes(name_token + 1, nullptr);
  if (at >= last_ || !tokens_[at].is(TokenKind::less)) return true;
  const uint32_t end = after_annotations(at);
  if (end == at) return false;
  annotations_first_ = at;
  annotations_end_ = end;
  return true;
}

uint32_t BodyResolver::after_array_sizes(uint32_t i, uint32_t* rank) const {
  while (i < last_ && tokens_[i].is(TokenKind::l_square)) {
    int depth = 0;
    for (; i < last_; ++i) {
      if (tokens_[i].is(TokenKind::l_square)) ++depth;
      if (tokens_[i].is(TokenKind::r_square) && --depth == 0) break;
    }
    if (rank) ++*rank;
    ++i;
  }
  return i;
}

uint32_t BodyResolver::array_rank_after(uint32_t i) const {
  uint32_t rank = 0;
  after_array_sizes(i, &rank);
  return rank;
}

bool BodyResolver::try_declaration(uint32_t& i) {
  uint32_t j = i;
  while (j < last_ && tokens_[j].is(TokenKind::identifier) && one_of(kModifiers, tokens_[j].text())) ++j;
  // `vector` and `matrix` are keywords that name types (`matrix m = ...;`).
  if (j >= last_ || !tokens_[j].is(TokenKind::identifier) ||
      (one_of(kKeywords, tokens_[j].text()) && tokens_[j].text() != "vector" && tokens_[j].text() != "matrix"))
    return false;
  const std::string_view type_name = tokens_[j].text();
  // `Name name =` with a Name that is no type the model knows: a type from a dialect or a
  // prelude the compiler adds (pre-release HLSL's vec3). Declared, but the body goes quiet.
  const bool known_type = is_type_name(type_name);
  if (!known_type && (lookup(type_name) || find_intrinsic(type_name))) return false;
  uint32_t k = j + 1;
  const bool templated = k < last_ && tokens_[k].is(TokenKind::less) && takes_template_arguments(type_name);
  if (templated) {
    k = skip_template_arguments(k);
    if (k == j + 1) return false;
  }
  if (k + 1 >= last_ || !tokens_[k].is(TokenKind::identifier) || one_of(kKeywords, tokens_[k].text())) return false;
  const TokenKind next = tokens_[k + 1].kind;
  if (next != TokenKind::equal && next != TokenKind::semi && next != TokenKind::comma && next != TokenKind::l_square &&
      next != TokenKind::colon && next != TokenKind::less)
    return false;
  if (!skip_annotations_of(k)) return false;
  if (!known_type) modelled_ = false;
  ShaderType type;
  if (templated) {
    type.kind = is_object_type_name(type_name) ? TypeClass::object : TypeClass::unknown;
    for (uint32_t t = j; t < k; ++t) type.name += tokens_[t].text();
  } else {
    type = model_.resolve_type_name(type_name);
  }
  if (const Symbol* s = lookup(type_name)) add_reference(j, s, {});
  ShaderType declared = type;
  declared.array_rank += array_rank_after(k + 1);
  declare_local(k, declared, j);
  declaration_ = Declaration{true, type, j, parens_, 0};
  i = k;
  return true;
}

void BodyResolver::declare_local(uint32_t name_token, const ShaderType& type, uint32_t type_first) {
  const Token& t = tokens_[name_token];
  Symbol s;
  s.kind = SymbolKind::local;
  s.name = t.text();
  s.name_range = t.range();
  s.range = {tokens_[type_first].loc, t.range().end};
  s.container = function_.name;
  s.type = type;
  s.visible = {name_token, last_};
  Symbol& added = model_.add(std::move(s));
  model_.locals_.push_back(&added);
  scope_.push_back(&added);
  Reference r;
  r.token = name_token;
  r.symbol = &added;
  r.type = type;
  r.declaration = true;
  model_.references_.push_back(std::move(r));
  typed_[name_token] = type;
}

const Symbol* BodyResolver::lookup(std::string_view name) const {
  for (auto it = scope_.rbegin(); it != scope_.rend(); ++it)
    if ((*it)->name == name) return *it;
  if (owner_)
    if (const Symbol* m = class_member(*owner_, name, 0)) return m;
  return model_.global(name);
}

const Symbol* BodyResolver::class_member(const ast::Struct& c, std::string_view name, int depth) const {
  if (const Symbol* m = model_.member(c, name)) return m;
  for (const ast::Function& method : c.methods)
    if (method.name == name) return model_.function_symbols_.at(&method);
  if (depth > 16) return nullptr;        // a cycle of bases: reported by the compiler, not here
  for (const ast::Text& base : c.bases)  // `class Rough : Base`: Base's members too
    if (const Symbol* b = model_.global(base); b && b->kind == SymbolKind::structure && b->structure)
      if (const Symbol* m = class_member(*b->structure, name, depth + 1)) return m;
  return nullptr;
}

void BodyResolver::add_reference(uint32_t i, const Symbol* symbol, const ShaderType& type) {
  Reference r;
  r.token = i;
  r.symbol = symbol;
  r.type = type;
  model_.references_.push_back(std::move(r));
  if (type.known()) typed_[i] = type;
}

bool BodyResolver::quiet(uint32_t i) const { return !modelled_ || (tokens_[i].flags & kFromMacro); }

void BodyResolver::resolve_identifier(uint32_t i) {
  const std::string_view name = tokens_[i].text();
  if (one_of(kKeywords, name)) return;
  if (const Symbol* s = lookup(name)) {
    ++model_.counts_.identifiers;
    ++model_.counts_.resolved;
    const bool value =
        s->kind != SymbolKind::structure && s->kind != SymbolKind::type_alias && s->kind != SymbolKind::function;
    add_reference(i, s, value ? s->type : ShaderType{});
    return;
  }
  if (builtin_numeric_type(name) || is_object_type_name(name)) return;
  ++model_.counts_.identifiers;
  if (const Intrinsic* in = find_intrinsic(name)) {
    ++model_.counts_.intrinsics;
    Reference r;
    r.token = i;
    r.intrinsic = in;
    model_.references_.push_back(std::move(r));
    return;
  }
  if (quiet(i)) {
    ++model_.counts_.unresolved;
    return;
  }
  report_unknown_identifier(i);
}

void BodyResolver::resolve_member(uint32_t i) {
  ++model_.counts_.identifiers;
  const uint32_t base_token = i - 2;
  auto it = i >= first_ + 2 ? typed_.find(base_token) : typed_.end();
  if (it == typed_.end()) {
    ++model_.counts_.unresolved;
    return;
  }
  const ShaderType base = it->second;
  const std::string_view name = tokens_[i].text();
  if (base.kind == TypeClass::structure && base.array_rank == 0 && base.structure) {
    if (const Symbol* m = model_.member(*base.structure, name)) {
      ++model_.counts_.resolved;
      add_reference(i, m, m->type);
      return;
    }
    for (const ast::Function& method : base.structure->methods)
      if (method.name == name) {
        ++model_.counts_.resolved;
        add_reference(i, model_.function_symbols_.at(&method), {});
        return;
      }
    if (quiet(i) || !base.structure->bases.empty()) {
      ++model_.counts_.unresolved;
      return;
    }
    report_unknown_member(i, base);
    return;
  }
  if (base.kind == TypeClass::scalar || base.kind == TypeClass::vector || base.kind == TypeClass::matrix) {
    if (auto swizzled = swizzle_type(base, name)) {
      ++model_.counts_.resolved;
      typed_[i] = *swizzled;
      Reference r;
      r.token = i;
      r.type = *swizzled;
      model_.references_.push_back(std::move(r));
      return;
    }
    if (quiet(i) || base.array_rank != 0) {
      ++model_.counts_.unresolved;
      return;
    }
    report_unknown_member(i, base);
    return;
  }
  if (base.kind == TypeClass::object) ++model_.counts_.methods;  // `tex.Sample`
  else ++model_.counts_.unresolved;                              // a value of a type not modelled
}

void BodyResolver::report_unknown_identifier(uint32_t i) {
  const std::string_view name = tokens_[i].text();
  std::vector<std::string_view> candidates;
  for (const Symbol* s : scope_) candidates.push_back(s->name);
  if (owner_)
    for (const Symbol* m : model_.members(*owner_)) candidates.push_back(m->name);
  for (const Symbol* g : model_.globals_) candidates.push_back(g->name);
  for (const Intrinsic& in : all_intrinsics()) candidates.push_back(in.name);
  const std::string guess = closest_match(name, candidates);
  std::string message = "use of undeclared identifier " + quote(name);
  if (!guess.empty()) message += "; did you mean " + quote(guess) + "?";
  Diagnostic d;
  d.id = "unknown-identifier";
  d.range = tokens_[i].range();
  d.message = std::move(message);
  if (!guess.empty()) {
    d.fixits.push_back({d.range, guess});
    if (const Symbol* s = lookup(guess); s && s->name_range.valid())
      d.notes.push_back({s->name_range.begin, quote(guess) + " is declared here"});
  }
  model_.diagnostics_.push_back(std::move(d));
  ++model_.counts_.diagnosed;
}

void BodyResolver::report_unknown_member(uint32_t i, const ShaderType& base) {
  const std::string_view name = tokens_[i].text();
  Diagnostic d;
  d.id = "unknown-member";
  d.range = tokens_[i].range();
  if (base.kind == TypeClass::structure) {
    std::vector<std::string_view> candidates;
    for (const Symbol* m : model_.members(*base.structure)) candidates.push_back(m->name);
    for (const ast::Function& method : base.structure->methods) candidates.push_back(method.name);
    const std::string guess = closest_match(name, candidates);
    d.message = "no member named " + quote(name) + " in " + quote(base.name);
    if (!guess.empty()) {
      d.message += "; did you mean " + quote(guess) + "?";
      d.fixits.push_back({d.range, guess});
      if (const Symbol* m = model_.member(*base.structure, guess))
        d.notes.push_back({m->name_range.begin, quote(guess) + " is declared here"});
    } else if (base.structure->name_range.valid()) {
      d.notes.push_back({base.structure->name_range.begin, quote(base.name) + " is declared here"});
    }
  } else {
    d.message = quote(name) + " is no swizzle of " + quote(base.name) +
                " (up to four of x, y, z, w or of r, g, b, a, within its size)";
  }
  model_.diagnostics_.push_back(std::move(d));
  ++model_.counts_.diagnosed;
}

}  // namespace fx::semantic
