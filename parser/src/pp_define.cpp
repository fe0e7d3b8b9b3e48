// #define parsing, the macro table and the run's work budget.
#include <string>

#include "pp_internal.h"

namespace fx::pp {
namespace {

bool is_ellipsis(std::span<const Token> t, size_t i) {
  return i + 2 < t.size() && t[i].is(TokenKind::period) && t[i + 1].is(TokenKind::period) &&
         t[i + 2].is(TokenKind::period) && !t[i + 1].leading_space() && !t[i + 2].leading_space();
}

}  // namespace

bool Macro::same_definition(const Macro& o) const {
  if (function_like != o.function_like || variadic != o.variadic || params != o.params || body.size() != o.body.size())
    return false;
  for (size_t i = 0; i < body.size(); ++i) {
    if (body[i].kind != o.body[i].kind || body[i].text() != o.body[i].text()) return false;
    // Whitespace between tokens matters (C 6.10.3p2), its amount does not.
    if (i > 0 && body[i].leading_space() != o.body[i].leading_space()) return false;
  }
  return true;
}

std::unique_ptr<Macro> parse_macro_definition(std::span<const Token> line, SourceLocation directive,
                                              DiagnosticSink& diags) {
  if (line.empty() || !line[0].is(TokenKind::identifier)) {
    diags.error("invalid-macro-name", line.empty() ? SourceRange{directive, {}} : line[0].range(),
                "macro name must be an identifier");
    return nullptr;
  }
  if (line[0].text() == "defined") {
    diags.error("invalid-macro-name", line[0].range(), "'defined' cannot be used as a macro name");
    return nullptr;
  }
  auto m = std::make_unique<Macro>();
  m->name = line[0].text();
  m->name_loc = line[0].loc;
  size_t i = 1;
  // Function-like only when '(' touches the name: `#define F (x)` is object-like.
  if (i < line.size() && line[i].is(TokenKind::l_paren) && !line[i].leading_space()) {
    m->function_like = true;
    ++i;
    bool closed = false;
    while (i < line.size()) {
      if (line[i].is(TokenKind::r_paren) && m->params.empty()) {
        closed = true, ++i;
        break;
      }
      if (is_ellipsis(line, i)) {
        m->variadic = true;
        m->params.push_back("__VA_ARGS__");
        i += 3;
      } else if (line[i].is(TokenKind::identifier)) {
        for (std::string_view p : m->params)
          if (p == line[i].text()) {
            diags.error("macro-definition", line[i].range(), "duplicate macro parameter '" + std::string(p) + "'");
            return nullptr;
          }
        if (line[i].text() == "__VA_ARGS__") {
          diags.error("macro-definition", line[i].range(),
                      "__VA_ARGS__ can only appear in the body of a variadic macro");
          return nullptr;
        }
        m->params.push_back(line[i].text());
        ++i;
      } else {
        break;
      }
      if (i < line.size() && line[i].is(TokenKind::r_paren)) {
        closed = true, ++i;
        break;
      }
      if (m->variadic || i >= line.size() || !line[i].is(TokenKind::comma)) break;
      ++i;
    }
    if (!closed) {
      SourceRange at = i < line.size() ? line[i].range() : line.back().range();
      diags.error("macro-definition", at, "expected ')' or a parameter name in macro parameter list");
      return nullptr;
    }
  } else if (i < line.size() && !line[i].leading_space()) {
    diags.warning("macro-definition", line[i].range(), "whitespace is required after the macro name");
  }
  for (; i < line.size(); ++i) {
    Token t = line[i];
    t.flags &= static_cast<uint8_t>(~(kAtLineStart | kNoExpand));
    int32_t param = -1;
    if (t.is(TokenKind::identifier)) {
      for (size_t p = 0; p < m->params.size(); ++p)
        if (m->params[p] == t.text()) param = static_cast<int32_t>(p);
      if (param < 0 && t.text() == "__VA_ARGS__") {
        diags.error("macro-definition", t.range(), "__VA_ARGS__ can only appear in the body of a variadic macro");
        return nullptr;
      }
    }
    if (t.is(TokenKind::hashhash) || (m->function_like && t.is(TokenKind::hash))) m->has_operators = true;
    m->body.push_back(t);
    m->param_of.push_back(param);
  }
  const auto& body = m->body;
  for (size_t b = 0; b < body.size(); ++b) {
    if (body[b].is(TokenKind::hashhash) && (b == 0 || b + 1 == body.size())) {
      diags.error("macro-definition", body[b].range(), "'##' cannot appear at either end of a macro expansion");
      return nullptr;
    }
    if (m->function_like && body[b].is(TokenKind::hash) && (b + 1 == body.size() || m->param_of[b + 1] < 0)) {
      diags.error("macro-definition", body[b].range(), "'#' is not followed by a macro parameter");
      return nullptr;
    }
  }
  if (!body.empty()) {
    m->body_start = body.front().loc;
    m->body_length = body.back().loc.raw + static_cast<uint32_t>(body.back().text().size()) - body.front().loc.raw;
  }
  return m;
}

Macro* MacroTable::define(std::unique_ptr<Macro> m) {
  names_.add(m->name);
  Macro* previous = find(m->name);
  map_[m->name] = m.get();
  storage_.push_back(std::move(m));
  return previous;
}

void MacroTable::clear() {
  names_.clear();
  map_.clear();
  storage_.clear();
}

void Budget::fail(SourceRange where, std::string message) {
  if (exhausted_) return;
  exhausted_ = true;
  diags_.error("limit-exceeded", where, std::move(message));
}

bool Budget::add_expansion(SourceRange where) {
  if (++expansions_ <= limits_.max_macro_expansions) return true;
  fail(where, "more than " + std::to_string(limits_.max_macro_expansions) +
                  " macro expansions (recursive or exponentially growing macros?)");
  return false;
}

bool Budget::add_tokens(uint64_t n, SourceRange where) {
  tokens_ += n;
  if (tokens_ <= limits_.max_tokens) return true;
  fail(where, "more than " + std::to_string(limits_.max_tokens) + " tokens produced");
  return false;
}

bool Budget::add_input(uint64_t bytes, SourceRange where) {
  input_bytes_ += bytes;
  if (input_bytes_ <= limits_.max_input_bytes) return true;
  fail(where, "more than " + std::to_string(limits_.max_input_bytes) + " bytes of input read");
  return false;
}

bool Budget::add_location_space(uint64_t bytes, SourceRange where) {
  // SourceLocations are 32-bit; keep a quarter of the space for whoever shares the
  // SourceManager after us.
  constexpr uint64_t kMaxSpace = 3ull << 30;
  location_space_ += bytes + 1;
  if (location_space_ <= kMaxSpace) return true;
  fail(where, "source location space exhausted (too much input or macro expansion)");
  return false;
}

}  // namespace fx::pp
