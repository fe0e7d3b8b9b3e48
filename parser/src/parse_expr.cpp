// Effect expressions: initializers, annotation values, state values, array sizes.
// Precedence climbing for binary operators; recursion is bounded by max_nesting.
#include <utility>

#include "fx/lexer.h"
#include "parse_internal.h"

namespace fx::detail {
namespace {

// Binding strength of a binary operator token (0: not a binary operator).
int binary_precedence(TokenKind k) {
  switch (k) {
    case TokenKind::pipepipe: return 1;
    case TokenKind::ampamp: return 2;
    case TokenKind::pipe: return 3;
    case TokenKind::caret: return 4;
    case TokenKind::amp: return 5;
    case TokenKind::equalequal:
    case TokenKind::exclaimequal: return 6;
    case TokenKind::less:
    case TokenKind::greater:
    case TokenKind::lessequal:
    case TokenKind::greaterequal: return 7;
    case TokenKind::lessless:
    case TokenKind::greatergreater: return 8;
    case TokenKind::plus:
    case TokenKind::minus: return 9;
    case TokenKind::star:
    case TokenKind::slash:
    case TokenKind::percent: return 10;
    default: return 0;
  }
}

// A token after which no expression continues: what follows most state, annotation and
// argument values (`ZEnable = true;`, `{0, 1}`, `f(a, b)`).
bool ends_expression(TokenKind k) {
  return k == TokenKind::semi || k == TokenKind::comma || k == TokenKind::r_paren || k == TokenKind::r_brace ||
         k == TokenKind::r_square;
}

bool starts_operand(TokenKind k) {
  return k == TokenKind::identifier || k == TokenKind::integer || k == TokenKind::floating || k == TokenKind::l_paren ||
         k == TokenKind::string;
}

// Fast path for the common plain decimal integer (`0`, `16`): no copy, no strtod.
bool decimal_value(std::string_view s, double& out) {
  if (s.empty() || s.size() > 15 || (s.size() > 1 && s[0] == '0')) return false;
  uint64_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + uint64_t(c - '0');
  }
  out = double(v);
  return true;
}

// Fast path for a plain `0.577` / `1.0f` with at most 15 significant digits: mantissa and
// power of ten are both exact doubles, so one IEEE division gives the correctly rounded
// value strtod would. Anything else (exponents, long mantissas) takes parse_number.
bool simple_float_value(std::string_view s, double& out) {
  static constexpr double kPow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  if (!s.empty() && (s.back() == 'f' || s.back() == 'F' || s.back() == 'h' || s.back() == 'H')) s.remove_suffix(1);
  uint64_t mantissa = 0;
  int digits = 0, fraction = -1;
  for (char c : s) {
    if (c == '.') {
      if (fraction >= 0) return false;
      fraction = 0;
      continue;
    }
    if (c < '0' || c > '9' || ++digits > 15) return false;
    mantissa = mantissa * 10 + uint64_t(c - '0');
    if (fraction >= 0) ++fraction;
  }
  if (fraction < 0 || digits == 0) return false;
  out = double(mantissa) / kPow10[fraction];
  return true;
}

}  // namespace

bool Parser::nesting_too_deep() {
  --nesting_;
  error_here("nesting-too-deep",
             "expression nested too deeply (more than " + std::to_string(options_.max_nesting) + " levels)");
  return false;
}

ast::ExprPtr Parser::make(ast::ExprKind kind, uint32_t first) {
  ast::ExprPtr e = expressions_.make(kind);
  e->range = tokens_[first].range();
  return e;
}

ast::ExprPtr Parser::parse_expression() {
  uint32_t first = pos_;
  ast::ExprPtr e = parse_assignment();
  while (!failed_ && at(TokenKind::comma)) {
    advance();
    ast::ExprPtr rhs = parse_assignment();
    if (failed_) return nullptr;
    auto comma = make(ast::ExprKind::binary, first);
    comma->text = ",";
    comma->args = expressions_.list({e, rhs});
    comma->range = range_from(first);
    e = std::move(comma);
  }
  return failed_ ? nullptr : std::move(e);
}

ast::ExprPtr Parser::parse_assignment() {
  // A lone name or number is what parse_binary would return after climbing every level:
  // with nothing that continues an expression after it, its primary is the whole value.
  const TokenKind kind = tok().kind;
  if ((kind == TokenKind::identifier || kind == TokenKind::integer || kind == TokenKind::floating) &&
      ends_expression(peek().kind))
    return parse_primary();
  uint32_t first = pos_;
  ast::ExprPtr cond = parse_binary(1);
  if (failed_ || !at(TokenKind::question)) return cond;
  advance();
  auto e = make(ast::ExprKind::ternary, first);
  ast::ExprPtr then = parse_assignment();
  if (failed_ || !expect(TokenKind::colon, "in conditional expression")) return nullptr;
  ast::ExprPtr otherwise = parse_assignment();
  if (failed_) return nullptr;
  e->args = expressions_.list({cond, then, otherwise});
  e->range = range_from(first);
  return e;
}

