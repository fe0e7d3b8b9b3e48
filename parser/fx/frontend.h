// The whole front end in one call: preprocess, parse, check. What `fxkit check`, the
// effect compiler and the hot reloader run on an effect file.
#pragma once
#include <string>
#include <vector>

#include "fx/ast.h"
#include "fx/checker.h"
#include "fx/diagnostic.h"
#include "fx/parser.h"
#include "fx/preprocessor.h"
#include "fx/source_manager.h"

namespace fx {

struct FrontEndOptions {
  PreprocessorOptions preprocessor;
  ParseOptions parse;
  CheckOptions check;
};

// A parsed and checked effect, with the files it was read from.
struct ParsedEffect {
  ast::Effect ast;
  std::vector<std::string> files;     // the effect file first, then every include
  std::vector<IncludeEdge> includes;  // include graph (for hot reload)
  bool ok = false;                    // no errors reported by this load
};

// Reads `path` (through options.preprocessor.loader) and runs the front end on it.
ParsedEffect parse_effect_file(const std::string& path, SourceManager& sm, DiagnosticSink& diags,
                               const FrontEndOptions& options = {});
// The same for text in memory named `name` (includes resolve against its folder).
ParsedEffect parse_effect_text(std::string name, std::string text, SourceManager& sm, DiagnosticSink& diags,
                               const FrontEndOptions& options = {});

}  // namespace fx
