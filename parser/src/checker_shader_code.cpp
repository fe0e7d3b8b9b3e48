// The shader code glslang gets, checked before it gets any: nesting depth, operators per
// statement, over-long names and numbers, and preprocessor tokens left in the code. glslang
// recurses once per level of these and has no limit of its own (20,000 open parentheses
// overflow its stack), and a `#` the preprocessor left in the code can start a directive of
// glslang's own preprocessor (a `#define` with `##` that glslang expands again). fxc takes no
// such code either: its own parser stops far earlier. Limits and ids: docs/diagnostics.md.
#include <string>

#include "checker_internal.h"

namespace fx::check {
namespace {

// Brackets, statements without braces (`if (a) if (b) ...`) and prefix operators nested in
// one declaration. Effects nest a few levels; the effect parser's own expressions stop at
// the same depth (ParseOptions::max_nesting).
constexpr size_t kMaxShaderNesting = 256;
// Binary, assignment and conditional operators in one statement: glslang's tree is as deep
// as its longest operator chain, and it walks trees recursively (x*x*...*x with 20,000
// factors overflows its stack). Hand-written and generated effects stay in the hundreds.
constexpr size_t kMaxStatementOperators = 4096;
// glslang's own token limit (MaxTokenLength): longer names and numbers it cuts short.
constexpr size_t kMaxTokenLength = 1024;

// Whether an operand ends at `t` (so a following `-` is binary), given whether one ended just
// before it: a name that is not a keyword opening an expression, a literal, a closing
// bracket, or a postfix `++`/`--` after an operand.
bool ends_operand(const Token& t, bool operand_before) {
  switch (t.kind) {
    case TokenKind::identifier: {
      const std::string_view w = t.text();
      return w != "return" && w != "case" && w != "else" && w != "do";
    }
    case TokenKind::integer:
    case TokenKind::floating:
    case TokenKind::string:
    case TokenKind::character:
    case TokenKind::r_paren:
    case TokenKind::r_square: return true;
    case TokenKind::plusplus:
    case TokenKind::minusminus: return operand_before;
    default: return false;
  }
}

bool is_prefix_operator(TokenKind k) {
  switch (k) {
    case TokenKind::minus:
    case TokenKind::plus:
    case TokenKind::exclaim:
    case TokenKind::tilde:
    case TokenKind::plusplus:
    case TokenKind::minusminus: return true;
    default: return false;
  }
}

bool is_binary_operator(TokenKind k) {
  switch (k) {
    case TokenKind::plus:
    case TokenKind::minus:
    case TokenKind::star:
    case TokenKind::slash:
    case TokenKind::percent:
    case TokenKind::caret:
    case TokenKind::amp:
    case TokenKind::pipe:
    case TokenKind::equal:
    case TokenKind::less:
    case TokenKind::greater:
    case TokenKind::question:
    case TokenKind::plusequal:
    case TokenKind::minusequal:
    case TokenKind::starequal:
    case TokenKind::slashequal:
    case TokenKind::percentequal:
    case TokenKind::ampequal:
    case TokenKind::pipeequal:
    case TokenKind::caretequal:
    case TokenKind::lessless:
    case TokenKind::greatergreater:
    case TokenKind::lesslessequal:
    case TokenKind::greatergreaterequal:
    case TokenKind::equalequal:
    case TokenKind::exclaimequal:
    case TokenKind::lessequal:
    case TokenKind::greaterequal:
    case TokenKind::ampamp:
    case TokenKind::pipepipe: return true;
    default: return false;
  }
}

// A statement that nests the next one without braces. An `else if` chain is not counted:
// glslang reads it in a loop, and generated effects chain hundreds.
bool is_nesting_statement(const Token& t, const Token* previous) {
  if (!t.is(TokenKind::identifier)) return false;
  const std::string_view w = t.text();
  if (w == "if") return !previous || !previous->is_identifier("else");
  return w == "for" || w == "while" || w == "do" || w == "switch";
}

}  // namespace

void Checker::check_shader_code(ast::TokenSpan span, ShaderCode code) {
  const std::vector<Token>& toks = effect_.tokens;
  size_t brackets = 0, statements = 0, prefixes = 0, operators = 0;
  bool operand_before = false;
  for (uint32_t i = span.first; i < span.last && i < toks.size(); ++i) {
    const Token& t = toks[i];
    switch (t.kind) {
      case TokenKind::l_paren:
      case TokenKind::l_square: ++brackets; break;
      case TokenKind::l_brace:
        ++brackets;
        statements = operators = 0;
        break;
      case TokenKind::r_paren:
      case TokenKind::r_square:
        if (brackets) --brackets;
        break;
      case TokenKind::r_brace:
        if (brackets) --brackets;
        statements = operators = 0;
        break;
      case TokenKind::semi:
        operators = 0;
        // `if (a) x; else ...`: the if statement goes on.
        if (i + 1 >= span.last || i + 1 >= toks.size() || !toks[i + 1].is_identifier("else")) statements = 0;
        break;
      case TokenKind::hash:
      case TokenKind::hashhash: {
        // `GLSLShader X { #version 450`: the preprocessor leaves a directive that does not
        // start its line as tokens, and the GLSL block takes it as its version line.
        const bool block_version = code == ShaderCode::glsl && i == span.first && t.is(TokenKind::hash) &&
                                   i + 1 < span.last && toks[i + 1].is_identifier("version");
        if (block_version) break;
        diags_.error("shader-preprocessor-token", t.range(),
                     t.is(TokenKind::hash)
                         ? "'#' in shader code: a preprocessing directive must start its line, and a macro's "
                           "replacement cannot make one"
                         : "'##' in shader code: tokens are pasted only in a macro's replacement list");
        return;
      }
      case TokenKind::directive:
        if (code == ShaderCode::hlsl && !t.text().starts_with("#pragma")) {
          const std::string_view text = t.text();
          std::string message(1, '\'');
          message.append(text.substr(0, text.find(' ')));
          message +=
              "' in HLSL code: only #pragma is kept for the shader compiler (#version and #extension "
              "belong to GLSL blocks)";
          diags_.error("shader-preprocessor-token", t.range(), std::move(message));
          return;
        }
        break;
      case TokenKind::identifier:
      case TokenKind::integer:
      case TokenKind::floating:
        if (t.text().size() > kMaxTokenLength) {
          diags_.error("shader-token-too-long", {t.loc, t.loc.offset(1)},
                       std::string(t.is(TokenKind::identifier) ? "name" : "number") + " of " +
                           std::to_string(t.text().size()) + " characters in shader code (at most " +
                           std::to_string(kMaxTokenLength) + ")");
          return;
        }
        if (is_nesting_statement(t, i > span.first ? &toks[i - 1] : nullptr)) ++statements;
        break;
      default: break;
    }
    if (is_prefix_operator(t.kind) && !operand_before) ++prefixes;
    else if (t.kind != TokenKind::l_paren) prefixes = 0;
    const bool binary = is_binary_operator(t.kind) && operand_before;
    operand_before = ends_operand(t, operand_before);
    if (binary && ++operators > kMaxStatementOperators) {
      diags_.error("shader-statement-too-long", t.range(),
                   "more than " + std::to_string(kMaxStatementOperators) +
                       " operators in one statement of shader code; split it with temporaries");
      return;
    }
    if (brackets + statements + prefixes > kMaxShaderNesting) {
      diags_.error("shader-nesting-too-deep", t.range(),
                   "shader code nested more than " + std::to_string(kMaxShaderNesting) +
                       " levels deep (brackets, statements without braces and prefix operators)");
      return;
    }
  }
}

void Checker::check_shader_code() {
  for (const ast::Decl& d : effect_.decls) {
    switch (d.kind) {
      case ast::DeclKind::variable: check_shader_code(d.variable->tokens, ShaderCode::hlsl); break;
      case ast::DeclKind::type_alias: check_shader_code(d.type_alias->tokens, ShaderCode::hlsl); break;
      case ast::DeclKind::function: check_shader_code(d.function->tokens, ShaderCode::hlsl); break;
      case ast::DeclKind::constant_buffer: check_shader_code(d.constant_buffer->tokens, ShaderCode::hlsl); break;
      case ast::DeclKind::structure:
        check_shader_code(d.structure->tokens, ShaderCode::hlsl);
        // A method defined after its class is written inside it (its tokens are its own).
        for (const ast::Function& m : d.structure->methods)
          if (!m.owner.empty()) check_shader_code(m.tokens, ShaderCode::hlsl);
        break;
      case ast::DeclKind::glsl_block: check_shader_code(d.glsl_block->code, ShaderCode::glsl); break;
      default: break;
    }
  }
}

}  // namespace fx::check