ast::ExprPtr Parser::parse_binary(int min_precedence) {
  uint32_t first = pos_;
  ast::ExprPtr lhs = parse_unary();
  for (;;) {
    if (failed_) return nullptr;
    int precedence = binary_precedence(tok().kind);
    if (precedence == 0 || precedence < min_precedence) return lhs;
    auto e = make(ast::ExprKind::binary, first);
    e->text = keep(advance().text());
    ast::ExprPtr rhs = parse_binary(precedence + 1);
    if (failed_) return nullptr;
    e->args = expressions_.list({lhs, rhs});
    e->range = range_from(first);
    lhs = std::move(e);
  }
}

ast::ExprPtr Parser::parse_unary() {
  if (!enter_nesting()) return nullptr;
  uint32_t first = pos_;
  ast::ExprPtr result;
  switch (tok().kind) {
    case TokenKind::minus:
    case TokenKind::plus:
    case TokenKind::exclaim:
    case TokenKind::tilde:
    case TokenKind::plusplus:
    case TokenKind::minusminus: {
      result = make(ast::ExprKind::unary, first);
      result->text = keep(advance().text());
      ast::ExprPtr operand = parse_unary();
      if (failed_) {
        result = nullptr;
        break;
      }
      result->args = expressions_.list({operand});
      result->range = range_from(first);
      break;
    }
    case TokenKind::l_paren:
      // `(float3)x` is a cast when a lone name in parentheses is followed by an operand;
      // so is `(float2[32])x`, with constant array sizes.
      if (size_t close = cast_close(); close != 0) {
        result = make(ast::ExprKind::cast, first);
        advance();
        std::string type;
        while (pos_ < first + close) append_spelling(type, advance());
        result->text = keep(type);
        advance();
        ast::ExprPtr operand = parse_unary();
        if (failed_) {
          result = nullptr;
          break;
        }
        result->args = expressions_.list({operand});
        result->range = range_from(first);
        break;
      }
      [[fallthrough]];
    default:
      result = parse_primary();
      if (!failed_) result = parse_postfix(std::move(result), first);
      break;
  }
  leave_nesting();
  return failed_ ? nullptr : std::move(result);
}

size_t Parser::cast_close() const {
  if (!peek(1).is(TokenKind::identifier)) return 0;
  size_t i = 2;
  while (peek(i).is(TokenKind::l_square) && peek(i + 1).is(TokenKind::integer) && peek(i + 2).is(TokenKind::r_square))
    i += 3;
  return peek(i).is(TokenKind::r_paren) && starts_operand(peek(i + 1).kind) ? i : 0;
}

ast::ExprPtr Parser::parse_postfix_operators(ast::ExprPtr e, uint32_t first) {
  for (;;) {
    if (at(TokenKind::l_square)) {
      e = parse_index(e, first);
      if (!e) return nullptr;
      e->range = range_from(first);
    } else if (at(TokenKind::period) && peek().is(TokenKind::identifier)) {
      advance();
      auto member = make(ast::ExprKind::member, first);
      member->text = keep(advance().text());
      member->args = expressions_.list({e});
      member->range = range_from(first);
      e = std::move(member);
    } else {
      return e;
    }
  }
}

ast::ExprPtr Parser::parse_index(ast::ExprPtr e, uint32_t first) {
  advance();  // [
  auto index = make(ast::ExprKind::index, first);
  ast::ExprPtr subscript = parse_expression();
  if (failed_ || !expect(TokenKind::r_square, "after index")) return nullptr;
  index->args = expressions_.list({e, subscript});
  return index;
}

ast::ExprPtr Parser::parse_primary() {
  uint32_t first = pos_;
  const Token& t = tok();
  switch (t.kind) {
    case TokenKind::integer:
    case TokenKind::floating: {
      auto e = make(t.is(TokenKind::integer) ? ast::ExprKind::int_literal : ast::ExprKind::float_literal, first);
      const std::string_view spelling = t.text();
      e->text = keep(spelling);
      bool fast =
          t.is(TokenKind::integer) ? decimal_value(spelling, e->number) : simple_float_value(spelling, e->number);
      if (!fast) {
        std::string why;
        std::optional<NumberValue> value = parse_number(spelling, &why);
        if (!value) {
          error_here("invalid-number", why + " " + quote(spelling));
          return nullptr;
        }
        e->number = value->as_double();
      }
      advance();
      return e;
    }
    case TokenKind::string: {
      auto e = make(ast::ExprKind::string_literal, first);
      std::string text;
      while (at(TokenKind::string)) append_unquoted(text, advance().text());  // "a" "b" joins
      e->text = keep(text);
      e->range = range_from(first);
      return e;
    }
    case TokenKind::identifier: return parse_identifier_expr();
    case TokenKind::l_paren: {
      Token open = advance();
      ast::ExprPtr inner = parse_expression();
      if (failed_) return nullptr;
      if (!at(TokenKind::r_paren)) {
        if (Diagnostic* d = error_here("expected-token", "expected ')' after expression, found " + describe(tok())))
          d->notes.push_back({open.loc, "to match this '('"});
        return nullptr;
      }
      advance();
      return inner;
    }
    case TokenKind::l_brace: return parse_init_list();
    case TokenKind::less: {
      // `<name>` after '=' refers to a parameter (D3D9 state values).
      advance();
      if (!at(TokenKind::identifier)) {
        error_here("expected-identifier", "expected a parameter name after '<', found " + describe(tok()));
        return nullptr;
      }
      ast::ExprPtr e = make(ast::ExprKind::reference, first);
      e->text = keep(advance().text());
      // `<g_vLightPos[0]>` is an element: an index node over the reference, as `a[0]`.
      while (at(TokenKind::l_square))
        if (!(e = parse_index(e, first))) return nullptr;
      split_greater();
      if (!expect(TokenKind::greater, "to close the parameter reference")) return nullptr;
      e->range = range_from(first);
      return e;
    }
    default: error_here("expected-expression", "expected an expression, found " + describe(t)); return nullptr;
  }
}

