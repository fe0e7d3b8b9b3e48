// Where the effect's source locations are in an open document's terms: LSP positions,
// ranges and locations of fx::SourceLocations, for any SourceManager that read the document
// (a DocumentAnalysis's, or the EffectFile of a compile).
#pragma once
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "fx/source_manager.h"
#include "text_document.h"

namespace fx::tools::lsp {

using json = nlohmann::json;

class DocumentPlaces {
 public:
  // `sm` (which must outlive this) read the document at `path` and its includes.
  DocumentPlaces(const fx::SourceManager& sm, std::string path) : sm_(&sm), path_(std::move(path)) {}

  const std::string& path() const { return path_; }
  const fx::SourceManager& sources() const { return *sm_; }
  // LSP position and range of a location (its file location, for macro expansions).
  Position position_of(fx::SourceLocation loc) const;
  json range_json(fx::SourceRange range) const;
  // An LSP Location: uri and range.
  json location_json(fx::SourceRange range) const;
  // The file a location is in (after following macro expansions to the invocation).
  std::string file_of(fx::SourceLocation loc) const;
  bool in_document(fx::SourceLocation loc) const { return file_of(loc) == path_; }
  // The source text of a range within one file ("" when it spans files).
  std::string_view text_of(fx::SourceRange range) const;

 private:
  const fx::SourceManager* sm_;
  std::string path_;
};

}  // namespace fx::tools::lsp
