// Macro expansion: argument collection, substitution with # and ##, and rescanning.
//
// Expansions are a stack of contexts per level; a macro is disabled while its context is
// on the stack (popped lazily, when a read goes past its end), which gives C's
// no-recursion rule and bounds the stack by the number of distinct macros. Level 0 reads
// the files; deeper levels expand standalone lists (macro arguments, #if lines) and are
// the only recursion, bounded by max_nesting. Contexts keep their vectors when popped,
// so steady-state expansion allocates nothing per invocation beyond the SourceManager's
// expansion record.
#include <algorithm>
#include <string>

#include "pp_internal.h"

namespace fx::pp {

namespace {
constexpr uint32_t kNotExpanded = UINT32_MAX;
constexpr uint32_t kExpandsToItself = UINT32_MAX - 1;
constexpr uint8_t kLineFlags = kAtLineStart | kLeadingSpace;

Token eof_token() { return Token{}; }
}  // namespace

Token scratch_token(SourceManager& sm, Budget& budget, TokenKind kind, std::string_view text, SourceLocation loc,
                    uint8_t flags) {
  budget.add_location_space(text.size(), {loc, {}});
  SourceLocation at = sm.add_scratch(text, loc);
  Token t;
  t.kind = kind;
  t.flags = flags;
  t.loc = loc;
  t.set_text(sm.text_at(at).substr(0, text.size()), sm);
  return t;
}

std::optional<TokenKind> classify_token(std::string_view s) {
  if (s.empty()) return std::nullopt;
  auto ident_char = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  };
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (!digit(s[0]) && ident_char(s[0])) {
    return std::all_of(s.begin(), s.end(), ident_char) ? std::optional(TokenKind::identifier) : std::nullopt;
  }
  if (digit(s[0]) || (s[0] == '.' && s.size() > 1 && digit(s[1]))) {
    // The lexer's pp-number rule, so a pasted number lexes like a written one.
    bool hex = s.size() > 1 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    bool floating = false;
    for (size_t i = 0; i < s.size(); ++i) {
      char c = s[i];
      if (c == '.') floating = true;
      else if ((c == '+' || c == '-') && !hex && i > 0 && (s[i - 1] == 'e' || s[i - 1] == 'E')) floating = true;
      else if (!ident_char(c)) return std::nullopt;
      else if (!hex && (c == 'e' || c == 'E' || c == 'f' || c == 'F' || c == 'h' || c == 'H')) floating = true;
    }
    return floating ? TokenKind::floating : TokenKind::integer;
  }
  for (auto k = static_cast<uint8_t>(TokenKind::l_paren); k <= static_cast<uint8_t>(TokenKind::hashhash); ++k)
    if (s == spelling(static_cast<TokenKind>(k))) return static_cast<TokenKind>(k);
  return std::nullopt;
}

MacroEngine::MacroEngine(SourceManager& sm, DiagnosticSink& diags, MacroTable& macros, Budget& budget)
    : sm_(sm), diags_(diags), macros_(macros), budget_(budget) {
  level(0).from_files = true;
}

MacroEngine::~MacroEngine() = default;

MacroEngine::Level& MacroEngine::level(size_t depth) {
  while (levels_.size() <= depth) levels_.push_back(std::make_unique<Level>());
  return *levels_[depth];
}

void MacroEngine::reset(FileTokenSource* files) {
  for (auto& l : levels_) {
    for (size_t i = 0; i < l->active; ++i)
      if (l->contexts[i].macro) l->contexts[i].macro->disabled = false;
    l->active = 0;
    l->pushback.clear();
  }
  files_ = files;
  depth_ = 0;
  disabled_ = 0;
  counter_ = 0;
  level(0).from_files = true;
}

MacroEngine::Context& MacroEngine::push_context(Level& l, Macro* m) {
  if (l.active == l.contexts.size()) l.contexts.emplace_back();
  Context& c = l.contexts[l.active++];
  c.macro = m;
  c.pos = 0;
  c.tokens.clear();
  if (m) {
    m->disabled = true;
    ++disabled_;
  }
  return c;
}

void MacroEngine::paint(Token& t) const {
  if (disabled_ == 0 || t.kind != TokenKind::identifier || (t.flags & kNoExpand)) return;
  if (Macro* m = macros_.find(t.text()); m && m->disabled) t.flags |= kNoExpand;
}

