// The preprocessor driver: the include stack, directives and conditional groups. Macro
// expansion lives in pp_macro.cpp, #if arithmetic in pp_expression.cpp, include search
// in pp_include.cpp.
#include "fx/preprocessor.h"

#include <algorithm>
#include <array>
#include <string>
#include <unordered_set>

#include "fx/huge_pages.h"
#include "fx/lexer.h"
#include "pp_internal.h"

namespace fx {

using pp::Macro;

namespace {
// Tokens lexed per batch: enough to amortise the call, small enough to stay in cache.
constexpr size_t kLexBatch = 256;
// How far above the including file a root-relative #include ("Data/Effects/x.fx") is looked for.
constexpr size_t kAncestorLevels = 8;
}  // namespace

class Preprocessor::Impl final : public pp::FileTokenSource {
 public:
  Impl(SourceManager& sm, DiagnosticSink& diags, PreprocessorOptions options)
      : sm_(sm),
        diags_(diags),
        options_(std::move(options)),
        budget_(diags, options_.limits),
        engine_(sm, diags, macros_, budget_) {
    if (!options_.loader) {
      options_.loader = disk_file_loader();
      if (!options_.lister) options_.lister = disk_directory_lister();
    }
  }

  bool run(const std::string& name, std::optional<std::string> text, std::vector<Token>& out);
  Token next_file_token() override;
  [[gnu::noinline]] Token next_file_token_slow();
  // Appends up to `limit` tokens from the middle of the current batch to `out` in one
  // copy; returns how many. Only while no macro expands.
  size_t copy_plain_tokens(std::vector<Token>& out, uint64_t limit);

  std::vector<std::string> files_;
  std::vector<IncludeEdge> includes_;

 private:
  // One file being read. Lexer diagnostics go to a private sink first, so text in skipped
  // groups (which C still tokenizes) cannot produce errors.
  struct Frame {
    Frame(SourceManager& sm, BufferId id, std::string p, size_t base)
        : buffer(id),
          path(std::move(p)),
          folder(pp::parent_folder(path)),
          lexer(sm, id, lex_diags),
          conditional_base(base) {}
    BufferId buffer;
    std::string path, folder;
    DiagnosticSink lex_diags;
    Lexer lexer;
    size_t conditional_base;  // conditionals_ entries opened before this file
    // Tokens lexed ahead (Lexer::next_batch), up to the next directive: one call per
    // batch instead of per token. Only the last one may have left lexer diagnostics.
    std::array<Token, kLexBatch> ahead;
    size_t ahead_size = 0, ahead_next = 0;
  };
  struct Conditional {
    SourceLocation loc;
    bool taken = false;  // some group of this #if chain was (or is being) emitted
    bool seen_else = false;
  };

  // Moves the lexer's diagnostics to the real sink (keep) or drops them.
  void forward(Frame& f, bool keep) {
    if (!f.lex_diags.diagnostics().empty()) forward_diagnostics(f, keep);
  }
  void forward_diagnostics(Frame& f, bool keep);
  void read_line(Frame& f, bool keep = true);
  void skip_line(Frame& f) { read_line(f, false); }
  std::optional<Token> directive(Frame& f, const Token& hash);
  void define(Frame& f);
  void undefine(Frame& f);
  void include(Frame& f, const Token& hash);
  void include_file(Frame& f, const Token& hash, SourceRange spelled, const std::string& name, bool angled);
  void line_directive(Frame& f, const Token& name);
  void message_directive(Frame& f, const Token& hash, const Token& name);
  Token kept_directive(Frame& f, const Token& hash, const Token& name);
  bool condition(Frame& f, const Token& name);
  void open_conditional(Frame& f, const Token& hash, bool value);
  Conditional* current_conditional(Frame& f, const Token& name);
  void skip_group(Frame& f);
  void close_conditionals(Frame& f);
  void push_file(const std::string& path, std::string text, SourceLocation included_from);
  void run_definitions(std::string name, std::string text);

