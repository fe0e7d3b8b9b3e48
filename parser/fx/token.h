// Tokens of the effect language (HLSL tokens plus the preprocessor's), as the lexer and
// preprocessor produce them and the parser consumes them.
#pragma once
#include <cassert>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include "fx/source_location.h"

namespace fx {

class SourceManager;

enum class TokenKind : uint8_t {
  eof,
  identifier,  // also keywords: the parser decides, since effect keywords are contextual
  integer,     // 12, 0x1F, 10u, 3l (spelling kept; see parse_number)
  floating,    // 1.0f, 1.h, .5, 1e-3; also pp-numbers such as ".1.1" in shader assembly
  string,      // "text" with its quotes
  character,   // 'c' with its quotes
  directive,   // a kept directive line for the shader compiler: #pragma, #version, #extension
  // punctuators
  l_paren,
  r_paren,
  l_square,
  r_square,
  l_brace,
  r_brace,
  semi,
  comma,
  period,
  colon,
  coloncolon,
  question,
  tilde,
  exclaim,
  plus,
  minus,
  star,
  slash,
  percent,
  caret,
  amp,
  pipe,
  equal,
  less,
  greater,
  plusplus,
  minusminus,
  arrow,
  plusequal,
  minusequal,
  starequal,
  slashequal,
  percentequal,
  ampequal,
  pipeequal,
  caretequal,
  lessless,
  greatergreater,
  lesslessequal,
  greatergreaterequal,
  equalequal,
  exclaimequal,
  lessequal,
  greaterequal,
  ampamp,
  pipepipe,
  hash,
  hashhash,
  unknown,  // a character that starts no token; the lexer has reported it
};

// Spelling of a punctuator kind, or a description for the other kinds ("identifier").
const char* spelling(TokenKind kind);

enum TokenFlags : uint8_t {
  kAtLineStart = 1 << 0,   // first token on its line (directives start here)
  kLeadingSpace = 1 << 1,  // whitespace or a comment before it (for # stringizing)
  kNoExpand = 1 << 2,      // an identifier naming a macro that must not expand again
  kFromMacro = 1 << 3,     // produced by a macro expansion
};

// 16 bytes, since a 10 MB effect makes over 3 million tokens and the parser walks them
// all: the spelling is a pointer and a 16-bit length. A spelling too long for that (a huge
// string literal or #pragma line, a pathological identifier) has its view kept by the
// SourceManager, and the token points at that view instead (set_text).
struct Token {
  TokenKind kind = TokenKind::eof;
  uint8_t flags = 0;

 private:
  uint16_t text_size_ = 0;  // kLongText: text_ points at a view the SourceManager keeps

 public:
  SourceLocation loc;  // where the token starts (may be an expansion location)

  // Spellings this long or longer are kept by the SourceManager.
  static constexpr size_t kLongText = UINT16_MAX;

  // The spelling, owned by the SourceManager.
  std::string_view text() const {
    if (text_size_ != kLongText) [[likely]]
      return {text_.data, text_size_};
    return *text_.long_view;
  }
  // Sets the spelling to text the SourceManager owns (a buffer's or scratch space's).
  void set_text(std::string_view text, SourceManager& sm) {
    if (text.size() < kLongText) [[likely]]
      set_short_text(text);
    else set_long_text(text, sm);
  }
  // The same for a spelling shorter than kLongText, such as a punctuator's or a part of
  // one, which needs no SourceManager.
  void set_short_text(std::string_view text) {
    assert(text.size() < kLongText && "a long spelling needs set_text and the SourceManager");
    text_.data = text.data();
    text_size_ = static_cast<uint16_t>(text.size());
  }

  bool is(TokenKind k) const { return kind == k; }
  bool is_identifier(std::string_view name) const { return kind == TokenKind::identifier && text() == name; }
  bool at_line_start() const { return flags & kAtLineStart; }
  bool leading_space() const { return flags & kLeadingSpace; }
  SourceRange range() const { return {loc, loc.offset(static_cast<uint32_t>(text().size()))}; }

 private:
  [[gnu::noinline]] void set_long_text(std::string_view text, SourceManager& sm);

  union {
    const char* data = nullptr;         // text_size_ characters
    const std::string_view* long_view;  // when text_size_ == kLongText
  } text_;
};
static_assert(sizeof(Token) == 16 && std::is_trivially_copyable_v<Token>);

}  // namespace fx