Token MacroEngine::next_raw(Level& l) {
  for (;;) {
    if (!l.pushback.empty()) {
      Token t = l.pushback.back();
      l.pushback.pop_back();
      return t;
    }
    if (l.active != 0) {
      Context& c = l.contexts[l.active - 1];
      if (c.pos < c.tokens.size()) return c.tokens[c.pos++];
      if (c.macro) {
        c.macro->disabled = false;
        --disabled_;
      }
      --l.active;
      continue;
    }
    if (l.from_files && files_ && !budget_.exhausted()) return files_->next_file_token();
    return eof_token();
  }
}

Token MacroEngine::next() {
  Level& l = *levels_[0];
  // Hot path: nothing pending at file level, so the next token comes straight from the
  // files and only a macro name needs the general path (which reads it back from
  // pushback exactly as if it had come from the files).
  if (l.pushback.empty() && l.active == 0 && files_ && !budget_.exhausted()) {
    Token t = files_->next_file_token();
    if (t.kind != TokenKind::identifier || (t.flags & kNoExpand) || !macros_.find(t.text())) return t;
    l.pushback.push_back(t);
  }
  return next_expanded(l);
}

Token MacroEngine::expand_file_token(const Token& name) {
  Level& l = *levels_[0];
  l.pushback.push_back(name);
  return next_expanded(l);
}

Token MacroEngine::next_expanded(Level& l) {
  for (;;) {
    Token t = next_raw(l);
    if (t.kind != TokenKind::identifier || (t.flags & kNoExpand)) return t;
    Macro* m = macros_.find(t.text());
    if (!m) return t;
    if (m->disabled) {
      t.flags |= kNoExpand;
      return t;
    }
    if (!expand(l, t, *m)) return t;
    if (budget_.exhausted()) return eof_token();
  }
}

void MacroEngine::expand_list(std::span<const Token> in, std::vector<Token>& out) {
  if (depth_ + 1 >= budget_.limits().max_nesting) {
    budget_.fail(in.empty() ? SourceRange{} : in.front().range(),
                 "macro arguments nested more than " + std::to_string(budget_.limits().max_nesting) + " levels deep");
    return;
  }
  Level& sub = level(++depth_);
  sub.from_files = false;
  sub.pushback.clear();
  Context& list = push_context(sub, nullptr);
  list.tokens.assign(in.begin(), in.end());
  for (;;) {
    Token t = next_expanded(sub);
    if (t.kind == TokenKind::eof) break;
    out.push_back(t);
  }
  // Only a budget stop leaves contexts behind; their macros must be enabled again.
  for (size_t i = 0; i < sub.active; ++i)
    if (Macro* m = sub.contexts[i].macro) m->disabled = false, --disabled_;
  sub.active = 0;
  --depth_;
}

Token MacroEngine::builtin_token(const Token& name, Macro& m) {
  uint8_t flags = static_cast<uint8_t>(name.flags | kFromMacro);
  PresumedLocation p = sm_.presumed(name.loc);
  if (m.builtin == Builtin::file) {
    scratch_.assign(1, '"');
    for (char c : p.file) {
      if (c == '\\' || c == '"') scratch_.push_back('\\');
      scratch_.push_back(c);
    }
    scratch_.push_back('"');
    return scratch_token(sm_, budget_, TokenKind::string, scratch_, name.loc, flags);
  }
  scratch_ = std::to_string(m.builtin == Builtin::line ? p.line : counter_++);
  return scratch_token(sm_, budget_, TokenKind::integer, scratch_, name.loc, flags);
}

bool MacroEngine::expand(Level& l, const Token& name, Macro& m) {
  if (m.builtin != Builtin::none) {
    l.pushback.push_back(builtin_token(name, m));
    return true;
  }
  SourceRange invocation = name.range();
  if (m.function_like) {
    Token open = next_raw(l);
    paint(open);
    if (!open.is(TokenKind::l_paren)) {
      // Not an invocation: the name stays an identifier.
      l.pushback.push_back(open);
      return false;
    }
    Token close;
    if (!collect_arguments(l, name, m, close)) return true;
    invocation.end = close.range().end;
  }
  if (!budget_.add_expansion(invocation)) return true;
  if (m.body.empty()) return true;
  if (!budget_.add_location_space(m.body_length, invocation) || !budget_.add_tokens(m.body.size(), invocation))
    return true;
  SourceLocation base = sm_.add_expansion({std::string(m.name), m.body_start, invocation}, m.body_length);
  substitute(l, name, m, base);
  return true;
}

