// Tokens of the effect language (HLSL tokens plus the preprocessor's), as the lexer and
// preprocessor produce them and the parser consumes them.
#pragma once
#include <cstdint>
#include <string_view>

#include "fx/source_location.h"

namespace fx {

enum class TokenKind : uint8_t {
  eof,
  identifier,  // also keywords: the parser decides, since effect keywords are contextual
  integer,     // 12, 0x1F, 10u, 3l (spelling kept; see parse_number)
  floating,    // 1.0f, 1.h, .5, 1e-3; also pp-numbers such as ".1.1" in shader assembly
  string,      // "text" with its quotes
  character,   // 'c' with its quotes
  directive,   // a kept directive line for the shader compiler: #pragma, #version, #extension
  // punctuators
  l_paren, r_paren, l_square, r_square, l_brace, r_brace,
  semi, comma, period, colon, coloncolon, question, tilde, exclaim,
  plus, minus, star, slash, percent, caret, amp, pipe, equal, less, greater,
  plusplus, minusminus, arrow,
  plusequal, minusequal, starequal, slashequal, percentequal,
  ampequal, pipeequal, caretequal, lessless, greatergreater, lesslessequal, greatergreaterequal,
  equalequal, exclaimequal, lessequal, greaterequal, ampamp, pipepipe,
  hash, hashhash,
  unknown,  // a character that starts no token; the lexer has reported it
};

// Spelling of a punctuator kind, or a description for the other kinds ("identifier").
const char* spelling(TokenKind kind);

enum TokenFlags : uint8_t {
  kAtLineStart = 1 << 0,    // first token on its line (directives start here)
  kLeadingSpace = 1 << 1,   // whitespace or a comment before it (for # stringizing)
  kNoExpand = 1 << 2,       // an identifier naming a macro that must not expand again
  kFromMacro = 1 << 3,      // produced by a macro expansion
};

struct Token {
  TokenKind kind = TokenKind::eof;
  uint8_t flags = 0;
  SourceLocation loc;     // where the token starts (may be an expansion location)
  std::string_view text;  // spelling, owned by the SourceManager

  bool is(TokenKind k) const { return kind == k; }
  bool is_identifier(std::string_view name) const {
    return kind == TokenKind::identifier && text == name;
  }
  bool at_line_start() const { return flags & kAtLineStart; }
  bool leading_space() const { return flags & kLeadingSpace; }
  SourceRange range() const { return {loc, loc.offset(static_cast<uint32_t>(text.size()))}; }
};

}  // namespace fx
