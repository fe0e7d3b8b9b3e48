// Where a translation unit's entry point is defined, in the .fx file its #line directives
// name: the place a failure of the whole unit (a compiler crash) is reported at.
// Private to runtime/compile.
#pragma once
#include "fx/compile/shader_message.h"
#include "fx/compile/translation_unit.h"

namespace fx {

// The file, line and column of the entry point's definition (a line `type Entry(`), else of
// the unit's first line; severity and text are left for the caller.
ShaderMessage entry_location(const TranslationUnit& unit);

}  // namespace fx