bool MacroEngine::collect_arguments(Level& l, const Token& name, Macro& m, Token& close) {
  l.args.clear();
  l.arg_begin.assign(1, 0);
  size_t params = m.params.size();
  int depth = 1;
  for (;;) {
    Token t = next_raw(l);
    if (t.kind == TokenKind::eof) {
      l.pushback.push_back(t);
      if (!budget_.exhausted())
        diags_.error("unterminated-macro-call", name.range(),
                     "unterminated argument list invoking macro '" + std::string(m.name) + "'");
      return false;
    }
    paint(t);
    if (t.is(TokenKind::l_paren)) {
      ++depth;
    } else if (t.is(TokenKind::r_paren)) {
      if (--depth == 0) {
        close = t;
        break;
      }
    } else if (t.is(TokenKind::comma) && depth == 1 && !(m.variadic && l.arg_begin.size() == params)) {
      l.arg_begin.push_back(static_cast<uint32_t>(l.args.size()));
      continue;
    }
    l.args.push_back(t);
  }
  l.arg_begin.push_back(static_cast<uint32_t>(l.args.size()));
  size_t given = l.arg_begin.size() - 1;
  if (params == 0 && given == 1 && l.args.empty()) given = 0;
  if (m.variadic && given + 1 == params) {
    // `F(a)` for `F(a, ...)`: an empty __VA_ARGS__ (C23 allows leaving it out).
    l.arg_begin.push_back(static_cast<uint32_t>(l.args.size()));
    given = params;
  }
  if (given != params) {
    diags_.error("macro-args", {name.loc, close.range().end},
                 "macro '" + std::string(m.name) + "' takes " + std::to_string(params) +
                     (params == 1 ? " argument" : " arguments") + ", but " + std::to_string(given) +
                     (given == 1 ? " was" : " were") + " given");
    return false;
  }
  l.expanded.clear();
  l.expanded_begin.assign(params, kNotExpanded);
  l.expanded_end.assign(params, 0);
  return true;
}

std::span<const Token> MacroEngine::expanded_argument(Level& l, size_t i) {
  std::span<const Token> raw(l.args.data() + l.arg_begin[i], l.arg_begin[i + 1] - l.arg_begin[i]);
  if (l.expanded_begin[i] == kNotExpanded) {
    bool any_macro = false;
    for (const Token& t : raw)
      if (t.kind == TokenKind::identifier && !(t.flags & kNoExpand) && macros_.find(t.text())) {
        any_macro = true;
        break;
      }
    if (!any_macro) {
      l.expanded_begin[i] = kExpandsToItself;
    } else {
      // The argument is fully expanded on its own first (C 6.10.3.1); `raw` stays valid
      // because deeper levels do not touch this level's vectors.
      uint32_t begin = static_cast<uint32_t>(l.expanded.size());
      expand_list(raw, l.expanded);
      l.expanded_begin[i] = begin;
      l.expanded_end[i] = static_cast<uint32_t>(l.expanded.size());
    }
  }
  if (l.expanded_begin[i] == kExpandsToItself) return raw;
  return {l.expanded.data() + l.expanded_begin[i], l.expanded_end[i] - l.expanded_begin[i]};
}

Token MacroEngine::stringize(std::span<const Token> arg, SourceLocation loc, uint8_t flags) {
  scratch_.assign(1, '"');
  for (size_t i = 0; i < arg.size(); ++i) {
    if (i > 0 && arg[i].leading_space()) scratch_.push_back(' ');
    bool quoted = arg[i].is(TokenKind::string) || arg[i].is(TokenKind::character);
    for (char c : arg[i].text()) {
      if (quoted && (c == '"' || c == '\\')) scratch_.push_back('\\');
      scratch_.push_back(c);
    }
  }
  scratch_.push_back('"');
  return scratch_token(sm_, budget_, TokenKind::string, scratch_, loc, flags);
}

