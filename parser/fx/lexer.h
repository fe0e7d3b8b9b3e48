// Splits one source buffer into tokens: HLSL/GLSL tokens, numbers with suffixes, strings,
// both comment styles and backslash-newline continuations.
#pragma once
#include <optional>
#include <string_view>
#include <variant>

#include "fx/diagnostic.h"
#include "fx/name_filter.h"
#include "fx/source_manager.h"
#include "fx/token.h"

namespace fx {

class Lexer {
 public:
  Lexer(SourceManager& sm, BufferId buffer, DiagnosticSink& diags);

  // The next token; TokenKind::eof at the end (repeatedly).
  Token next();
  // Writes up to `max` tokens to `out` and returns how many, stopping after a `#` that
  // starts a line (a directive reads the raw line after it), after eof, after the first
  // token that reported a diagnostic (so the caller can forward it with that token), and
  // after an identifier `stop_after` may contain (a possible macro name). Lexing does not
  // depend on macros, so reading ahead like this yields exactly the tokens next() would.
  size_t next_batch(Token* out, size_t max, const NameFilter* stop_after = nullptr);
  // After `#include`: reads a `<path>` header name if one follows on this line.
  std::optional<Token> header_name();
  // Skips the rest of the current line (an unknown or skipped directive) and returns it.
  std::string_view rest_of_line();
  // True when the next token starts a new line (checked by directive parsing).
  bool at_line_end();
  // Location of the next character.
  SourceLocation here() const { return at(pos_); }
  BufferId buffer() const { return buffer_; }

 private:
  char peek(size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
  // The location of a buffer offset; the buffer's base is cached because this runs once
  // per token (SourceManager::location is an out-of-line bounds-checked lookup).
  SourceLocation at(size_t offset) const {
    return base_ ? SourceLocation{base_ + static_cast<uint32_t>(offset)} : SourceLocation{};
  }
  void skip_splices();
  void skip_whitespace_and_comments();
  // At a backslash or '/': skips a splice or a comment and returns true, or returns false at
  // a token.
  bool skip_comment_or_splice();
  Token next_token();
  Token make(TokenKind kind, size_t begin);
  std::string_view clean_spelling(std::string_view raw, SourceLocation loc);
  Token lex_number(size_t begin);
  Token lex_quoted(size_t begin, char quote);
  Token lex_punct(size_t begin);

  SourceManager& sm_;
  DiagnosticSink& diags_;
  BufferId buffer_;
  std::string_view text_;
  uint32_t base_ = 0;  // raw location of offset 0 (0 for an invalid buffer)
  size_t pos_ = 0;
  uint8_t pending_flags_ = kAtLineStart;
  bool spliced_ = false;  // the current token contains a backslash-newline
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
// The same, appended to `out` (adjacent literals join without a temporary string).
void append_unquoted(std::string& out, std::string_view spelling);

}  // namespace fx
