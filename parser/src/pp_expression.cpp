// The #if / #elif constant-expression evaluator: C's integer arithmetic on 64-bit
// values (signed, or unsigned when either operand is), short-circuiting && || ?:.
#include <climits>
#include <string>

#include "fx/lexer.h"
#include "pp_internal.h"

namespace fx::pp {
namespace {

struct Value {
  int64_t v = 0;
  bool is_unsigned = false;
  uint64_t u() const { return static_cast<uint64_t>(v); }
  bool truth() const { return v != 0; }
};

Value signed_value(int64_t v) { return {v, false}; }

int precedence(TokenKind k) {
  switch (k) {
    case TokenKind::star:
    case TokenKind::slash:
    case TokenKind::percent: return 10;
    case TokenKind::plus:
    case TokenKind::minus: return 9;
    case TokenKind::lessless:
    case TokenKind::greatergreater: return 8;
    case TokenKind::less:
    case TokenKind::greater:
    case TokenKind::lessequal:
    case TokenKind::greaterequal: return 7;
    case TokenKind::equalequal:
    case TokenKind::exclaimequal: return 6;
    case TokenKind::amp: return 5;
    case TokenKind::caret: return 4;
    case TokenKind::pipe: return 3;
    case TokenKind::ampamp: return 2;
    case TokenKind::pipepipe: return 1;
    default: return 0;
  }
}

class Evaluator {
 public:
  Evaluator(std::span<const Token> tokens, SourceLocation directive, DiagnosticSink& diags, Budget& budget)
      : t_(tokens), directive_(directive), diags_(diags), budget_(budget) {}

  bool run() {
    if (t_.empty()) {
      error({directive_, {}}, "#if with no expression");
      return false;
    }
    Value v = comma(true);
    if (!failed_ && pos_ < t_.size()) {
      error(t_[pos_].range(),
            "token '" + std::string(t_[pos_].text()) + "' is not a valid binary operator in a preprocessor expression");
    }
    return !failed_ && v.truth();
  }

 private:
  const Token* peek() const { return pos_ < t_.size() ? &t_[pos_] : nullptr; }
  bool at(TokenKind k) const { return pos_ < t_.size() && t_[pos_].is(k); }
  SourceRange here() const {
    return pos_ < t_.size() ? t_[pos_].range() : t_.empty() ? SourceRange{directive_, {}} : t_.back().range();
  }
  void error(SourceRange r, std::string message) {
    if (failed_) return;
    failed_ = true;
    diags_.error("pp-expression", r, std::move(message));
  }
  // Guards every recursive entry; false once the nesting limit is hit.
  bool enter() {
    if (++depth_ <= budget_.limits().max_nesting) return true;
    if (!failed_) {
      failed_ = true;
      budget_.fail(here(), "preprocessor expression nested more than " + std::to_string(budget_.limits().max_nesting) +
                               " levels deep");
    }
    return false;
  }

  Value comma(bool eval) {
    Value v = conditional(eval);
    while (!failed_ && at(TokenKind::comma)) {
      ++pos_;
      v = conditional(eval);
    }
    return v;
  }

  Value conditional(bool eval) {
    if (!enter()) return {};
    Value c = binary(1, eval);
    if (!failed_ && at(TokenKind::question)) {
      ++pos_;
      Value a = comma(eval && c.truth());
      if (!failed_ && !at(TokenKind::colon)) error(here(), "expected ':' in conditional expression");
      ++pos_;
      Value b = failed_ ? Value{} : conditional(eval && !c.truth());
      bool u = a.is_unsigned || b.is_unsigned;
      c = c.truth() ? a : b;
      c.is_unsigned = u;
    }
    --depth_;
    return c;
  }

  Value binary(int min_prec, bool eval) {
    Value lhs = unary(eval);
    for (;;) {
      if (failed_ || pos_ >= t_.size()) return lhs;
      const Token& op = t_[pos_];
      int prec = precedence(op.kind);
      if (prec == 0 || prec < min_prec) return lhs;
      ++pos_;
      if (op.is(TokenKind::ampamp) || op.is(TokenKind::pipepipe)) {
        bool is_and = op.is(TokenKind::ampamp);
        bool decided = is_and ? !lhs.truth() : lhs.truth();
        Value rhs = binary(prec + 1, eval && !decided);
        lhs = signed_value(decided ? !is_and : rhs.truth());
        continue;
      }
      Value rhs = binary(prec + 1, eval);
      lhs = apply(op, lhs, rhs, eval);
    }
  }

