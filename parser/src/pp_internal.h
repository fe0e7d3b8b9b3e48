// Internals of the preprocessor shared by its source files: the macro table, the macro
// expansion engine, the #if evaluator and include path resolution. Not installed.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/name_filter.h"
#include "fx/preprocessor.h"
#include "fx/source_manager.h"
#include "fx/token.h"

namespace fx::pp {

enum class Builtin : uint8_t { none, file, line, counter };

struct Macro {
  std::string_view name;
  SourceLocation name_loc;
  std::vector<Token> body;
  std::vector<int32_t> param_of;  // per body token: index into params, or -1
  std::vector<std::string_view> params;
  SourceLocation body_start;  // first body character: the expansion's spelling
  uint32_t body_length = 0;   // characters from body_start to the end of the body
  Builtin builtin = Builtin::none;
  bool function_like = false;
  bool variadic = false;       // the last parameter is __VA_ARGS__
  bool has_operators = false;  // '#' or '##' in the body: substitution takes the slow path
  bool disabled = false;       // being rescanned: its name must not expand again

  bool same_definition(const Macro& other) const;
};

// Parses the tokens of a `#define` line after the directive name (all on one line).
// Returns nullptr after reporting an error.
std::unique_ptr<Macro> parse_macro_definition(std::span<const Token> line, SourceLocation directive,
                                              DiagnosticSink& diags);

// Macros by name. Replaced and undefined macros stay allocated until clear(), because
// an expansion in progress may still point at them.
class MacroTable {
 public:
  Macro* find(std::string_view name) const {
    // Most identifiers are not macros: the filter answers "no" before hashing the name.
    if (!names_.may_contain(name)) return nullptr;
    auto it = map_.find(name);
    return it == map_.end() ? nullptr : it->second;
  }
  // Every name defined since clear() (undefined ones too) may be in it.
  const NameFilter& names() const { return names_; }
  // Installs `m` and returns the definition it replaces (or nullptr).
  Macro* define(std::unique_ptr<Macro> m);
  bool undefine(std::string_view name) { return map_.erase(name) != 0; }
  void clear();

 private:
  NameFilter names_;
  std::unordered_map<std::string_view, Macro*> map_;
  std::vector<std::unique_ptr<Macro>> storage_;
};

// Shared work counters for one run; a limit hit is reported once and stops everything.
class Budget {
 public:
  Budget(DiagnosticSink& diags, const PreprocessorLimits& limits) : diags_(diags), limits_(limits) {}
  void reset() {
    expansions_ = tokens_ = input_bytes_ = location_space_ = 0;
    exhausted_ = false;
  }
  bool exhausted() const { return exhausted_; }
  const PreprocessorLimits& limits() const { return limits_; }
  // Each returns false (after reporting at `where`) when the limit is exceeded.
  bool add_expansion(SourceRange where);
  bool add_tokens(uint64_t n, SourceRange where);
  bool add_input(uint64_t bytes, SourceRange where);
  bool add_location_space(uint64_t bytes, SourceRange where);
  // Reports a limit hit found elsewhere (include depth, expression nesting).
  void fail(SourceRange where, std::string message);

 private:
  DiagnosticSink& diags_;
  const PreprocessorLimits& limits_;
  uint64_t expansions_ = 0, tokens_ = 0, input_bytes_ = 0, location_space_ = 0;
  bool exhausted_ = false;
};

// Supplies the tokens of the current file, directives already handled; eof at the end.
class FileTokenSource {
 public:
  virtual Token next_file_token() = 0;

 protected:
  ~FileTokenSource() = default;
};

// Copies `text` into scratch space and returns a token spelled by it.
Token scratch_token(SourceManager& sm, Budget& budget, TokenKind kind, std::string_view text, SourceLocation loc,
                    uint8_t flags);
// Kind of a token spelled `text` if it is exactly one preprocessing token.
std::optional<TokenKind> classify_token(std::string_view text);

// Expands macros in tokens coming from the files (level 0) or in standalone token lists
// (the operands of #if, #include, #line, and macro arguments before substitution).
class MacroEngine {
 public:
  MacroEngine(SourceManager& sm, DiagnosticSink& diags, MacroTable& macros, Budget& budget);
  ~MacroEngine();
  void reset(FileTokenSource* files);
  // The next fully expanded token from the files.
  Token next();
  // True when nothing is pending at file level: the next token would come straight from
  // the files, so a driver may read it itself and call expand_file_token only for a
  // macro name (what next() does, without two calls per token).
  bool idle() const;
  // Continues as next() would after reading `name` (a macro name) from the files.
  Token expand_file_token(const Token& name);
  // Appends the expansion of `in` to `out` (nothing beyond `in` is read).
  void expand_list(std::span<const Token> in, std::vector<Token>& out);
  // True while a function-like macro's arguments are being collected from the files.

