// One analysis of an open effect: the front end (preprocess, parse, check) and the
// semantic model run on the editor's text, with included files read from the editor's
// buffers when open and from disk otherwise, and the mapping between the document's
// positions and the effect's tokens that the requests use.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "document_places.h"
#include "fx/frontend.h"
#include "fx/semantic_model.h"
#include "text_document.h"
#include "workspace_config.h"

namespace fx::tools::lsp {

using json = nlohmann::json;

// A `#define` found in the effect's files.
struct MacroDefinition {
  std::string name;
  std::string line;  // the directive as written (first line)
  fx::SourceLocation at;
};

// The places of its locations (DocumentPlaces) are those of its own sources.
class DocumentAnalysis : public DocumentPlaces {
 public:
  // Analyzes `document`; `open` maps paths to the texts of every open document.
  DocumentAnalysis(const TextDocument& document, const WorkspaceConfig& config,
                   const std::map<std::string, std::string>& open);

  int64_t version() const { return version_; }
  const fx::ParsedEffect& parsed() const { return parsed_; }
  const fx::semantic::SemanticModel& model() const { return *model_; }
  // The front end's diagnostics followed by the semantic model's.
  const std::vector<fx::Diagnostic>& diagnostics() const { return diags_.diagnostics(); }
  const std::vector<MacroDefinition>& macros() const { return macros_; }

  // The token of the document at `p` (a position inside a token or just after an
  // identifier), or nullopt. Tokens made by macro expansion have no place of their own.
  std::optional<uint32_t> token_at(Position p) const;
  // What the identifier at `p` names: its reference in a function body, else (a pass's
  // `compile vs_2_0 VS()`, `<Texture>`, a state object) the global of that name; or nullptr.
  const fx::semantic::Symbol* symbol_at(Position p) const;
  // The last token of the document that starts before `p`.
  std::optional<uint32_t> token_before(Position p) const;
  // A macro defined in the effect's files under `name`, or nullptr (the last definition).
  const MacroDefinition* macro(std::string_view name) const;
  // Builds the index of the document's tokens by position that token_at and token_before
  // read (once; they build it on first use otherwise). The server builds it right after
  // publishing diagnostics, so the first request after an edit does not wait for it.
  void index_tokens() const;

 private:
  struct TokenPlace {
    uint32_t line, character, length;  // LSP line and UTF-16 column; length in UTF-16 units
    uint32_t token;
  };
  void find_macros();

  int64_t version_ = 0;
  fx::SourceManager sm_;  // the base refers to it: it must not move
  fx::DiagnosticSink diags_;
  fx::ParsedEffect parsed_;
  std::unique_ptr<fx::semantic::SemanticModel> model_;
  std::vector<MacroDefinition> macros_;
  mutable std::vector<TokenPlace> places_;  // the document's tokens in order, built on first use
  mutable bool indexed_ = false;
};

}  // namespace fx::tools::lsp
