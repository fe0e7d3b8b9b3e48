// The recursive-descent effect parser shared by parser.cpp (cursor, errors, recovery,
// file scope), parse_expr.cpp (expressions), parse_decl.cpp (types, variables, functions,
// structs, buffers) and parse_technique.cpp (techniques, passes, states, annotations).
// Private to fxkit_parser.
#pragma once
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fx/ast.h"
#include "fx/diagnostic.h"
#include "fx/parser.h"
#include "fx/source_manager.h"

namespace fx::detail {

class Parser {
 public:
  Parser(std::vector<Token> tokens, const SourceManager& sm, DiagnosticSink& diags, const ParseOptions& options);
  ast::Effect run();

 private:
  // --- cursor (parser.cpp) ---
  const Token& tok() const { return tokens_[pos_]; }
  const Token& peek(size_t ahead = 1) const {
    size_t i = pos_ + ahead;
    return i < tokens_.size() ? tokens_[i] : tokens_.back();
  }
  bool at(TokenKind k) const { return tokens_[pos_].kind == k; }
  bool at_ident(std::string_view name) const { return tokens_[pos_].is_identifier(name); }
  bool at_eof() const { return at(TokenKind::eof); }
  // Consumes the current token (never the final eof) and tracks brace depth. Inline: it
  // runs once per token from every part of the parser.
  const Token& advance() {
    const Token& t = tokens_[pos_];
    if (t.kind == TokenKind::eof) return t;
    if (t.kind == TokenKind::l_brace) ++depth_;
    else if (t.kind == TokenKind::r_brace && depth_ > 0) --depth_;
    ++pos_;
    return t;
  }
  // The cursor helpers below are inline: each runs once or more per token or node.
  bool accept(TokenKind k) {
    if (!at(k)) return false;
    advance();
    return true;
  }
  // Consumes `k` or reports `expected-token`: "expected 'k' <context>".
  bool expect(TokenKind k, std::string_view context);
  // A missing ';' before a token on a new line is reported without derailing the parse.
  bool expect_semi(std::string_view context) { return accept(TokenKind::semi) || missing_semi(context); }
  bool missing_semi(std::string_view context);
  // Splits `>>`, `>=`, `>>=` so that the current token is a single `>`.
  void split_greater();
  SourceLocation end_of_previous() const {
    if (pos_ == 0) return tok().loc;
    return tokens_[pos_ - 1].range().end;
  }
  SourceRange range_from(uint32_t first) const {
    SourceRange r{tokens_[first].loc, tokens_[first].range().end};
    if (pos_ > first) r.end = end_of_previous();
    return r;
  }
  ast::TokenSpan span_from(uint32_t first) const { return {first, pos_}; }
  // A copy of `text` in the effect's arena, for the nodes' names and texts.
  ast::Text keep(std::string_view text) { return arena_.text(text); }

  // --- errors and recovery (parser.cpp) ---
  // Reports unless an error is already being recovered from; marks the parse failed.
  Diagnostic* error(std::string id, SourceRange range, std::string message);
  Diagnostic* error_here(std::string id, std::string message);
  void unterminated(const Token& open, std::string_view what);
  // At '{': `{ item, item, ... }`, a trailing comma allowed; `item` parses one and returns
  // false to stop. False after `item` fails or after "expected ',' or '}' <where>" (with a
  // note at the '{').
  bool parse_braced_list(std::string_view where, const std::function<bool()>& item);
  // Skips to the end of the broken construct: past the next ';' at `depth`, before a '}'
  // that closes the enclosing block (or a '>' ending annotations), or past a '}' that
  // returns to `depth` (and one ';' after it). Clears the failed state.
  void recover(uint32_t depth, bool stop_at_greater = false);
  // Consumes `{ ... }` without parsing it; returns the span between the braces.
  bool skip_braced(ast::TokenSpan& inner, std::string_view what);

  // --- file scope (parser.cpp) ---
  void parse_profile_header();
  void parse_top_level(std::vector<ast::Decl>& out);
  bool parse_attributes(std::vector<std::string>& out);
  void parse_glsl_block(std::vector<ast::Decl>& out);
  // Reports `keyword-as-name` when `name` is an effect keyword: "cannot name <what>".
  bool check_name(const Token& name, std::string_view what);

