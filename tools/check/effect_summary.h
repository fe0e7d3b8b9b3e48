// A JSON summary of what an effect declares: parameters, techniques and passes, with
// their source positions. Used by `fxkit check --json`.
#pragma once
#include <nlohmann/json.hpp>

#include "fx/ast.h"
#include "fx/source_manager.h"

namespace fx::tools {

nlohmann::json summarize_effect(const fx::ast::Effect& effect, const fx::SourceManager& sm);

// What every fxkit JSON output (`check --json`, `info --json`) writes for these, so that one
// reader serves both (docs/info-json-schema.md, "Shared forms"):
// a declaration's place, {"file", "line", "column"} of its name (1-based; null when unknown),
nlohmann::json source_location(const fx::SourceManager& sm, fx::SourceRange range);
// and an annotation's value as JSON: a string without its quotes, a number, a bool; null for
// lists and constructors.
nlohmann::json annotation_value(const fx::ast::Expr* e);

}  // namespace fx::tools
