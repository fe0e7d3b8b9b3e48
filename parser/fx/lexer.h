// Splits one source buffer into tokens: HLSL/GLSL tokens, numbers with suffixes, strings,
// both comment styles and backslash-newline continuations.
#pragma once
#include <optional>
#include <string_view>
#include <variant>

#include "fx/diagnostic.h"
#include "fx/source_manager.h"
#include "fx/token.h"

namespace fx {

class Lexer {
 public:
  Lexer(SourceManager& sm, BufferId buffer, DiagnosticSink& diags);

  // The next token; TokenKind::eof at the end (repeatedly).
  Token next();
  // After `#include`: reads a `<path>` header name if one follows on this line.
  std::optional<Token> header_name();
  // Skips the rest of the current line (an unknown or skipped directive) and returns it.
  std::string_view rest_of_line();
  // True when the next token starts a new line (checked by directive parsing).
  bool at_line_end();
  // Location of the next character.
  SourceLocation here() const { return sm_.location(buffer_, static_cast<uint32_t>(pos_)); }
  BufferId buffer() const { return buffer_; }

 private:
  char peek(size_t ahead = 0) const;
  void skip_splices();
  void skip_whitespace_and_comments();
  Token make(TokenKind kind, size_t begin);
  Token lex_number(size_t begin);
  Token lex_quoted(size_t begin, char quote);
  Token lex_punct(size_t begin);

  SourceManager& sm_;
  DiagnosticSink& diags_;
  BufferId buffer_;
  std::string_view text_;
  size_t pos_ = 0;
  uint8_t pending_flags_ = kAtLineStart;
};

// Value of a numeric literal: integer or floating, with its suffix checked. Returns
// nullopt (and the reason) for malformed spellings.
struct NumberValue {
  std::variant<int64_t, double> value;
  bool is_float() const { return value.index() == 1; }
  double as_double() const { return is_float() ? std::get<double>(value) : double(std::get<int64_t>(value)); }
};
std::optional<NumberValue> parse_number(std::string_view spelling, std::string* error = nullptr);

// The contents of a string literal with escapes resolved.
std::string unquote(std::string_view spelling);

}  // namespace fx