void MacroEngine::substitute(Level& l, const Token& name, Macro& m, SourceLocation base) {
  std::vector<Token>& out = l.build;
  out.clear();
  auto mapped = [&](const Token& bt) {
    Token t = bt;
    t.loc = base.offset(bt.loc.raw - m.body_start.raw);
    t.flags = static_cast<uint8_t>((bt.flags & ~kAtLineStart) | kFromMacro);
    return t;
  };
  auto raw_arg = [&](size_t i) {
    return std::span<const Token>(l.args.data() + l.arg_begin[i], l.arg_begin[i + 1] - l.arg_begin[i]);
  };
  // Appends an argument's tokens; its first token takes the parameter's spacing.
  auto append_arg = [&](std::span<const Token> arg, const Token& param) {
    if (!budget_.add_tokens(arg.size(), name.range())) return;
    for (size_t k = 0; k < arg.size(); ++k) {
      Token t = arg[k];
      t.flags = static_cast<uint8_t>((t.flags & ~kAtLineStart) | kFromMacro);
      if (k == 0) t.flags = static_cast<uint8_t>((t.flags & ~kLeadingSpace) | (param.flags & kLeadingSpace));
      out.push_back(t);
    }
  };

  const size_t n = m.body.size();
  if (!m.has_operators) {
    for (size_t i = 0; i < n && !budget_.exhausted(); ++i) {
      if (m.param_of[i] >= 0) append_arg(expanded_argument(l, size_t(m.param_of[i])), m.body[i]);
      else out.push_back(mapped(m.body[i]));
    }
  } else {
    // `paste` is set after a `##`: the next operand's first token joins the last one.
    // `operand_start` is where the latest operand begins, so an empty operand (a
    // placemarker) is recognisable as "nothing was appended".
    bool paste = false;
    size_t operand_start = 0;
    auto append_operand = [&](std::span<const Token> toks, const Token& param, bool is_arg) {
      size_t start = out.size();
      if (toks.empty()) {
        if (!paste) operand_start = out.size();
        paste = false;
        return;
      }
      size_t first = 0;
      if (paste) {
        Token& lhs = out.back();
        scratch_.assign(lhs.text()).append(toks[0].text());
        if (std::optional<TokenKind> kind = classify_token(scratch_)) {
          lhs = scratch_token(sm_, budget_, *kind, scratch_, lhs.loc, static_cast<uint8_t>(lhs.flags & ~kNoExpand));
          first = 1;
          start = out.size() - 1;
        } else {
          diags_.error("invalid-paste", toks[0].range(),
                       "pasting formed '" + scratch_ + "', an invalid preprocessing token");
        }
      }
      if (is_arg) {
        if (first < toks.size()) append_arg(toks.subspan(first), first == 0 ? param : toks[first]);
      } else if (first == 0) {
        out.push_back(toks[0]);
      }
      operand_start = start;
      paste = false;
    };
    for (size_t i = 0; i < n && !budget_.exhausted(); ++i) {
      const Token& bt = m.body[i];
      int32_t p = m.param_of[i];
      if (m.function_like && bt.is(TokenKind::hash)) {
        Token s = stringize(raw_arg(size_t(m.param_of[i + 1])), mapped(bt).loc, mapped(bt).flags);
        append_operand({&s, 1}, bt, false);
        ++i;
        continue;
      }
      if (bt.is(TokenKind::hashhash)) {
        // GNU `, ## __VA_ARGS__`: the comma disappears with an empty variable argument.
        bool va_next = m.variadic && m.param_of[i + 1] == int32_t(m.params.size() - 1);
        if (va_next && m.body[i - 1].is(TokenKind::comma) && m.param_of[i - 1] < 0) {
          std::span<const Token> va = raw_arg(m.params.size() - 1);
          if (va.empty() && !out.empty()) out.pop_back();
          append_arg(va, m.body[i + 1]);
          operand_start = out.size();
          ++i;
          continue;
        }
        paste = out.size() > operand_start;
        continue;
      }
      bool next_pastes = i + 1 < n && m.body[i + 1].is(TokenKind::hashhash);
      if (p >= 0) {
        bool pasted = paste || next_pastes;
        append_operand(pasted ? raw_arg(size_t(p)) : expanded_argument(l, size_t(p)), bt, true);
      } else {
        Token t = mapped(bt);
        append_operand({&t, 1}, bt, false);
      }
    }
  }
  if (out.empty() || budget_.exhausted()) return;
  out[0].flags = static_cast<uint8_t>((out[0].flags & ~kLineFlags) | (name.flags & kLineFlags));
  Context& c = push_context(l, &m);
  std::swap(c.tokens, out);
}

}  // namespace fx::pp