  SourceManager& sm_;
  DiagnosticSink& diags_;
  PreprocessorOptions options_;
  pp::Budget budget_;
  pp::MacroTable macros_;
  pp::MacroEngine engine_;
  std::vector<std::unique_ptr<Frame>> frames_;
  std::vector<Conditional> conditionals_;
  std::unordered_set<std::string> once_;
  std::vector<Token> line_, work_, expanded_;
  std::string text_;
};

namespace {
Token number_token(std::string_view text, SourceLocation loc) {
  Token t;
  t.kind = TokenKind::integer;
  t.loc = loc;
  t.set_short_text(text);
  return t;
}
}  // namespace

void Preprocessor::Impl::forward_diagnostics(Frame& f, bool keep) {
  if (keep)
    for (const Diagnostic& d : f.lex_diags.diagnostics()) {
      Diagnostic& copy = diags_.report(d.severity, d.id, d.range, d.message);
      copy.notes = d.notes;
      copy.fixits = d.fixits;
    }
  f.lex_diags.clear();
}

void Preprocessor::Impl::read_line(Frame& f, bool keep) {
  line_.clear();
  while (!f.lexer.at_line_end()) line_.push_back(f.lexer.next());
  forward(f, keep);
}

void Preprocessor::Impl::push_file(const std::string& path, std::string text, SourceLocation included_from) {
  bool seen = false;
  for (const std::string& p : files_) seen = seen || p == path;
  if (!seen) files_.push_back(path);
  budget_.add_location_space(text.size(), {included_from, {}});
  BufferId id = sm_.add_buffer(path, std::move(text), included_from);
  frames_.push_back(std::make_unique<Frame>(sm_, id, path, conditionals_.size()));
}

Token Preprocessor::Impl::next_file_token() {
  // Hot path: a token from the middle of a batch is never a directive or eof and left no
  // lexer diagnostics (only a batch's last token can), so it needs no checks but the
  // limits. Everything else takes next_file_token_slow().
  if (!frames_.empty()) {
    Frame& f = *frames_.back();
    if (f.ahead_next + 1 < f.ahead_size && !budget_.exhausted() && !diags_.error_limit_reached())
      return f.ahead[f.ahead_next++];
  }
  return next_file_token_slow();
}

Token Preprocessor::Impl::next_file_token_slow() {
  for (;;) {
    if (frames_.empty() || budget_.exhausted() || diags_.error_limit_reached()) return Token{};
    Frame& f = *frames_.back();
    if (f.ahead_next == f.ahead_size) {
      f.ahead_size = f.lexer.next_batch(f.ahead.data(), kLexBatch, &macros_.names());
      f.ahead_next = 0;
    }
    Token t = f.ahead[f.ahead_next++];
    if (f.ahead_next == f.ahead_size) forward(f, true);
    if (t.kind == TokenKind::hash && t.at_line_start()) {
      if (std::optional<Token> kept = directive(f, t)) return *kept;
      continue;
    }
    if (t.kind == TokenKind::eof) {
      close_conditionals(f);
      if (frames_.size() == 1) return t;
      frames_.pop_back();
      continue;
    }
    return t;
  }
}

size_t Preprocessor::Impl::copy_plain_tokens(std::vector<Token>& out, uint64_t limit) {
  // The tokens next_file_token() would return one by one on its hot path: no directive,
  // no eof, no diagnostics among them, so nothing can happen between two of them. Nor a
  // macro name: a batch ends after an identifier the macro table's filter may contain, and
  // only a directive (which ends a batch too) defines macros.
  if (frames_.empty() || budget_.exhausted() || diags_.error_limit_reached()) return 0;
  Frame& f = *frames_.back();
  if (f.ahead_next + 1 >= f.ahead_size) return 0;
  const Token* first = f.ahead.data() + f.ahead_next;
  const Token* t = f.ahead.data() + f.ahead_size - 1;
  if (static_cast<uint64_t>(t - first) > limit) t = first + limit;
  size_t n = static_cast<size_t>(t - first);
  // Included files make the output outgrow any first estimate. Growing 4x instead of 2x
  // writes the tokens into fresh memory 1.33 times instead of 2 on average, and huge pages
  // make the faults on that fresh memory 512 times fewer (fx/huge_pages.h). Only touched
  // pages become resident, so the spare capacity costs address space only.
  if (out.capacity() - out.size() < n) reserve_with_huge_pages(out, std::max(4 * out.capacity(), out.size() + n));
  out.insert(out.end(), first, t);
  f.ahead_next += n;
  return n;
}

std::optional<Token> Preprocessor::Impl::directive(Frame& f, const Token& hash) {
  if (f.lexer.at_line_end()) return std::nullopt;  // the null directive: a lone '#'
  Token name = f.lexer.next();
  forward(f, true);
  std::string_view n = name.is(TokenKind::identifier) ? name.text() : std::string_view();
  if (name.is(TokenKind::integer)) {
    // GNU line marker `# 12 "file"`, as other preprocessors write it.
    line_directive(f, name);
  } else if (n == "define") {
    define(f);
  } else if (n == "undef") {
    undefine(f);
  } else if (n == "include") {
    include(f, hash);
  } else if (n == "if") {
    open_conditional(f, hash, condition(f, name));
  } else if (n == "ifdef" || n == "ifndef") {
    read_line(f);
    if (line_.empty() || !line_[0].is(TokenKind::identifier)) {
      diags_.error("invalid-directive", name.range(), "macro name missing in #" + std::string(n));
      open_conditional(f, hash, false);
      return std::nullopt;
    }
    if (line_.size() > 1) diags_.warning("extra-tokens", line_[1].range(), "extra tokens at end of #" + std::string(n));
    bool defined = macros_.find(line_[0].text()) != nullptr;
    open_conditional(f, hash, n == "ifdef" ? defined : !defined);
  } else if (n == "elif" || n == "else") {
    // Reached from an emitted group: the chain is decided, skip to its #endif.
    Conditional* c = current_conditional(f, name);
    skip_line(f);
    if (!c) return std::nullopt;
    if (c->seen_else) diags_.error("invalid-directive", name.range(), "#" + std::string(n) + " after #else");
    if (n == "else") c->seen_else = true;
    skip_group(f);
  } else if (n == "endif") {
    read_line(f);
    if (!line_.empty()) diags_.warning("extra-tokens", line_[0].range(), "extra tokens at end of #endif");
    if (current_conditional(f, name)) conditionals_.pop_back();
  } else if (n == "line") {
    line_directive(f, name);
  } else if (n == "error" || n == "warning") {
    message_directive(f, hash, name);
  } else if (n == "pragma") {
    read_line(f);
    if (line_.size() == 1 && line_[0].is_identifier("once")) {
      once_.insert(f.path);
      return std::nullopt;
    }
    return kept_directive(f, hash, name);
  } else if (n == "version" || n == "extension") {
    read_line(f);
    return kept_directive(f, hash, name);
  } else {
    diags_.error("unknown-directive", {hash.loc, name.range().end},
                 "unknown preprocessing directive '#" + std::string(name.text()) + "'");
    skip_line(f);
  }
  return std::nullopt;
}

Token Preprocessor::Impl::kept_directive(Frame& f, const Token& hash, const Token& name) {
  text_.assign("#").append(name.text());
  for (size_t i = 0; i < line_.size(); ++i) {
    if (i == 0 || line_[i].leading_space()) text_.push_back(' ');
    text_.append(line_[i].text());
  }
  return pp::scratch_token(sm_, budget_, TokenKind::directive, text_, hash.loc, hash.flags);
}

void Preprocessor::Impl::define(Frame& f) {
  read_line(f);
  SourceLocation at = line_.empty() ? f.lexer.here() : line_[0].loc;
  std::unique_ptr<Macro> m = pp::parse_macro_definition(line_, at, diags_);
  if (!m) return;
  Macro* previous = macros_.find(m->name);
  if (previous && previous->builtin != pp::Builtin::none) {
    diags_.warning("builtin-macro-redefined", line_[0].range(),
                   "redefining builtin macro '" + std::string(m->name) + "'");
  } else if (previous && !previous->same_definition(*m)) {
    Diagnostic& d =
        diags_.warning("macro-redefined", line_[0].range(), "'" + std::string(m->name) + "' macro redefined");
    d.notes.push_back({previous->name_loc, "previous definition is here"});
  }
  macros_.define(std::move(m));
}

void Preprocessor::Impl::undefine(Frame& f) {
  read_line(f);
  if (line_.empty() || !line_[0].is(TokenKind::identifier)) {
    diags_.error("invalid-macro-name", line_.empty() ? SourceRange{f.lexer.here(), {}} : line_[0].range(),
                 "macro name must be an identifier");
    return;
  }
  if (line_.size() > 1) diags_.warning("extra-tokens", line_[1].range(), "extra tokens at end of #undef");
  if (Macro* m = macros_.find(line_[0].text()); m && m->builtin != pp::Builtin::none)
    diags_.warning("builtin-macro-redefined", line_[0].range(),
                   "undefining builtin macro '" + std::string(m->name) + "'");
  macros_.undefine(line_[0].text());
}

void Preprocessor::Impl::include(Frame& f, const Token& hash) {
  std::optional<Token> header = f.lexer.header_name();
  forward(f, true);
  std::string name;
  bool angled = false;
  SourceRange spelled{hash.loc, {}};
  size_t extra = 0;
  if (header) {
    read_line(f);
    name = header->text().substr(1, header->text().size() - 2);
    angled = true;
    spelled = header->range();
  } else {
    read_line(f);
    const std::vector<Token>* toks = &line_;
    if (!line_.empty() && !line_[0].is(TokenKind::string)) {
      // `#include MACRO`: the expansion must be "file" or <file>.
      expanded_.clear();
      engine_.expand_list(line_, expanded_);
      toks = &expanded_;
    }
    if (!toks->empty() && (*toks)[0].is(TokenKind::string)) {
      // No escape processing: `"shaders\common.fxh"` is a Windows path, not an escape.
      name = (*toks)[0].text().substr(1, (*toks)[0].text().size() - 2);
      spelled = (*toks)[0].range();
      extra = 1;
    } else if (!toks->empty() && (*toks)[0].is(TokenKind::less)) {
      size_t i = 1;
      for (; i < toks->size() && !(*toks)[i].is(TokenKind::greater); ++i) {
        if (i > 1 && (*toks)[i].leading_space()) name.push_back(' ');
        name.append((*toks)[i].text());
      }
      if (i == toks->size()) name.clear();
      angled = true;
      spelled = (*toks)[0].range();
      extra = i + 1;
    }
    if (name.empty()) {
      diags_.error("invalid-directive", toks->empty() ? SourceRange{hash.loc, {}} : (*toks)[0].range(),
                   "expected \"FILENAME\" or <FILENAME> after #include");
      return;
    }
    if (toks->size() > extra) diags_.warning("extra-tokens", (*toks)[extra].range(), "extra tokens at end of #include");
  }
  if (header && !line_.empty()) diags_.warning("extra-tokens", line_[0].range(), "extra tokens at end of #include");
  include_file(f, hash, spelled, name, angled);
}

void Preprocessor::Impl::include_file(Frame& f, const Token& hash, SourceRange spelled, const std::string& name,
                                      bool angled) {
  std::vector<std::string> folders;
  // fxc, like MSVC, looks for a quoted name beside the file holding the directive, then
  // beside each file that included it, innermost first, and only then in the -I folders.
  if (!angled)
    for (auto open = frames_.rbegin(); open != frames_.rend(); ++open)
      if (std::find(folders.begin(), folders.end(), (*open)->folder) == folders.end())
        folders.push_back((*open)->folder);
  folders.insert(folders.end(), options_.include_dirs.begin(), options_.include_dirs.end());
  std::optional<pp::ResolvedInclude> found = pp::resolve_include(name, folders, options_.loader, options_.lister);
  // "Data/Effects/x.fx" found nowhere: written relative to the folder the engine runs
  // from, which is then above the including file (tried nearest first, with a warning).
  std::string ancestor;
  if (!found && !angled && pp::names_a_folder(name))
    for (std::string& folder : pp::ancestor_folders(f.folder, kAncestorLevels))
      if ((found = pp::resolve_include(name, {folder}, options_.loader, options_.lister))) {
        ancestor = folder.empty() ? std::string(".") : std::move(folder);
        break;
      }
  if (!found) {
    const pp::MissingInclude missing = pp::describe_missing_include(name, folders, options_.lister);
    std::string message = "'" + name + "' file not found";
    if (!missing.searched.empty()) {
      message += " (searched";
      for (size_t i = 0; i < missing.searched.size(); ++i) message += (i ? ", '" : " '") + missing.searched[i] + "'";
      message += ")";
    }
    if (!missing.near.empty()) message += "; did you mean '" + missing.near + "'?";
    diags_.error("include-not-found", spelled, message);
    return;
  }
  if (!ancestor.empty())
    diags_.warning("include-from-ancestor", spelled,
                   "'" + name + "' is found only from the folder '" + ancestor +
                       "' above the including file (as a program run there would find it); add it to the include path");
  if (frames_.size() >= options_.limits.max_include_depth) {
    std::string message =
        "#include nested more than " + std::to_string(options_.limits.max_include_depth) + " levels deep";
    for (const auto& open : frames_)
      if (open->path == found->path) {
        message += " (include cycle: '" + found->path + "' includes itself)";
        break;
      }
    budget_.fail(spelled, message);
    return;
  }
  if (found->case_mismatch)
    diags_.warning("include-case-mismatch", spelled,
                   "'" + name + "' matches '" + found->path + "' only when ignoring case");
  includes_.push_back({f.path, found->path, hash.loc});
  if (once_.count(found->path)) return;
  if (!budget_.add_input(found->text.size(), spelled)) return;
  push_file(found->path, std::move(found->text), hash.loc);
}

void Preprocessor::Impl::line_directive(Frame& f, const Token& name) {
  read_line(f);
  if (name.is(TokenKind::integer)) line_.insert(line_.begin(), name);
  const Token& last = line_.empty() ? name : line_.back();
  expanded_.clear();
  engine_.expand_list(line_, expanded_);
  auto digits = [](std::string_view s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
  };
  if (expanded_.empty() || !digits(expanded_[0].text()) || expanded_[0].text().size() > 9 ||
      (expanded_.size() > 1 && !expanded_[1].is(TokenKind::string))) {
    diags_.error("invalid-directive", expanded_.empty() ? name.range() : expanded_[0].range(),
                 "#line expects a line number and an optional \"file name\"");
    return;
  }
  uint32_t line = static_cast<uint32_t>(std::stoul(std::string(expanded_[0].text())));
  std::string file = expanded_.size() > 1 ? unquote(expanded_[1].text()) : "";
  std::string_view text = sm_.buffer_text(f.buffer);
  size_t newline = text.find('\n', sm_.offset_in_buffer(last.loc) + last.text().size());
  if (newline == std::string_view::npos) return;  // nothing follows to renumber
  sm_.add_line_directive(sm_.location(f.buffer, static_cast<uint32_t>(newline + 1)), line, std::move(file));
}

void Preprocessor::Impl::message_directive(Frame& f, const Token& hash, const Token& name) {
  std::string_view rest = f.lexer.rest_of_line();
  // The message is raw text (apostrophes allowed); drop a trailing line comment.
  if (size_t c = rest.find("//"); c != std::string_view::npos && rest.find('"') > c) rest = rest.substr(0, c);
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t' || rest.back() == '\r')) rest.remove_suffix(1);
  std::string message = rest.empty() ? "#" + std::string(name.text()) : std::string(rest);
  SourceRange range{hash.loc, name.range().end};
  if (name.text() == "error") diags_.error("error-directive", range, std::move(message));
  else diags_.warning("warning-directive", range, std::move(message));
}

bool Preprocessor::Impl::condition(Frame& f, const Token& name) {
  read_line(f);
  work_.clear();
  // `defined X` and `defined(X)` are resolved before macro expansion.
  for (size_t i = 0; i < line_.size(); ++i) {
    if (!line_[i].is_identifier("defined")) {
      work_.push_back(line_[i]);
      continue;
    }
    bool paren = i + 1 < line_.size() && line_[i + 1].is(TokenKind::l_paren);
    size_t id = i + (paren ? 2 : 1);
    if (id >= line_.size() || !line_[id].is(TokenKind::identifier) ||
        (paren && (id + 1 >= line_.size() || !line_[id + 1].is(TokenKind::r_paren)))) {
      diags_.error("pp-expression", line_[i].range(), "macro name missing after 'defined'");
      return false;
    }
    work_.push_back(number_token(macros_.find(line_[id].text()) ? "1" : "0", line_[i].loc));
    i = id + (paren ? 1 : 0);
  }
  expanded_.clear();
  engine_.expand_list(work_, expanded_);
  if (budget_.exhausted()) return false;
  return pp::evaluate_condition(expanded_, name.loc, diags_, budget_);
}

void Preprocessor::Impl::open_conditional(Frame& f, const Token& hash, bool value) {
  conditionals_.push_back({hash.loc, value, false});
  if (!value) skip_group(f);
}

Preprocessor::Impl::Conditional* Preprocessor::Impl::current_conditional(Frame& f, const Token& name) {
  if (conditionals_.size() > f.conditional_base) return &conditionals_.back();
  diags_.error(name.text() == "endif" ? "unmatched-endif" : "unmatched-conditional", name.range(),
               "#" + std::string(name.text()) + " without #if");
  return nullptr;
}

// Skips tokens up to the #elif/#else that starts an emitted group or the #endif that ends
// the innermost conditional (which it pops). Nested conditionals are only counted.
void Preprocessor::Impl::skip_group(Frame& f) {
  size_t nested = 0;
  for (;;) {
    if (budget_.exhausted()) return;
    Token t = f.lexer.next();
    forward(f, false);
    if (t.kind == TokenKind::eof) return;  // close_conditionals reports it
    if (!t.is(TokenKind::hash) || !t.at_line_start() || f.lexer.at_line_end()) continue;
    Token name = f.lexer.next();
    forward(f, false);
    std::string_view n = name.is(TokenKind::identifier) ? name.text() : std::string_view();
    if (n == "if" || n == "ifdef" || n == "ifndef") {
      ++nested;
    } else if (n == "endif") {
      if (nested == 0) {
        skip_line(f);
        conditionals_.pop_back();
        return;
      }
      --nested;
    } else if (nested == 0 && (n == "elif" || n == "else")) {
      Conditional& c = conditionals_.back();
      if (c.seen_else) diags_.error("invalid-directive", name.range(), "#" + std::string(n) + " after #else");
      if (n == "else") {
        c.seen_else = true;
        skip_line(f);
        if (!c.taken) return void(c.taken = true);
        continue;
      }
      if (!c.taken && condition(f, name)) return void(c.taken = true);
      continue;
    }
    skip_line(f);
  }
}

void Preprocessor::Impl::close_conditionals(Frame& f) {
  while (conditionals_.size() > f.conditional_base) {
    if (!budget_.exhausted())
      diags_.error("unterminated-conditional", {conditionals_.back().loc, {}}, "unterminated conditional directive");
    conditionals_.pop_back();
  }
}

void Preprocessor::Impl::run_definitions(std::string name, std::string text) {
  push_file(name, std::move(text), {});
  files_.pop_back();  // not a file a reloader could watch
  while (next_file_token().kind != TokenKind::eof) {
  }
  frames_.clear();
}

bool Preprocessor::Impl::run(const std::string& name, std::optional<std::string> text, std::vector<Token>& out) {
  size_t errors_before = diags_.error_count();
  engine_.reset(this);
  macros_.clear();
  budget_.reset();
  frames_.clear();
  conditionals_.clear();
  once_.clear();
  files_.clear();
  includes_.clear();

  for (auto [builtin, spelling] : {std::pair{pp::Builtin::file, "__FILE__"}, std::pair{pp::Builtin::line, "__LINE__"},
                                   std::pair{pp::Builtin::counter, "__COUNTER__"}}) {
    auto m = std::make_unique<Macro>();
    m->name = spelling;
    m->builtin = builtin;
    macros_.define(std::move(m));
  }
  run_definitions("<built-in>", "#define FXKIT 1\n#define FXKIT_VERSION 100\n");
  if (!options_.defines.empty()) {
    std::string defines;
    for (const auto& [n, value] : options_.defines) defines += "#define " + n + " " + value + "\n";
    run_definitions("<command line>", std::move(defines));
  }

  std::string path = text ? name : pp::normalize_path(name);
  if (!text) text = options_.loader(path);
  if (!text) {
    diags_.error("file-not-found", {}, "cannot open '" + name + "'");
    return false;
  }
  if (!budget_.add_input(text->size(), {})) return false;
  size_t size = text->size();
  reserve_with_huge_pages(out, out.size() + size / 3);  // effects average 3-4 bytes per token
  push_file(path, std::move(*text), {});
  BufferId main = frames_.back()->buffer;
  uint64_t emitted = 0;
  for (;;) {
    if (engine_.idle() && emitted < options_.limits.max_tokens) {
      size_t n = copy_plain_tokens(out, options_.limits.max_tokens - emitted);
      emitted += n;
      if (n) continue;
    }
    Token t;
    if (engine_.idle() && !budget_.exhausted()) {
      // MacroEngine::next's hot path, with the file read inlined here.
      t = next_file_token();
      if (t.kind == TokenKind::identifier && !(t.flags & kNoExpand) && macros_.find(t.text()))
        t = engine_.expand_file_token(t);
    } else {
      t = engine_.next();
    }
    if (t.kind == TokenKind::eof) break;
    // A character that starts no token was reported where it was lexed; passing it on
    // would only make the parser report the same mistake again.
    if (t.kind == TokenKind::unknown) continue;
    if (++emitted > options_.limits.max_tokens) {
      budget_.fail(t.range(), "more than " + std::to_string(options_.limits.max_tokens) + " output tokens");
      break;
    }
    if (out.size() == out.capacity()) reserve_with_huge_pages(out, 4 * out.capacity());  // see copy_plain_tokens
    out.push_back(t);
  }
  Token eof;
  eof.flags = kAtLineStart;
  eof.loc = sm_.location(main, static_cast<uint32_t>(size));
  out.push_back(eof);
  engine_.reset(nullptr);
  frames_.clear();
  return diags_.error_count() == errors_before;
}

Preprocessor::Preprocessor(SourceManager& sm, DiagnosticSink& diags, PreprocessorOptions options)
    : impl_(std::make_unique<Impl>(sm, diags, std::move(options))) {}

Preprocessor::~Preprocessor() = default;

bool Preprocessor::run_file(const std::string& path, std::vector<Token>& out) {
  return impl_->run(path, std::nullopt, out);
}

bool Preprocessor::run_buffer(std::string name, std::string text, std::vector<Token>& out) {
  return impl_->run(name, std::move(text), out);
}

const std::vector<std::string>& Preprocessor::files() const { return impl_->files_; }
const std::vector<IncludeEdge>& Preprocessor::includes() const { return impl_->includes_; }

}  // namespace fx
