#include "fx/lexer.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <string>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace fx {
namespace {

// Character classes by table: the lexer asks "identifier character?" for nearly every byte.
enum : uint8_t { kIdentStart = 1, kDigit = 2, kSpace = 4 };
constexpr std::array<uint8_t, 256> kClass = [] {
  std::array<uint8_t, 256> t{};
  for (int c = 'a'; c <= 'z'; ++c) t[c] = kIdentStart;
  for (int c = 'A'; c <= 'Z'; ++c) t[c] = kIdentStart;
  t['_'] = kIdentStart;
  for (int c = '0'; c <= '9'; ++c) t[c] = kDigit;
  for (char c : {' ', '\t', '\r', '\f', '\v'}) t[static_cast<unsigned char>(c)] = kSpace;
  return t;
}();
uint8_t char_class(char c) { return kClass[static_cast<unsigned char>(c)]; }
bool is_ident_start(char c) { return char_class(c) & kIdentStart; }
bool is_digit(char c) { return char_class(c) & kDigit; }
bool is_ident_char(char c) { return char_class(c) & (kIdentStart | kDigit); }

// The end of the identifier characters that start at `p`; `end` is the end of the text,
// which a '\0' follows. Names such as `WorldViewProj123` are most of an effect's bytes, so
// 16 characters are classified at a time while 16 remain.
inline const char* identifier_end(const char* p, const char* end) {
#if defined(__SSE2__)
  while (end - p >= 16) {
    const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    // Unsigned range tests as signed compares: x - lo + 0x80 < n + 0x80 - 256.
    auto in_range = [](__m128i x, char lo, int n) {
      return _mm_cmplt_epi8(_mm_add_epi8(x, _mm_set1_epi8(static_cast<char>(0x80 - lo))),
                            _mm_set1_epi8(static_cast<char>(0x80 + n)));
    };
    const __m128i letter = in_range(_mm_or_si128(c, _mm_set1_epi8(0x20)), 'a', 26);
    const __m128i digit = in_range(c, '0', 10);
    const __m128i underscore = _mm_cmpeq_epi8(c, _mm_set1_epi8('_'));
    const unsigned ident =
        static_cast<unsigned>(_mm_movemask_epi8(_mm_or_si128(_mm_or_si128(letter, digit), underscore)));
    if (ident != 0xFFFF) return p + __builtin_ctz(~ident);
    p += 16;
  }
#endif
  while (is_ident_char(*p)) ++p;
  return p;
}

// The pp-number rule, one character at a time, shared by lex_number and next_batch's fast
// path: digits, letters, '.', and a sign after an exponent letter continue a number; '.',
// an exponent or a float suffix makes it floating (hex digits 'e' and 'f' do not). `p` is
// inside a number (not at its first character) when it is a sign, so p[-1] exists then.
enum class NumberChar : uint8_t { end, part, floating };
inline bool starts_hex(const char* p) { return p[0] == '0' && (p[1] == 'x' || p[1] == 'X'); }
inline NumberChar number_char(const char* p, bool hex) {
  const char c = *p;
  if (c == '.') return NumberChar::floating;
  if (c == '+' || c == '-') return !hex && (p[-1] == 'e' || p[-1] == 'E') ? NumberChar::floating : NumberChar::end;
  if (!is_ident_char(c)) return NumberChar::end;
  if (!hex && (c == 'e' || c == 'E' || c == 'f' || c == 'F' || c == 'h' || c == 'H')) return NumberChar::floating;
  return NumberChar::part;
}

// The flags a blank character gives the next token (0: not a blank), so that skipping
// blanks is one load and one test per character.
constexpr std::array<uint8_t, 256> kBlankFlags = [] {
  std::array<uint8_t, 256> t{};
  for (char c : {' ', '\t', '\r', '\f', '\v'}) t[static_cast<unsigned char>(c)] = kLeadingSpace;
  t['\n'] = kAtLineStart | kLeadingSpace;
  return t;
}();

// How next_batch starts a token on its first character. Everything `other` (quotes, a
// backslash, '\0' at the end, characters that start no token) takes the general path.
enum class Start : uint8_t { other, identifier, digit, period, punct };
constexpr std::array<Start, 256> kStart = [] {
  std::array<Start, 256> t{};
  for (int c = 0; c < 256; ++c) {
    if (kClass[c] & kIdentStart) t[c] = Start::identifier;
    else if (kClass[c] & kDigit) t[c] = Start::digit;
  }
  t['.'] = Start::period;
  for (char c : std::string_view("()[]{};,?~:!=*/%^#+-&|<>")) t[static_cast<unsigned char>(c)] = Start::punct;
  return t;
}();

// The punctuator at `p` (a character kStart marks punct), longest match; advances `p`.
inline TokenKind punctuator(const char*& p) {
  const char c = *p++;
  auto take = [&](char next) {
    if (*p == next) return ++p, true;
    return false;
  };
  switch (c) {
    case '(': return TokenKind::l_paren;
    case ')': return TokenKind::r_paren;
    case '[': return TokenKind::l_square;
    case ']': return TokenKind::r_square;
    case '{': return TokenKind::l_brace;
    case '}': return TokenKind::r_brace;
    case ';': return TokenKind::semi;
    case ',': return TokenKind::comma;
    case '.': return TokenKind::period;
    case '?': return TokenKind::question;
    case '~': return TokenKind::tilde;
    case ':': return take(':') ? TokenKind::coloncolon : TokenKind::colon;
    case '!': return take('=') ? TokenKind::exclaimequal : TokenKind::exclaim;
    case '=': return take('=') ? TokenKind::equalequal : TokenKind::equal;
    case '*': return take('=') ? TokenKind::starequal : TokenKind::star;
    case '/': return take('=') ? TokenKind::slashequal : TokenKind::slash;
    case '%': return take('=') ? TokenKind::percentequal : TokenKind::percent;
    case '^': return take('=') ? TokenKind::caretequal : TokenKind::caret;
    case '#': return take('#') ? TokenKind::hashhash : TokenKind::hash;
    case '+': return take('+') ? TokenKind::plusplus : take('=') ? TokenKind::plusequal : TokenKind::plus;
    case '-':
      return take('-')   ? TokenKind::minusminus
             : take('=') ? TokenKind::minusequal
             : take('>') ? TokenKind::arrow
                         : TokenKind::minus;
    case '&': return take('&') ? TokenKind::ampamp : take('=') ? TokenKind::ampequal : TokenKind::amp;
    case '|': return take('|') ? TokenKind::pipepipe : take('=') ? TokenKind::pipeequal : TokenKind::pipe;
    case '<':
      if (take('<')) return take('=') ? TokenKind::lesslessequal : TokenKind::lessless;
      return take('=') ? TokenKind::lessequal : TokenKind::less;
    case '>':
      if (take('>')) return take('=') ? TokenKind::greatergreaterequal : TokenKind::greatergreater;
      return take('=') ? TokenKind::greaterequal : TokenKind::greater;
    default: return TokenKind::unknown;
  }
}

}  // namespace

