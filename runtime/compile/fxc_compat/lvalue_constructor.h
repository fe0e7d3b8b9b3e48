// fxc accepts an assignment to a constructor of l-values, `float4(dxSize, dx) = ddx(v);`
// (the DirectX SDK's parallax occlusion mapping takes two float2 derivatives so); glslang
// does not. The unit writes it as a temporary and one assignment per part instead.
// Private to runtime/compile.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "fx/ast.h"
#include "fx/token.h"

namespace fx::detail {

// One `T(a, b, ...) = value;` statement in a function body, as token indices.
struct LvalueConstructor {
  uint32_t type = 0;        // the vector type token that starts the statement
  uint32_t equal = 0;       // its `=`
  uint32_t semi = 0;        // the `;` that ends it
  std::string temporary;    // the name the rewrite declares
  std::string assignments;  // `a = t.xy; b = t.zw;`
};

// The lvalue constructors in `body` whose parts are variables declared in it (parameters
// and locals) with known sizes that add up to the constructor's.
std::vector<LvalueConstructor> find_lvalue_constructors(const std::vector<Token>& toks, ast::TokenSpan body);

}  // namespace fx::detail
