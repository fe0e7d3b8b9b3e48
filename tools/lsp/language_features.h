// The language features over one analysis, one file each: diagnostics for the document,
// hover, go-to-definition, references, code actions, the document's outline and completion. Each returns the LSP
// result as JSON (null where the protocol allows "nothing here").
#pragma once
#include <nlohmann/json.hpp>

#include "document_analysis.h"
#include "text_document.h"

namespace fx::tools::lsp {

// The analysis's diagnostics as LSP Diagnostics of `document`: those in included files sit
// on the `#include` line that brings them in, with the include stack as related information.
json document_diagnostics(const DocumentAnalysis& analysis);
// Other diagnostics (the compiled shaders'), placed in the sources that reported them, alike.
json document_diagnostics(const DocumentPlaces& places, const std::vector<fx::Diagnostic>& diagnostics);
// Hover: a declaration with its type, semantic, default and annotations; a state with its
// allowed values and Vulkan mapping; an intrinsic's signature; a macro's definition.
json hover(const DocumentAnalysis& analysis, const TextDocument& document, Position at);
// The declaration of what is at `at` (across includes; a pass's shader entry, a macro, an
// included file).
json definition(const DocumentAnalysis& analysis, const TextDocument& document, Position at);
// Every place naming the symbol at `at` (across includes; passes naming a shader entry or
// a parameter), with its declaration first when `include_declaration`.
json references(const DocumentAnalysis& analysis, Position at, bool include_declaration);
// The fix-its of the diagnostics under `range` (an LSP Range) as quick-fix CodeActions.
json code_actions(const DocumentAnalysis& analysis, const TextDocument& document, const json& range);
// Techniques with their passes, parameters, functions, structs with their members, cbuffers.
json document_symbols(const DocumentAnalysis& analysis);
// State names and values inside passes and state blocks; elsewhere the names in scope
// (members after `.`), intrinsics and built-in types.
json completion(const DocumentAnalysis& analysis, const TextDocument& document, Position at);

}  // namespace fx::tools::lsp
