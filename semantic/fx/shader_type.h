// Types of shader-code values, as far as hover, go-to-definition and completion need them:
// scalars, vectors and matrices by their built-in names, structs by their declaration,
// resource objects (textures, samplers, buffers) by name, arrays by rank. No conversions
// or overloads: that is the shader compiler's business.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "fx/ast.h"

namespace fx::semantic {

enum class TypeClass : uint8_t { unknown, scalar, vector, matrix, structure, object };

struct ShaderType {
  TypeClass kind = TypeClass::unknown;
  std::string name;                        // as written ("float4", "Light", "Texture2D<float4>")
  std::string_view scalar;                 // scalar, vector, matrix: "float", "half", "int", ...
  uint8_t rows = 1, columns = 1;           // vector: columns is its size; matrix: rows x columns
  const ast::Struct* structure = nullptr;  // structure: its declaration
  uint32_t array_rank = 0;                 // `float4 a[4][2]`: 2

  bool known() const { return kind != TypeClass::unknown; }
  // The type as a declaration writes it, with one `[]` per array dimension.
  std::string spelling() const;
};

// A built-in scalar, vector or matrix type name (`float`, `half3`, `int2x2`, `dword`),
// or nullopt.
std::optional<ShaderType> builtin_numeric_type(std::string_view name);
// A resource or shader object type name: textures, samplers, buffers, streams, patches,
// shader types (`texture2D`, `Texture2D`, `sampler`, `SamplerState`, `RWBuffer`, ...).
bool is_object_type_name(std::string_view name);
// Object and vector/matrix type names that take `<...>` arguments in shader code.
bool takes_template_arguments(std::string_view name);
// The type of `base.swizzle` for a scalar, vector or matrix base (`v.xyz`, `c.rgba`,
// `m._m00_m11`, `m._11`), or nullopt when `swizzle` is no valid swizzle of `base`.
std::optional<ShaderType> swizzle_type(const ShaderType& base, std::string_view swizzle);
// The type of `value[i]`: an array's element, a vector's scalar, a matrix's row; unknown
// for anything else.
ShaderType element_type(const ShaderType& value);

}  // namespace fx::semantic