const char* spelling(TokenKind k) {
  switch (k) {
    case TokenKind::eof: return "end of file";
    case TokenKind::identifier: return "identifier";
    case TokenKind::integer: return "integer";
    case TokenKind::floating: return "number";
    case TokenKind::string: return "string";
    case TokenKind::character: return "character";
    case TokenKind::directive: return "directive";
    case TokenKind::l_paren: return "(";
    case TokenKind::r_paren: return ")";
    case TokenKind::l_square: return "[";
    case TokenKind::r_square: return "]";
    case TokenKind::l_brace: return "{";
    case TokenKind::r_brace: return "}";
    case TokenKind::semi: return ";";
    case TokenKind::comma: return ",";
    case TokenKind::period: return ".";
    case TokenKind::colon: return ":";
    case TokenKind::coloncolon: return "::";
    case TokenKind::question: return "?";
    case TokenKind::tilde: return "~";
    case TokenKind::exclaim: return "!";
    case TokenKind::plus: return "+";
    case TokenKind::minus: return "-";
    case TokenKind::star: return "*";
    case TokenKind::slash: return "/";
    case TokenKind::percent: return "%";
    case TokenKind::caret: return "^";
    case TokenKind::amp: return "&";
    case TokenKind::pipe: return "|";
    case TokenKind::equal: return "=";
    case TokenKind::less: return "<";
    case TokenKind::greater: return ">";
    case TokenKind::plusplus: return "++";
    case TokenKind::minusminus: return "--";
    case TokenKind::arrow: return "->";
    case TokenKind::plusequal: return "+=";
    case TokenKind::minusequal: return "-=";
    case TokenKind::starequal: return "*=";
    case TokenKind::slashequal: return "/=";
    case TokenKind::percentequal: return "%=";
    case TokenKind::ampequal: return "&=";
    case TokenKind::pipeequal: return "|=";
    case TokenKind::caretequal: return "^=";
    case TokenKind::lessless: return "<<";
    case TokenKind::greatergreater: return ">>";
    case TokenKind::lesslessequal: return "<<=";
    case TokenKind::greatergreaterequal: return ">>=";
    case TokenKind::equalequal: return "==";
    case TokenKind::exclaimequal: return "!=";
    case TokenKind::lessequal: return "<=";
    case TokenKind::greaterequal: return ">=";
    case TokenKind::ampamp: return "&&";
    case TokenKind::pipepipe: return "||";
    case TokenKind::hash: return "#";
    case TokenKind::hashhash: return "##";
    case TokenKind::unknown: return "unknown character";
  }
  return "?";
}

