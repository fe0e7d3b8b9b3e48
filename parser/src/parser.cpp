// Parser core: the token cursor, error reporting and recovery, and file-scope dispatch.
#include <array>
#include <bit>
#include <utility>

#include "fx/lexer.h"
#include "parse_internal.h"

namespace fx {

std::vector<Token> lex_all(SourceManager& sm, BufferId buffer, DiagnosticSink& diags) {
  Lexer lexer(sm, buffer, diags);
  std::vector<Token> tokens;
  // Effect source averages well over four bytes per token; one reservation avoids most
  // regrowth on large files.
  tokens.reserve(sm.buffer_text(buffer).size() / 4 + 1);
  for (;;) {
    Token t = lexer.next();
    if (t.is(TokenKind::unknown)) continue;  // reported by the lexer; as in the preprocessor
    tokens.push_back(t);
    if (t.is(TokenKind::eof)) return tokens;
  }
}

ast::Effect parse_effect(std::vector<Token> tokens, const SourceManager& sm, DiagnosticSink& diags,
                         const ParseOptions& options) {
  detail::Parser parser(std::move(tokens), sm, diags, options);
  return parser.run();
}

namespace detail {

std::string quote(std::string_view text) {
  std::string out = "'";
  out.append(text).push_back('\'');
  return out;
}

std::string describe(const Token& t) { return t.is(TokenKind::eof) ? std::string("end of file") : quote(t.text()); }

void append_spelling(std::string& out, const Token& t) {
  auto wordy = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '"' ||
           c == '.';
  };
  const std::string_view spelling = t.text();
  if (!out.empty() && !spelling.empty() && wordy(out.back()) && wordy(spelling.front()) && t.leading_space())
    out.push_back(' ');
  out.append(spelling);
}

Parser::Parser(std::vector<Token> tokens, const SourceManager& sm, DiagnosticSink& diags, const ParseOptions& options)
    : tokens_(std::move(tokens)), sm_(sm), diags_(diags), options_(options) {
  if (tokens_.empty() || !tokens_.back().is(TokenKind::eof)) {
    Token eof;
    if (!tokens_.empty()) eof.loc = tokens_.back().range().end;
    tokens_.push_back(eof);
  }
  if (options_.max_nesting == 0) options_.max_nesting = 1;
}

bool Parser::expect(TokenKind k, std::string_view context) {
  if (accept(k)) return true;
  std::string message = "expected '";
  message += spelling(k);
  message += "' ";
  message.append(context);
  message += ", found " + describe(tok());
  error_here("expected-token", std::move(message));
  return false;
}

bool Parser::missing_semi(std::string_view context) {
  if (pos_ > 0 && (tok().at_line_start() || at_eof())) {
    // The statement is complete and the next one starts on its own line: a forgotten ';'.
    // Say so once and keep parsing from here rather than skipping the next statement.
    SourceLocation end = end_of_previous();
    std::string message = "expected ';' ";
    message.append(context);
    if (Diagnostic* d = error("expected-token", {end, {}}, std::move(message))) d->fixits.push_back({{end, end}, ";"});
    failed_ = false;
    // A truncated file: whatever else is unclosed at the end is the same mistake.
    if (at_eof()) eof_error_ = true;
    return true;
  }
  return expect(TokenKind::semi, context);
}

void Parser::split_greater() {
  Token& t = tokens_[pos_];
  if (t.kind == TokenKind::greater || t.text().size() < 2) return;
  Token rest = t;
  rest.loc = t.loc.offset(1);
  rest.set_short_text(t.text().substr(1));
  rest.flags = 0;
  rest.kind = t.kind == TokenKind::greatergreater        ? TokenKind::greater
              : t.kind == TokenKind::greatergreaterequal ? TokenKind::greaterequal
                                                         : TokenKind::equal;
  t.kind = TokenKind::greater;
  t.set_short_text(t.text().substr(0, 1));
  // Only nested template arguments get here, so the O(n) insert stays rare. No span
  // handed out so far ends after pos_, so every stored index remains valid.
  tokens_.insert(tokens_.begin() + pos_ + 1, rest);
}

Diagnostic* Parser::error(std::string id, SourceRange range, std::string message) {
  bool echo = failed_ || eof_error_;
  failed_ = true;
  if (echo) return nullptr;
  return &diags_.error(std::move(id), range, std::move(message));
}

Diagnostic* Parser::error_here(std::string id, std::string message) {
  return error(std::move(id), tok().range(), std::move(message));
}

void Parser::unterminated(const Token& open, std::string_view what) {
  std::string message = "expected '}' to close ";
  message.append(what);
  if (Diagnostic* d = error("unterminated-block", tok().range(), std::move(message)))
    d->notes.push_back({open.loc, "to match this '{'"});
}

bool Parser::parse_braced_list(std::string_view where, const std::function<bool()>& item) {
  Token open = advance();  // {
  while (!accept(TokenKind::r_brace)) {
    if (!item()) return false;
    if (accept(TokenKind::comma) || at(TokenKind::r_brace)) continue;
    std::string message = "expected ',' or '}' ";
    message.append(where).append(", found ").append(describe(tok()));
    if (Diagnostic* d = error_here("expected-token", std::move(message)))
      d->notes.push_back({open.loc, "to match this '{'"});
    return false;
  }
  return true;
}

void Parser::recover(uint32_t depth, bool stop_at_greater) {
  for (;;) {
    switch (tok().kind) {
      case TokenKind::eof:
        if (failed_) eof_error_ = true;
        failed_ = false;
        return;
      case TokenKind::semi:
        if (depth_ <= depth) {
          advance();
          failed_ = false;
          return;
        }
        break;
      case TokenKind::r_brace:
        if (depth_ <= depth) {
          // At file scope a stray '}' is the mistake itself: step over it.
          if (depth_ == 0) advance();
          failed_ = false;
          return;
        }
        if (depth_ == depth + 1) {
          advance();
          accept(TokenKind::semi);
          failed_ = false;
          return;
        }
        break;
      case TokenKind::greater:
      case TokenKind::greatergreater:
        if (stop_at_greater && depth_ <= depth) {
          failed_ = false;
          return;
        }
        break;
      default: break;
    }
    advance();
  }
}

bool Parser::skip_braced(ast::TokenSpan& inner, std::string_view what) {
  if (!at(TokenKind::l_brace)) {
    std::string context = "to begin ";
    context.append(what);
    return expect(TokenKind::l_brace, context);
  }
  Token open = tok();
  uint32_t outer = depth_;
  advance();
  inner.first = pos_;
  while (!(at(TokenKind::r_brace) && depth_ == outer + 1)) {
    if (at_eof()) {
      unterminated(open, what);
      return false;
    }
    advance();
  }
  inner.last = pos_;
  advance();
  return true;
}

ast::Effect Parser::run() {
  ast::Effect effect;
  parse_profile_header();
  effect.decls.reserve(tokens_.size() / 16 + 1);
  while (!at_eof()) {
    uint32_t start = pos_;
    parse_top_level(effect.decls);
    if (failed_) recover(0);
    if (pos_ == start && !at_eof()) advance();  // every round makes progress
  }
  effect.profile_header = std::move(profile_header_);
  effect.tokens = std::move(tokens_);
  effect.declarations = std::move(declarations_);
  effect.expressions = std::move(expressions_);
  effect.arena = std::move(arena_);
  return effect;
}

void Parser::parse_profile_header() {
  // `fx.2.0` lexes as the identifier `fx` glued to the pp-number `.2.0`.
  if (!tok().is(TokenKind::identifier) || !iequals(tok().text(), "fx")) return;
  const Token& next = peek();
  if (!next.is(TokenKind::floating) || next.leading_space() || next.text().front() != '.') return;
  profile_header_.append(tok().text());
  advance();
  while (!at_eof() && !tok().at_line_start()) profile_header_.append(advance().text());
}

void Parser::parse_top_level(std::vector<ast::Decl>& out) {
  uint32_t first = pos_;
  const Token& t = tok();
  switch (t.kind) {
    case TokenKind::directive: {
      ast::Decl d;
      d.kind = ast::DeclKind::directive;
      d.directive = declarations_.make<ast::Directive>();
      d.directive->text = keep(t.text());
      d.directive->range = t.range();
      advance();
      d.directive->tokens = span_from(first);
      out.push_back(d);
      return;
    }
    case TokenKind::semi:  // empty declaration, e.g. the `};` after a function body
      advance();
      return;
    case TokenKind::l_square: {
      std::vector<std::string> attributes;
      if (!parse_attributes(attributes)) return;
      parse_variable_or_function(out, first, std::move(attributes));
      return;
    }
    case TokenKind::identifier: break;
    default: error_here("expected-declaration", "expected a declaration, found " + describe(t)); return;
  }
  std::string_view word = t.text();
  if (technique_version(word)) {
    ast::Decl d;
    d.kind = ast::DeclKind::technique;
    d.technique = declarations_.make<ast::Technique>();
    if (parse_technique(*d.technique)) out.push_back(d);
  } else if (word == "fxgroup") {
    parse_group(out);
  } else if ((word == "cbuffer" || word == "tbuffer") && peek().is(TokenKind::identifier)) {
    parse_constant_buffer(out, first);
  } else if (word == "shared" && (peek().is_identifier("cbuffer") || peek().is_identifier("tbuffer")) &&
             peek(2).is(TokenKind::identifier)) {
    advance();  // shared: kept as a flag, the buffer's tokens start at `cbuffer`
    parse_constant_buffer(out, first);
  } else if ((word == "struct" && !peek().is(TokenKind::l_brace) &&  // not `struct { ... } s;`
              !(peek().is(TokenKind::identifier) &&                  // not `struct S s;`
                peek(2).is(TokenKind::identifier))) ||
             ((word == "interface" || word == "class") && peek().is(TokenKind::identifier))) {
    parse_struct(out);
  } else if (word == "typedef") {
    parse_typedef(out);
  } else if (word == "GLSLShader") {
    parse_glsl_block(out);
  } else {
    parse_variable_or_function(out, first, {});
  }
}

bool Parser::parse_attributes(std::vector<std::string>& out) {
  while (at(TokenKind::l_square)) {
    Token open = tok();
    advance();
    std::string text;
    int brackets = 1;
    for (;;) {
      if (at(TokenKind::l_square)) ++brackets;
      if (at(TokenKind::r_square) && --brackets == 0) break;
      if (at_eof() || at(TokenKind::semi) || at(TokenKind::l_brace) || at(TokenKind::r_brace)) {
        if (Diagnostic* d =
                error_here("expected-token", "expected ']' to close the attribute, found " + describe(tok())))
          d->notes.push_back({open.loc, "to match this '['"});
        return false;
      }
      append_spelling(text, tok());
      advance();
    }
    advance();
    out.push_back(std::move(text));
  }
  return true;
}

void Parser::parse_glsl_block(std::vector<ast::Decl>& out) {
  uint32_t first = pos_;
  advance();  // GLSLShader
  ast::GlslBlock* block = declarations_.make<ast::GlslBlock>();
  if (at(TokenKind::identifier)) {
    block->name = keep(tok().text());
    block->name_range = tok().range();
    advance();
  }
  if (!skip_braced(block->code, "GLSLShader block")) return;
  block->range = range_from(first);
  accept(TokenKind::semi);
  ast::Decl d;
  d.kind = ast::DeclKind::glsl_block;
  d.glsl_block = block;
  out.push_back(d);
}

bool is_storage_keyword(std::string_view word, uint32_t& bit) {
  static constexpr struct {
    std::string_view word;
    uint32_t bit;
  } kWords[] = {
      {"shared", ast::kShared},
      {"static", ast::kStatic},
      {"uniform", ast::kUniform},
      {"const", ast::kConst},
      {"extern", ast::kExtern},
      {"volatile", ast::kVolatile},
      {"row_major", ast::kRowMajor},
      {"column_major", ast::kColumnMajor},
      {"groupshared", ast::kGroupShared},
      {"in", ast::kIn},
      {"out", ast::kOut},
      {"inout", ast::kInOut},
      {"nointerpolation", ast::kNoInterpolation},
      {"linear", ast::kLinear},
      {"centroid", ast::kCentroid},
      {"precise", ast::kPrecise},
      {"noperspective", ast::kNoPerspective},
      {"sample", ast::kSample},
      {"inline", ast::kInline},
      {"point", ast::kPoint},
      {"line", ast::kLine},
      {"triangle", ast::kTriangle},
      {"lineadj", ast::kLineAdj},
      {"triangleadj", ast::kTriangleAdj},
      {"unorm", ast::kUnorm},
      {"snorm", ast::kSnorm},
  };
  // Most words are not modifiers: the first letter picks the few rows to compare (a bit
  // per row of kWords), and most letters pick none.
  static constexpr std::array<uint32_t, 26> kRowsByLetter = [] {
    std::array<uint32_t, 26> rows{};
    for (size_t i = 0; i < std::size(kWords); ++i) rows[kWords[i].word[0] - 'a'] |= 1u << i;
    return rows;
  }();
  if (word.empty() || word[0] < 'a' || word[0] > 'z') return false;
  for (uint32_t rows = kRowsByLetter[word[0] - 'a']; rows != 0; rows &= rows - 1) {
    const auto& w = kWords[std::countr_zero(rows)];
    if (w.word == word) {
      bit = w.bit;
      return true;
    }
  }
  return false;
}

int technique_version(std::string_view word) {
  // `technique` in any case, `technique10` and `technique11` in lower case only: fxc rejects
  // `tEchnique10 { }` and takes `float4 technIque10;` (vkd3d's effect-technique tests).
  if (iequals(word, "technique")) return 9;
  if (word == "technique10") return 10;
  if (word == "technique11") return 11;
  return 0;
}

bool is_effect_keyword(std::string_view word) {
  // The D3DX effect lexer matches these in any case (the XNA stock effects write
  // `Technique` and `Pass`); HLSL's own keywords (`float`, `struct`, `return`) are
  // case-sensitive and stay ordinary identifiers here.
  static constexpr std::string_view kWords[] = {
      "technique", "pass", "compile", "sampler_state", "stateblock", "stateblock_state", "pixelshader", "vertexshader"};
  for (std::string_view k : kWords)
    if (iequals(word, k)) return true;
  return word == "technique10" || word == "technique11";
}

bool Parser::check_name(const Token& name, std::string_view what) {
  if (!is_effect_keyword(name.text())) return true;
  std::string message = quote(name.text());
  message += " is an effect keyword (in any case) and cannot name ";
  message.append(what);
  error("keyword-as-name", name.range(), std::move(message));
  return false;
}

bool is_state_object_kind(std::string_view word) {
  return iequals(word, "BlendState") || iequals(word, "DepthStencilState") || iequals(word, "RasterizerState") ||
         iequals(word, "SamplerState") || iequals(word, "SamplerComparisonState");
}

}  // namespace detail
}  // namespace fx
