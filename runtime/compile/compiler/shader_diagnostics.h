// glslang's diagnostics of one stage, made to read like the front end's: one error per parse
// failure at its column, the column of the token a message names, "did you mean" for an
// unknown name from the effect's own symbols, and the follow-on errors of an unknown name
// dropped. Private to runtime/compile.
#pragma once
#include <string>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/source_manager.h"

namespace fx::detail {

void refine_shader_diagnostics(std::vector<Diagnostic>& diagnostics, const SourceManager& sm,
                               const std::vector<std::string>& symbols);

}  // namespace fx::detail
