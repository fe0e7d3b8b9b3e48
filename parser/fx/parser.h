// Parses a preprocessed token stream into the effect syntax tree (fx/ast.h). Effect
// syntax (parameters, annotations, techniques, passes, state objects) is parsed fully;
// shader code (function bodies, asm, GLSL blocks) is kept as token spans.
#pragma once
#include <cstddef>
#include <vector>

#include "fx/ascii_case.h"
#include "fx/ast.h"
#include "fx/diagnostic.h"
#include "fx/source_manager.h"
#include "fx/token.h"

namespace fx {

struct ParseOptions {
  // Deepest nesting of parentheses, braces, template arguments and unary operators in
  // effect expressions; deeper input gets one `nesting-too-deep` error, never a crash.
  size_t max_nesting = 256;
};

// Parses `tokens` (ending in TokenKind::eof; one is appended if missing). Errors are
// reported into `diags`; the returned Effect holds every declaration that parsed, and
// owns the tokens its TokenSpans index.
ast::Effect parse_effect(std::vector<Token> tokens, const SourceManager& sm, DiagnosticSink& diags,
                         const ParseOptions& options = {});

// Lexes a whole buffer without preprocessing (tests, tools that skip the preprocessor).
// The result ends with the eof token. Characters that start no token are reported and left
// out, as the preprocessor leaves them out: the parser would only report them again.
std::vector<Token> lex_all(SourceManager& sm, BufferId buffer, DiagnosticSink& diags);

}  // namespace fx
