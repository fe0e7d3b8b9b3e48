// Turns glslang's TProgram reflection (plus the SPIR-V words, for HLSL semantics) into
// fx::ShaderReflection. Private to runtime/compile.
#pragma once
#include <cstdint>
#include <vector>

#include <glslang/Public/ShaderLang.h>

#include "fx/compile/shader_reflection.h"

namespace fx {

// Glslang reflection options fxkit uses: all block members (parameters that a pass does not
// read still have a place in the buffer) and storage buffers kept apart from uniform blocks.
constexpr int kReflectionOptions = EShReflectionSeparateBuffers | EShReflectionAllBlockVariables |
                                   EShReflectionIntermediateIO | EShReflectionAllIOVariables;

// Reads `program` (linked, buildReflection(kReflectionOptions) done) for `stage`. `spirv`
// supplies HLSL input semantics; call it before stripping them.
ShaderReflection reflect_program(const glslang::TProgram& program, EShLanguage stage,
                                 const std::vector<uint32_t>& spirv);

}  // namespace fx
