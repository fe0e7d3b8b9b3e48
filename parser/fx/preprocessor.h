// The C preprocessor for effect files: #include with search paths, object- and
// function-like macros, conditionals, #line, and the directives the shader compiler needs
// to see again (#pragma, #version, #extension). Output is a token vector for the parser.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/source_manager.h"
#include "fx/token.h"

namespace fx {

// Reads a whole file (paths use '/'); nullopt when it does not exist or is not a file.
using FileLoader = std::function<std::optional<std::string>(const std::string& path)>;
// Names of the entries of a folder ("" is the current folder); empty if it cannot be listed.
// Only used for the case-insensitive #include fallback.
using DirectoryLister = std::function<std::vector<std::string>(const std::string& folder)>;

// The default hooks: the real file system.
FileLoader disk_file_loader();
DirectoryLister disk_directory_lister();

// Bounds that keep hostile or broken input from hanging or exhausting memory. Exceeding
// one is a `limit-exceeded` error and stops preprocessing.
struct PreprocessorLimits {
  uint32_t max_include_depth = 200;
  uint32_t max_macro_expansions = 1u << 18;  // per run, every macro invocation counts
  uint64_t max_tokens = 1u << 24;            // output tokens, and tokens built by expansion
  uint64_t max_input_bytes = 64u << 20;      // all files read in one run
  uint32_t max_nesting = 256;                // #if sub-expressions, nested macro arguments
};

struct PreprocessorOptions {
  std::vector<std::string> include_dirs;  // searched in order (after the includer's folder)
  // Each pair is `#define first second`; see parse_define for the `-D` syntax.
  std::vector<std::pair<std::string, std::string>> defines;
  FileLoader loader;       // empty: disk_file_loader()
  DirectoryLister lister;  // empty: the disk when `loader` is empty, else no case fallback
  PreprocessorLimits limits;
};

// Splits a `-D` argument: "NAME" -> {NAME, "1"}, "NAME=VALUE" -> {NAME, VALUE}.
std::pair<std::string, std::string> parse_define(std::string_view arg);

// One `#include` that was resolved: the including and the included file.
struct IncludeEdge {
  std::string includer, included;
  SourceLocation at;  // the `#` of the directive
};

class Preprocessor {
 public:
  Preprocessor(SourceManager& sm, DiagnosticSink& diags, PreprocessorOptions options = {});
  ~Preprocessor();
  Preprocessor(const Preprocessor&) = delete;
  Preprocessor& operator=(const Preprocessor&) = delete;

  // Preprocesses a file and appends its tokens to `out`, ending with one eof token.
  // Each run starts from the predefined macros and options.defines alone. Returns false
  // if any error was reported during the run.
  bool run_file(const std::string& path, std::vector<Token>& out);
  // The same for text in memory; `name` is its file name for diagnostics and for
  // resolving quoted includes against its folder.
  bool run_buffer(std::string name, std::string text, std::vector<Token>& out);

  // Every file read by the last run (normalized paths, first read first), and the include
  // graph between them: what a hot reloader watches.
  const std::vector<std::string>& files() const;
  const std::vector<IncludeEdge>& includes() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fx