Lexer::Lexer(SourceManager& sm, BufferId buffer, DiagnosticSink& diags)
    : sm_(sm), diags_(diags), buffer_(buffer), text_(sm.buffer_text(buffer)), base_(sm.location(buffer, 0).raw) {
  if (!text_.data()) text_ = "";  // an invalid buffer: still a '\0' after the text
  // Windows editors save effects (and their .fxh includes) with a UTF-8 byte-order mark,
  // which fxc skips. Its bytes stay in the buffer, so line 1 columns still count them.
  if (text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;
}

// Removes backslash-newline pairs at the current position (translation phase 2).
void Lexer::skip_splices() {
  while (peek() == '\\') {
    if (peek(1) == '\n') pos_ += 2;
    else if (peek(1) == '\r' && peek(2) == '\n') pos_ += 3;
    else break;
    spliced_ = true;
  }
}

// Inline into next_token(): most tokens follow one blank or none, and a call per token
// cost more than the skipping. Comments and splices go out of line.
inline void Lexer::skip_whitespace_and_comments() {
  const size_t size = text_.size();
  for (;;) {
    if (pos_ >= size) return;
    char c = text_[pos_];
    if (char_class(c) & kSpace) {
      ++pos_;
      pending_flags_ |= kLeadingSpace;
    } else if (c == '\n') {
      ++pos_;
      pending_flags_ |= kAtLineStart | kLeadingSpace;
    } else if (c != '\\' && c != '/') {
      return;
    } else if (!skip_comment_or_splice()) {
      return;
    }
  }
}

bool Lexer::skip_comment_or_splice() {
  const size_t size = text_.size();
  if (text_[pos_] == '\\') {
    size_t before = pos_;
    skip_splices();
    return pos_ != before;  // a stray backslash: a token of its own
  }
  if (peek(1) == '/') {
    // A line comment ends at a newline not preceded by a continuation backslash
    // (`\` + LF or `\` + CR LF).
    for (;;) {
      const void* nl = std::memchr(text_.data() + pos_, '\n', size - pos_);
      if (!nl) {
        pos_ = size;
        break;
      }
      size_t at_nl = static_cast<size_t>(static_cast<const char*>(nl) - text_.data());
      size_t prev = at_nl - 1;  // the comment's "//" precedes, so at_nl >= 2
      if (text_[prev] == '\r') --prev;
      if (text_[prev] != '\\') {
        pos_ = at_nl;
        break;
      }
      pos_ = at_nl + 1;
    }
    pending_flags_ |= kLeadingSpace;
    return true;
  }
  if (peek(1) == '*') {
    size_t begin = pos_;
    size_t end = text_.find("*/", pos_ + 2);
    if (end == std::string_view::npos) {
      diags_.error("unterminated-comment", {at(begin), {}}, "unterminated /* comment");
      pos_ = size;
      return false;
    }
    // A comment spanning lines still leaves the next token on a new line for directives
    // only if a real newline follows; C treats the comment as one space.
    pos_ = end + 2;
    pending_flags_ |= kLeadingSpace;
    return true;
  }
  return false;  // a '/' operator
}

bool Lexer::at_line_end() {
  skip_whitespace_and_comments();
  return pos_ >= text_.size() || (pending_flags_ & kAtLineStart);
}

Token Lexer::make(TokenKind kind, size_t begin) {
  Token t;
  t.kind = kind;
  t.flags = pending_flags_;
  pending_flags_ = 0;
  t.loc = at(begin);
  std::string_view text(text_.data() + begin, pos_ - begin);
  if (spliced_ && kind != TokenKind::string && kind != TokenKind::character) [[unlikely]]
    text = clean_spelling(text, t.loc);
  t.set_text(text, sm_);
  return t;
}

// Out of line so that make(), which runs for every token, needs no stack frame.
[[gnu::noinline]] std::string_view Lexer::clean_spelling(std::string_view raw, SourceLocation loc) {
  // The token was split by continuations: give it its clean spelling.
  std::string clean;
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '\\' && i + 1 < raw.size() && (raw[i + 1] == '\n' || raw[i + 1] == '\r')) {
      i += raw[i + 1] == '\r' ? 2 : 1;
      continue;
    }
    clean.push_back(raw[i]);
  }
  return sm_.text_at(sm_.add_scratch(clean, loc)).substr(0, clean.size());
}

