// Renders diagnostics for people (clang-style text) and tools (JSON). Both add the
// include stack ("included from") and macro stack ("in expansion of macro") as notes.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fx/diagnostic.h"
#include "fx/source_manager.h"

namespace fx {

struct TextRenderOptions {
  bool show_source_line = true;  // the line and a caret under the primary range
  bool color = false;
};

// `file:line:col: error: message [id]`, source line, caret, then notes, one per line.
std::string render_text(const Diagnostic& d, const SourceManager& sm, const TextRenderOptions& options = {});
std::string render_text(const std::vector<Diagnostic>& ds, const SourceManager& sm,
                        const TextRenderOptions& options = {});

// {"file","line","column","end":{"line","column"},"severity","id","message",
//  "notes":[{"file","line","column","message"}],"fixits":[{...,"replacement"}]}
nlohmann::json render_json(const Diagnostic& d, const SourceManager& sm);
nlohmann::json render_json(const std::vector<Diagnostic>& ds, const SourceManager& sm);

// The notes a renderer adds for a location: macro expansions innermost first, then the
// include stack innermost first.
std::vector<DiagnosticNote> context_notes(SourceLocation loc, const SourceManager& sm);

}  // namespace fx
