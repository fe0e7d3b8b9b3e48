// A JSON summary of what an effect declares: parameters, techniques and passes, with
// their source positions. Used by `fxkit check --json`.
#pragma once
#include <nlohmann/json.hpp>

#include "fx/ast.h"
#include "fx/source_manager.h"

namespace fxkit {

nlohmann::json summarize_effect(const fx::ast::Effect& effect, const fx::SourceManager& sm);

}  // namespace fxkit