Token Lexer::next() { return next_token(); }

// Every token next() returns, and the ones next_batch() leaves to the general path.
inline Token Lexer::next_token() {
  skip_whitespace_and_comments();
  size_t begin = pos_;
  spliced_ = false;
  if (pos_ >= text_.size()) {
    Token t = make(TokenKind::eof, begin);
    pending_flags_ = kAtLineStart;
    return t;
  }
  char c = text_[pos_];
  if (is_ident_start(c)) {
    const size_t size = text_.size();
    for (;;) {
      ++pos_;
      while (pos_ < size && is_ident_char(text_[pos_])) ++pos_;
      if (pos_ < size && text_[pos_] == '\\') skip_splices();
      if (!is_ident_char(peek())) break;
    }
    return make(TokenKind::identifier, begin);
  }
  if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return lex_number(begin);
  if (c == '"' || c == '\'') return lex_quoted(begin, c);
  return lex_punct(begin);
}

size_t Lexer::next_batch(Token* out, size_t max, const NameFilter* stop_after) {
  // Counts, not the stored list: they grow even past an error limit.
  auto reported = [&] { return diags_.error_count() + diags_.warning_count(); };
  const size_t before = reported();
  // The common tokens are lexed here with the position and flags in registers (a member
  // would be reloaded after every byte stored into a Token). The text is a std::string's,
  // so a '\0' follows it: the loops stop there without bounds checks. Anything else
  // (comments, continuations, strings, unknown characters, eof, and spellings too long
  // for a Token to hold their length) goes through next_token() from the token's first
  // character, which is always exact.
  static const NameFilter kNoStops;
  const NameFilter& stops = stop_after ? *stop_after : kNoStops;
  const char* const text = text_.data();
  const char* const end = text + text_.size();
  const char* p = text + pos_;
  uint8_t flags = pending_flags_;
  size_t n = 0;
  while (n < max) {
    for (;;) {
      while (uint8_t blank = kBlankFlags[static_cast<unsigned char>(*p)]) {
        flags |= blank;
        ++p;
      }
      if (*p != '\\' && (*p != '/' || (p[1] != '/' && p[1] != '*'))) break;
      pos_ = static_cast<size_t>(p - text);
      pending_flags_ = flags;
      bool skipped = skip_comment_or_splice();
      p = text + pos_;
      flags = pending_flags_;
      if (!skipped) break;
    }
    const char* begin = p;
    auto short_spelling = [&] { return static_cast<size_t>(p - begin) < Token::kLongText; };
    TokenKind kind = TokenKind::unknown;
    bool last = false;  // the batch ends after this token
    switch (kStart[static_cast<unsigned char>(*p)]) {
      case Start::identifier:
        p = identifier_end(p + 1, end);
        if (*p != '\\' && short_spelling()) {
          kind = TokenKind::identifier;
          last = stops.may_contain(std::string_view(begin, static_cast<size_t>(p - begin)));
        }
        break;
      case Start::period:
        if (!is_digit(p[1])) {
          kind = punctuator(p);
          break;
        }
        [[fallthrough]];
      case Start::digit: {
        const bool hex = starts_hex(p);
        bool floating = false;
        for (NumberChar c; (c = number_char(p, hex)) != NumberChar::end; ++p)
          floating = floating || c == NumberChar::floating;
        if (*p != '\\' && short_spelling()) kind = floating ? TokenKind::floating : TokenKind::integer;
        break;
      }
      case Start::punct:
        kind = punctuator(p);
        last = kind == TokenKind::hash && (flags & kAtLineStart);
        break;
      case Start::other: break;
    }
    if (kind == TokenKind::unknown) [[unlikely]] {
      pos_ = static_cast<size_t>(begin - text);
      pending_flags_ = flags;
      const Token& t = out[n++] = next_token();
      p = text + pos_;
      flags = pending_flags_;
      if ((t.kind == TokenKind::hash && t.at_line_start()) || t.kind == TokenKind::eof || reported() != before ||
          (t.kind == TokenKind::identifier && stops.may_contain(t.text())))
        break;
      continue;
    }
    Token& t = out[n++];
    t.kind = kind;
    t.flags = flags;
    t.loc = SourceLocation{base_ + static_cast<uint32_t>(begin - text)};
    t.set_short_text(std::string_view(begin, static_cast<size_t>(p - begin)));
    flags = 0;
    if (last) break;
  }
  pos_ = static_cast<size_t>(p - text);
  pending_flags_ = flags;
  return n;
}