  Value apply(const Token& op, Value a, Value b, bool eval) {
    bool shift = op.is(TokenKind::lessless) || op.is(TokenKind::greatergreater);
    bool u = shift ? a.is_unsigned : a.is_unsigned || b.is_unsigned;
    auto cmp = [&](bool r) { return signed_value(r); };
    auto less = [&](Value x, Value y) { return u ? x.u() < y.u() : x.v < y.v; };
    switch (op.kind) {
      case TokenKind::plus: return {static_cast<int64_t>(a.u() + b.u()), u};
      case TokenKind::minus: return {static_cast<int64_t>(a.u() - b.u()), u};
      case TokenKind::star: return {static_cast<int64_t>(a.u() * b.u()), u};
      case TokenKind::slash:
      case TokenKind::percent: {
        if (b.v == 0) {
          if (eval) error(op.range(), "division by zero in preprocessor expression");
          return {0, u};
        }
        bool div = op.is(TokenKind::slash);
        if (u) return {static_cast<int64_t>(div ? a.u() / b.u() : a.u() % b.u()), true};
        if (a.v == INT64_MIN && b.v == -1) return {div ? INT64_MIN : 0, false};  // wraps
        return {div ? a.v / b.v : a.v % b.v, false};
      }
      case TokenKind::lessless:
      case TokenKind::greatergreater: {
        bool left = op.is(TokenKind::lessless);
        int64_t count = b.v;
        if (!b.is_unsigned && count < 0) left = !left, count = count == INT64_MIN ? 64 : -count;
        if (b.is_unsigned && b.u() >= 64) count = 64;
        if (count >= 64) return {(!left && !u && a.v < 0) ? -1 : 0, u};
        if (left) return {static_cast<int64_t>(a.u() << count), u};
        return {u ? static_cast<int64_t>(a.u() >> count) : a.v >> count, u};
      }
      case TokenKind::less: return cmp(less(a, b));
      case TokenKind::greater: return cmp(less(b, a));
      case TokenKind::lessequal: return cmp(!less(b, a));
      case TokenKind::greaterequal: return cmp(!less(a, b));
      case TokenKind::equalequal: return cmp(a.v == b.v);
      case TokenKind::exclaimequal: return cmp(a.v != b.v);
      case TokenKind::amp: return {a.v & b.v, u};
      case TokenKind::caret: return {a.v ^ b.v, u};
      case TokenKind::pipe: return {a.v | b.v, u};
      default: return a;
    }
  }

  Value unary(bool eval) {
    if (!enter()) return {};
    Value v;
    const Token* t = peek();
    if (t &&
        (t->is(TokenKind::minus) || t->is(TokenKind::plus) || t->is(TokenKind::tilde) || t->is(TokenKind::exclaim))) {
      ++pos_;
      Value x = unary(eval);
      switch (t->kind) {
        case TokenKind::minus: v = {static_cast<int64_t>(0 - x.u()), x.is_unsigned}; break;
        case TokenKind::tilde: v = {~x.v, x.is_unsigned}; break;
        case TokenKind::exclaim: v = signed_value(!x.truth()); break;
        default: v = x; break;
      }
    } else {
      v = primary(eval);
    }
    --depth_;
    return v;
  }

  Value primary(bool eval) {
    const Token* t = peek();
    if (!t) {
      error(here(), "expected value in preprocessor expression");
      return {};
    }
    ++pos_;
    switch (t->kind) {
      case TokenKind::l_paren: {
        Value v = comma(eval);
        if (!failed_ && !at(TokenKind::r_paren)) error(here(), "expected ')' in preprocessor expression");
        ++pos_;
        return v;
      }
      case TokenKind::integer: {
        std::string why;
        std::optional<NumberValue> n = parse_number(t->text(), &why);
        if (!n) {
          error(t->range(), why);
          return {};
        }
        int64_t v = std::get<int64_t>(n->value);
        bool u = v < 0 || t->text().find_first_of("uU") != std::string_view::npos;
        return {v, u};
      }
      case TokenKind::character: {
        std::string c = unquote(t->text());
        return signed_value(c.empty() ? 0 : static_cast<unsigned char>(c[0]));
      }
      case TokenKind::identifier:
        // C: identifiers left after expansion are 0. HLSL is C++-like, so true/false count.
        return signed_value(t->text() == "true" ? 1 : 0);
      case TokenKind::floating: error(t->range(), "floating-point literal in preprocessor expression"); return {};
      default: error(t->range(), "unexpected '" + std::string(t->text()) + "' in preprocessor expression"); return {};
    }
  }

  std::span<const Token> t_;
  SourceLocation directive_;
  DiagnosticSink& diags_;
  Budget& budget_;
  size_t pos_ = 0;
  uint32_t depth_ = 0;
  bool failed_ = false;
};

}  // namespace

bool evaluate_condition(std::span<const Token> tokens, SourceLocation directive, DiagnosticSink& diags,
                        Budget& budget) {
  return Evaluator(tokens, directive, diags, budget).run();
}

}  // namespace fx::pp
