// Test helpers: lexes a source string straight into the parser (no preprocessor).
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "fx/diagnostic_render.h"
#include "fx/parser.h"

namespace fxtest {

struct Parsed {
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  fx::ast::Effect effect;
  // All diagnostics rendered as clang-style text.
  std::string text() const { return fx::render_text(diags.diagnostics(), sm); }
  const fx::ast::Decl& decl(size_t i) const { return effect.decls.at(i); }
  // The source text a token span covers, tokens joined by single spaces.
  std::string spelled(fx::ast::TokenSpan span) const {
    std::string out;
    for (uint32_t i = span.first; i < span.last; ++i) {
      if (!out.empty()) out += ' ';
      out += effect.tokens.at(i).text();
    }
    return out;
  }
};

inline std::unique_ptr<Parsed> parse(const std::string& source, const char* name = "test.fx",
                                     const fx::ParseOptions& options = {}) {
  auto p = std::make_unique<Parsed>();
  fx::BufferId buffer = p->sm.add_buffer(name, source);
  p->effect = fx::parse_effect(fx::lex_all(p->sm, buffer, p->diags), p->sm, p->diags, options);
  return p;
}

// Declaration `i` of `p`, which must be a variable.
inline const fx::ast::Variable& var(const Parsed& p, size_t i) {
  EXPECT_EQ(p.decl(i).kind, fx::ast::DeclKind::variable);
  return *p.decl(i).variable;
}

}  // namespace fxtest
