// How a symbol of the semantic model reads in hover text and completion details: its
// declaration as written, its kind and owner, and for variables the type, semantic,
// default value and annotations.
#pragma once
#include <string>

#include "document_analysis.h"

namespace fx::tools::lsp {

// One line: "float4 colour (member of Light)".
std::string symbol_detail(const fx::semantic::Symbol& s);
// Markdown: the declaration in a code block, then its facts.
std::string symbol_markdown(const DocumentAnalysis& analysis, const fx::semantic::Symbol& s);

}  // namespace fx::tools::lsp