// A pp-number: digits, letters, '.', and signs after an exponent letter. It is classified
// here and validated by parse_number when a value is needed.
Token Lexer::lex_number(size_t begin) {
  const bool hex = starts_hex(text_.data() + pos_);
  bool floating = false;
  // text_ is a std::string's: a '\0' (NumberChar::end) follows it.
  for (NumberChar c; (c = number_char(text_.data() + pos_, hex)) != NumberChar::end;) {
    floating = floating || c == NumberChar::floating;
    ++pos_;
    skip_splices();
  }
  return make(floating ? TokenKind::floating : TokenKind::integer, begin);
}

Token Lexer::lex_quoted(size_t begin, char quote) {
  ++pos_;
  while (pos_ < text_.size() && text_[pos_] != quote && text_[pos_] != '\n') {
    if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) ++pos_;
    ++pos_;
  }
  if (pos_ >= text_.size() || text_[pos_] != quote) {
    diags_.error("unterminated-string", {at(begin), {}},
                 quote == '"' ? "missing terminating '\"' character" : "missing terminating ' character");
  } else {
    ++pos_;
  }
  return make(quote == '"' ? TokenKind::string : TokenKind::character, begin);
}

Token Lexer::lex_punct(size_t begin) {
  const char* p = text_.data() + pos_;
  TokenKind k = punctuator(p);
  pos_ = static_cast<size_t>(p - text_.data());
  if (k == TokenKind::unknown) {
    // Swallow a whole UTF-8 sequence so one stray character gives one diagnostic.
    while (pos_ < text_.size() && (static_cast<unsigned char>(text_[pos_]) & 0xC0) == 0x80) ++pos_;
    Token t = make(TokenKind::unknown, begin);
    diags_.error("unknown-character", t.range(), "unexpected character in source");
    return t;
  }
  return make(k, begin);
}

