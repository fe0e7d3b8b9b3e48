// Folded constants: the typed values of initializers, annotations, state values and
// compile-time shader arguments, and the folder that computes them from ast::Expr.
// Stable: Value, ConstantScope, fold_constant, convert_value.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/ast.h"
#include "fx/diagnostic.h"
#include "fx/model/type.h"

namespace fx {

// A typed constant. Numeric components are flattened in D3D order (vectors x,y,z,w;
// matrices row by row, `m[r][c]` at r*cols+c, whatever the matrix's packing order; arrays
// element by element; structs member by member) and held as doubles: int/uint/bool values
// are exact integers (bool 0/1). Strings carry `text` and TypeClass::string.
struct Value {
  Type type;
  std::vector<double> components;
  std::string text;

  bool is_string() const { return type.cls == TypeClass::string; }
  bool is_numeric() const { return !components.empty() && !is_string(); }
  double number(size_t i = 0) const { return i < components.size() ? components[i] : 0.0; }
  // Components as float / int (truncated as HLSL converts) / bool (non-zero).
  std::vector<float> floats() const;
  std::vector<int32_t> ints() const;
  bool truthy() const { return !components.empty() && components[0] != 0.0; }
  // HLSL-like spelling: `float4(0, 0, 0, 1)`, `3`, `"text"`, `{1, 2}` for arrays/structs.
  std::string to_string() const;
};

Value make_scalar(BaseType base, double v);
Value make_string(std::string text);

// Names a folder may read: `static const` parameters and, where D3D allows, other
// parameters' defaults. Returns nullptr for names it does not know.
using ConstantLookup = std::function<const Value*(std::string_view name)>;

struct ConstantScope {
  ConstantLookup lookup;             // may be empty
  const TypeTable* types = nullptr;  // for constructors and casts of typedef/struct names
};

// Folds an expression to a constant. Literals, constructors (`float4(0,0,0,1)`), `{}`
// lists, unary/binary/ternary arithmetic, comparisons, logic, bit operations, swizzles,
// indexing and casts of constants, and names from `scope`. Reports `division-by-zero`,
// `not-constant`, `bad-swizzle`, `bad-constructor`, `index-out-of-range` and returns
// nullopt. With `quiet`, nothing is reported (used to probe whether a value is constant).
std::optional<Value> fold_constant(const ast::Expr& expr, const ConstantScope& scope, DiagnosticSink& diags,
                                   bool quiet = false);

// Converts a folded value to `target` with D3D initializer rules: a scalar splats to every
// component; `{}` lists and vectors are flattened and must supply exactly the target's
// component count (larger vectors truncate with a `truncated-initializer` warning); ints
// convert to float and floats truncate to int; bools become 0/1. Strings only go to
// strings. Mismatches report `initializer-mismatch` at `where` and return nullopt.
std::optional<Value> convert_value(const Value& value, const Type& target, SourceRange where, DiagnosticSink& diags);

}  // namespace fx