 private:
  struct Context;
  struct Level;
  Level& level(size_t depth);
  Token next_raw(Level& l);
  Token next_expanded(Level& l);
  bool expand(Level& l, const Token& name, Macro& m);
  bool collect_arguments(Level& l, const Token& name, Macro& m, Token& close);
  void substitute(Level& l, const Token& name, Macro& m, SourceLocation base);
  std::span<const Token> expanded_argument(Level& l, size_t index);
  Token builtin_token(const Token& name, Macro& m);
  Token stringize(std::span<const Token> arg, SourceLocation loc, uint8_t flags);
  void paint(Token& t) const;
  Context& push_context(Level& l, Macro* m);

  SourceManager& sm_;
  DiagnosticSink& diags_;
  MacroTable& macros_;
  Budget& budget_;
  FileTokenSource* files_ = nullptr;
  std::vector<std::unique_ptr<Level>> levels_;
  size_t depth_ = 0;      // levels in use by nested expand_list calls
  size_t disabled_ = 0;   // macros currently disabled
  uint32_t counter_ = 0;  // __COUNTER__
  std::string scratch_;
};

struct MacroEngine::Context {
  Macro* macro = nullptr;  // nullptr for a standalone list
  std::vector<Token> tokens;
  size_t pos = 0;
};

struct MacroEngine::Level {
  std::vector<Context> contexts;  // [0, active) in use; the rest keep their capacity
  size_t active = 0;
  std::vector<Token> pushback;
  bool from_files = false;
  // The invocation being substituted at this level.
  std::vector<Token> args;
  std::vector<uint32_t> arg_begin;  // argument i is args[arg_begin[i], arg_begin[i + 1])
  std::vector<Token> expanded;      // fully expanded arguments, computed on first use
  std::vector<uint32_t> expanded_begin, expanded_end;
  std::vector<Token> build;
};

inline bool MacroEngine::idle() const { return levels_[0]->pushback.empty() && levels_[0]->active == 0; }

// Evaluates the macro-expanded tokens of an #if/#elif line. `defined` must already be
// resolved. Reports `pp-expression` errors and treats a failed expression as false.
bool evaluate_condition(std::span<const Token> tokens, SourceLocation directive, DiagnosticSink& diags, Budget& budget);

// Path helpers for #include: '/' separators, "." and ".." removed lexically.
std::string normalize_path(std::string_view path);
std::string parent_folder(std::string_view path);
std::string join_path(std::string_view folder, std::string_view name);

// Whether an include name is a relative path through folders ("Data/Effects/x.fx"), the form
// an engine writes relative to the folder it runs from; not "./x" or "../x".
bool names_a_folder(std::string_view name);
// The folders above `folder`, nearest first, at most `levels` ("a/b" -> "a", "", "..", ...).
std::vector<std::string> ancestor_folders(std::string_view folder, size_t levels);

// Where an include resolved: the normalized path, its text, and whether only a
// case-insensitive match was found.
struct ResolvedInclude {
  std::string path;
  std::string text;
  bool case_mismatch = false;
};
// Tries each folder in order: exact matches everywhere first, then the case-insensitive
// fallback (when `lister` is set).
std::optional<ResolvedInclude> resolve_include(std::string_view name, const std::vector<std::string>& folders,
                                               const FileLoader& loader, const DirectoryLister& lister);

// An include found nowhere, said helpfully: the name as it could be reached with the
// closest file name in the folders searched (swaps and one-letter slips; "" when none is
// near), and the folders, as written ("." for the working directory).
struct MissingInclude {
  std::string near;
  std::vector<std::string> searched;
};
MissingInclude describe_missing_include(std::string_view name, const std::vector<std::string>& folders,
                                        const DirectoryLister& lister);

}  // namespace fx::pp