  // --- declarations (parse_decl.cpp) ---
  uint32_t parse_storage();
  bool parse_type(ast::TypeRef& type);
  bool parse_template_args(std::string& out);
  bool parse_array_dims(ast::List<ast::ExprPtr>& dims);
  bool parse_semantics(ast::Variable& v);
  bool parse_declarator_head(ast::Variable& v);
  bool parse_initializer(ast::Variable& v);
  void parse_variable_or_function(std::vector<ast::Decl>& out, uint32_t first, std::vector<std::string> attributes);
  // At `C` of `type C::M(...) { ... }`: the definition of class C's method M, which
  // completes M's prototype in C (declared earlier in `out`).
  void parse_method_definition(std::vector<ast::Decl>& out, uint32_t first, uint32_t storage,
                               const ast::TypeRef& return_type);
  bool parse_function(ast::Function& f);
  bool parse_parameter(ast::Variable& p);
  // `{ members }` of a struct or buffer; with `methods`, member functions too (class,
  // interface).
  bool parse_member_list(ast::List<ast::Variable>& members, std::string_view what,
                         ast::List<ast::Function>* methods = nullptr);
  // A member function, at its name after the return type.
  void parse_method(ast::List<ast::Function>& methods, uint32_t storage, const ast::TypeRef& return_type,
                    uint32_t first);
  // `struct`, `interface` or `class` at file scope.
  void parse_struct(std::vector<ast::Decl>& out);
  // `struct [Name] { members }` as a member's type (at `struct`).
  bool parse_member_struct(ast::TypeRef& type);
  void parse_typedef(std::vector<ast::Decl>& out);
  // At `cbuffer`/`tbuffer`; `first` is the declaration's first token (`shared`, if any).
  void parse_constant_buffer(std::vector<ast::Decl>& out, uint32_t first);
  void finish_state_object(std::vector<ast::Decl>& out, ast::Variable& head, uint32_t first);
  // `{ { states }, { states } }`: one state list per array element.
  bool parse_element_states(ast::List<ast::List<ast::StateAssignment>>& out);

  // --- effect blocks (parse_technique.cpp) ---
  bool parse_annotations(ast::List<ast::Annotation>& out);
  // One annotation declaration: a type and one or more `name = value` declarators.
  void parse_annotation(ast::List<ast::Annotation>& out);
  bool parse_technique(ast::Technique& t);
  bool parse_pass(ast::Pass& p);
  // `{ State = value; ... }` (pass bodies, state objects, sampler_state).
  bool parse_state_list(ast::List<ast::StateAssignment>& out, std::string_view what);
  bool parse_state(ast::StateAssignment& s);
  void parse_group(std::vector<ast::Decl>& out);

  // --- expressions (parse_expr.cpp) ---
  ast::ExprPtr parse_expression();  // with the comma operator
  ast::ExprPtr parse_assignment();  // one initializer / argument (no comma operator)
  ast::ExprPtr parse_binary(int min_precedence);
  ast::ExprPtr parse_unary();
  // `[index]` and `.member` after an operand; most operands have neither.
  ast::ExprPtr parse_postfix(ast::ExprPtr e, uint32_t first) {
    return at(TokenKind::l_square) || at(TokenKind::period) ? parse_postfix_operators(e, first) : e;
  }
  ast::ExprPtr parse_postfix_operators(ast::ExprPtr e, uint32_t first);
  // At '(': how far ahead the ')' of a cast's type (`(float3)`, `(float2[32])`) is, when
  // an operand follows it; 0 when this is no cast.
  size_t cast_close() const;
  // `[subscript]` after `e` (at the '['): the index node, its range still to be set.
  ast::ExprPtr parse_index(ast::ExprPtr e, uint32_t first);
  ast::ExprPtr parse_primary();
  ast::ExprPtr parse_identifier_expr();
  ast::ExprPtr parse_compile();
  ast::ExprPtr parse_asm();
  ast::ExprPtr parse_init_list();
  bool parse_call_args(std::span<const ast::ExprPtr>& args);
  ast::ExprPtr make(ast::ExprKind kind, uint32_t first);
  bool enter_nesting() {
    if (++nesting_ <= options_.max_nesting) return true;
    return nesting_too_deep();
  }
  bool nesting_too_deep();
  void leave_nesting() { --nesting_; }

  std::vector<Token> tokens_;
  ast::DeclPool declarations_;
  ast::ExprPool expressions_;
  ast::Arena arena_;  // the nodes' texts and lists
  // Arguments and list elements being parsed, innermost list last: each list is stored
  // in the pool once complete, so none needs a vector of its own.
  std::vector<ast::ExprPtr> pending_args_;
  uint32_t pos_ = 0;
  uint32_t depth_ = 0;      // unclosed '{' consumed so far
  size_t nesting_ = 0;      // current recursion depth of expressions
  bool failed_ = false;     // an error was reported and not yet recovered from
  bool eof_error_ = false;  // recovery ran into eof: further errors would be echoes
  std::string profile_header_;
  const SourceManager& sm_;
  DiagnosticSink& diags_;
  ParseOptions options_;
};

// Keyword tests shared by the parts.
bool is_storage_keyword(std::string_view word, uint32_t& bit);
bool is_state_object_kind(std::string_view word);
// 9, 10 or 11 for `technique`, `technique10`, `technique11` in any case; 0 otherwise.
int technique_version(std::string_view word);
// An effect keyword, which the D3DX lexer matches in any case (`Pass`, `COMPILE`).
bool is_effect_keyword(std::string_view word);
std::string quote(std::string_view text);  // 'text' for messages
std::string describe(const Token& t);      // 'text', or "end of file"
// Appends a token's spelling to text rebuilt from tokens, with a space between words.
void append_spelling(std::string& out, const Token& t);

}  // namespace fx::detail
