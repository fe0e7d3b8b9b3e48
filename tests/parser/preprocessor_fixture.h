// Shared by the preprocessor suites: a preprocessor over virtual files, and the expected
// output of a test lexed and respelled the same way.
#pragma once
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "../support/patience.h"
#include "fx/diagnostic_render.h"
#include "fx/lexer.h"
#include "fx/preprocessor.h"

namespace fx::test {

// A preprocessor over virtual files (the loader and lister hooks).
struct Pp {
  SourceManager sm;
  DiagnosticSink diags;
  std::map<std::string, std::string> files;
  PreprocessorOptions options;
  std::vector<Token> tokens;
  std::vector<std::string> read_files;
  std::vector<IncludeEdge> edges;
  bool ok = false;

  Pp() {
    options.loader = [this](const std::string& path) -> std::optional<std::string> {
      auto it = files.find(path);
      if (it == files.end()) return std::nullopt;
      return it->second;
    };
    options.lister = [this](const std::string& folder) {
      std::set<std::string> names;
      std::string prefix = folder.empty() ? "" : folder + "/";
      for (const auto& [path, text] : files)
        if (path.compare(0, prefix.size(), prefix) == 0) {
          std::string rest = path.substr(prefix.size());
          names.insert(rest.substr(0, rest.find('/')));
        }
      return std::vector<std::string>(names.begin(), names.end());
    };
  }
  // Preprocesses `text` as main.fx; returns the spellings joined by single spaces.
  std::string run(std::string text, std::string name = "main.fx") {
    tokens.clear();
    Preprocessor pp(sm, diags, options);
    ok = pp.run_buffer(std::move(name), std::move(text), tokens);
    read_files = pp.files();
    edges = pp.includes();
    return spell(tokens);
  }
  static std::string spell(const std::vector<Token>& ts) {
    std::string s;
    for (const Token& t : ts) {
      if (t.is(TokenKind::eof)) break;
      if (!s.empty()) s.push_back(' ');
      s.append(t.text());
    }
    return s;
  }
  std::string ids() const {
    std::string s;
    for (const Diagnostic& d : diags.diagnostics()) s += (s.empty() ? "" : " ") + d.id;
    return s;
  }
  const Diagnostic& only() const {
    EXPECT_EQ(diags.diagnostics().size(), 1u) << render_text(diags.diagnostics(), sm);
    return diags.diagnostics().at(0);
  }
  std::string where(SourceLocation loc) const {
    PresumedLocation p = sm.presumed(loc);
    return std::string(p.file) + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
  }
};

// The expected output of a test, lexed and respelled the same way as the output.
inline std::string spelled(std::string text) {
  SourceManager sm;
  DiagnosticSink diags;
  Lexer lexer(sm, sm.add_buffer("expected", std::move(text)), diags);
  std::vector<Token> ts;
  for (Token t = lexer.next(); !t.is(TokenKind::eof); t = lexer.next()) ts.push_back(t);
  return Pp::spell(ts);
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Catches a hang only (a limit that no longer stops the work), never slowness: a loaded
// 2-core CI machine must not fail a unit test. What the limits bound is checked by counts
// (tokens, include depth); speed is measured by `fxkit bench frontend`. Sanitizer builds
// run several times slower (FXKIT_TEST_SLOWDOWN, tests/CMakeLists.txt).
constexpr double kHangSeconds = 20.0 * FXKIT_TEST_SLOWDOWN;

}  // namespace fx::test
