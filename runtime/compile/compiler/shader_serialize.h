// CompiledShader metadata (entry point, reflection, messages) as JSON for the disk cache.
// Private to runtime/compile.
#pragma once
#include <string>
#include <string_view>

#include "fx/compile/shader_compiler.h"

namespace fx {

// Everything in `shader` except the SPIR-V words and timings.
std::string write_shader_metadata(const CompiledShader& shader);
// Fills `shader` from write_shader_metadata's output; false on malformed input.
bool read_shader_metadata(std::string_view json, CompiledShader& shader);

}  // namespace fx