std::optional<Token> Lexer::header_name() {
  skip_whitespace_and_comments();
  spliced_ = false;
  if (pending_flags_ & kAtLineStart || peek() != '<') return std::nullopt;
  size_t begin = pos_;
  size_t end = text_.find_first_of(">\n", pos_);
  if (end == std::string_view::npos || text_[end] != '>') return std::nullopt;
  pos_ = end + 1;
  return make(TokenKind::string, begin);
}

std::string_view Lexer::rest_of_line() {
  size_t begin = pos_;
  while (pos_ < text_.size() && text_[pos_] != '\n') {
    if (text_[pos_] == '\\' && (peek(1) == '\n' || (peek(1) == '\r' && peek(2) == '\n'))) {
      skip_splices();
      continue;
    }
    ++pos_;
  }
  pending_flags_ |= kAtLineStart;
  return text_.substr(begin, pos_ - begin);
}

std::optional<NumberValue> parse_number(std::string_view s, std::string* error) {
  auto fail = [&](const char* why) -> std::optional<NumberValue> {
    if (error) *error = why;
    return std::nullopt;
  };
  if (s.empty()) return fail("empty number");
  bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
  bool floating = !hex && s.find_first_of(".eEfFhH") != std::string_view::npos;
  if (floating) {
    std::string_view body = s;
    if (body.back() == 'f' || body.back() == 'F' || body.back() == 'h' || body.back() == 'H' || body.back() == 'l' ||
        body.back() == 'L')
      body.remove_suffix(1);
    std::string copy(body);
    if (copy.empty() || copy.back() == '.') copy.push_back('0');
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(copy.c_str(), &end);
    if (end != copy.c_str() + copy.size()) return fail("invalid floating-point literal");
    if (errno == ERANGE && v != 0.0) return fail("floating-point literal out of range");
    return NumberValue{v};
  }
  std::string_view body = s;
  while (!body.empty() && (body.back() == 'u' || body.back() == 'U' || body.back() == 'l' || body.back() == 'L'))
    body.remove_suffix(1);
  int base = 10;
  if (hex) body.remove_prefix(2), base = 16;
  else if (body.size() > 1 && body[0] == '0') base = 8;
  uint64_t v = 0;
  auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), v, base);
  if (body.empty() || ptr != body.data() + body.size()) return fail("invalid integer literal");
  if (ec == std::errc::result_out_of_range) return fail("integer literal out of range");
  return NumberValue{static_cast<int64_t>(v)};
}

std::string unquote(std::string_view s) {
  std::string out;
  append_unquoted(out, s);
  return out;
}

void append_unquoted(std::string& out, std::string_view s) {
  if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'' || s.front() == '<')) s = s.substr(1, s.size() - 2);
  // Most literals have no escape: one append instead of a push_back per character.
  size_t plain = s.find('\\');
  out.append(s.substr(0, plain));
  if (plain == std::string_view::npos) return;
  s = s.substr(plain);
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '\\' || i + 1 == s.size()) {
      out.push_back(s[i]);
      continue;
    }
    switch (char c = s[++i]) {
      case 'n': out.push_back('\n'); break;
      case 't': out.push_back('\t'); break;
      case 'r': out.push_back('\r'); break;
      case '0': out.push_back('\0'); break;
      default: out.push_back(c); break;
    }
  }
}

}  // namespace fx
