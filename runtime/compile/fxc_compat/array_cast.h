// fxc casts a vector to an array of its components, `int idx[4] = (int[4])v;` (the DirectX
// SDK's skinning shaders split blend indices and weights so); glslang has no array casts.
// The unit writes such an initializer as the list of the vector's components instead.
// Private to runtime/compile.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "fx/ast.h"
#include "fx/token.h"

namespace fx::detail {

// One `= (T[N]) operand` initializer in a function body, as token indices.
struct ArrayCast {
  uint32_t open = 0;     // the cast's `(`
  uint32_t operand = 0;  // the operand's first token
  uint32_t end = 0;      // the `;` or `,` that ends the initializer
  std::string vector;    // the vector type of N components: "int4"
  uint32_t count = 0;    // N
};

// The array casts in `body` that initialize a declaration: a scalar element type and 1 to 4
// elements, the cast's operand running to the end of the initializer.
std::vector<ArrayCast> find_array_casts(const std::vector<Token>& toks, ast::TokenSpan body);

// `{ ((int4)(v))[0], ((int4)(v))[1], ... }` for the operand spelled `operand`.
std::string array_cast_initializer(const ArrayCast& cast, const std::string& operand);

}  // namespace fx::detail