ast::ExprPtr Parser::parse_identifier_expr() {
  uint32_t first = pos_;
  std::string_view word = tok().text();
  bool braces_follow = peek().is(TokenKind::l_brace);
  if (iequals(word, "true") || iequals(word, "false")) {
    auto e = make(ast::ExprKind::bool_literal, first);
    e->text = keep(word);
    e->number = iequals(word, "true") ? 1 : 0;
    advance();
    return e;
  }
  if (iequals(word, "NULL")) {
    auto e = make(ast::ExprKind::null, first);
    e->text = keep(word);
    advance();
    return e;
  }
  if (iequals(word, "compile")) return parse_compile();
  if (braces_follow && (iequals(word, "asm") || iequals(word, "decl"))) return parse_asm();
  if (braces_follow && (iequals(word, "sampler_state") || iequals(word, "stateblock_state"))) {
    auto e = make(ast::ExprKind::state_block, first);
    e->text = keep(advance().text());
    if (!parse_state_list(e->states, e->text)) return nullptr;
    e->range = range_from(first);
    return e;
  }
  advance();
  if (at(TokenKind::l_paren)) {
    auto e = make(ast::ExprKind::call, first);
    e->text = keep(word);
    if (!parse_call_args(e->args)) return nullptr;
    e->range = range_from(first);
    return e;
  }
  auto e = make(ast::ExprKind::identifier, first);
  e->text = keep(word);
  return e;
}

ast::ExprPtr Parser::parse_compile() {
  uint32_t first = pos_;
  advance();  // compile
  auto e = make(ast::ExprKind::compile, first);
  if (!at(TokenKind::identifier)) {
    error_here("expected-profile", "expected a shader profile after 'compile', found " + describe(tok()));
    return nullptr;
  }
  e->text = keep(advance().text());
  if (!at(TokenKind::identifier)) {
    error_here("expected-identifier", "expected a shader function after the profile, found " + describe(tok()));
    return nullptr;
  }
  e->callee = keep(advance().text());
  if (at(TokenKind::l_paren) && !parse_call_args(e->args)) return nullptr;
  e->range = range_from(first);
  return e;
}

ast::ExprPtr Parser::parse_asm() {
  uint32_t first = pos_;
  auto e = make(ast::ExprKind::asm_block, first);
  if (iequals(tok().text(), "decl")) {
    advance();
    if (!skip_braced(e->decl_code, "decl block")) return nullptr;
    if (!tok().is(TokenKind::identifier) || !iequals(tok().text(), "asm") || !peek().is(TokenKind::l_brace)) {
      error_here("expected-token", "expected 'asm { }' after 'decl { }', found " + describe(tok()));
      return nullptr;
    }
  }
  advance();  // asm
  if (!skip_braced(e->code, "asm block")) return nullptr;
  e->range = range_from(first);
  return e;
}

ast::ExprPtr Parser::parse_init_list() {
  uint32_t first = pos_;
  auto e = make(ast::ExprKind::init_list, first);
  size_t mark = pending_args_.size();
  parse_braced_list("in initializer list", [&] {
    ast::ExprPtr element = parse_assignment();
    if (failed_) return false;
    pending_args_.push_back(element);
    return true;
  });
  if (!failed_) e->args = expressions_.list(std::span(pending_args_).subspan(mark));
  pending_args_.resize(mark);
  if (failed_) return nullptr;
  e->range = range_from(first);
  return e;
}

bool Parser::parse_call_args(std::span<const ast::ExprPtr>& args) {
  Token open = advance();  // (
  if (accept(TokenKind::r_paren)) return true;
  size_t mark = pending_args_.size();
  for (;;) {
    ast::ExprPtr arg = parse_assignment();
    if (failed_) break;
    pending_args_.push_back(arg);
    if (accept(TokenKind::comma)) continue;
    if (accept(TokenKind::r_paren)) {
      args = expressions_.list(std::span(pending_args_).subspan(mark));
      break;
    }
    if (Diagnostic* d = error_here("expected-token", "expected ')' or ',' in argument list, found " + describe(tok())))
      d->notes.push_back({open.loc, "to match this '('"});
    break;
  }
  pending_args_.resize(mark);
  return !failed_;
}

}  // namespace fx::detail
