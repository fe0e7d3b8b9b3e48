// Built-in shader types by name, swizzles and element types (fx/shader_type.h).
#include "fx/shader_type.h"

#include <algorithm>
#include <array>
#include <cctype>

#include "fx/ascii_case.h"

namespace fx::semantic {
namespace {

constexpr std::array<std::string_view, 18> kScalars = {
    "bool",     "int",      "uint",      "dword",   "half",     "float",   "double",   "min16float", "min10float",
    "min16int", "min12int", "min16uint", "int16_t", "uint16_t", "int64_t", "uint64_t", "float16_t",  "float32_t"};

// Lower-case names; shader code spells them in either case (`texture2D`, `Texture2D`).
constexpr std::array<std::string_view, 47> kObjects = {"computeshader",
                                                       "domainshader",
                                                       "hullshader",
                                                       "depthstencilview",
                                                       "rendertargetview",
                                                       "stateblock",
                                                       "texture",
                                                       "texture1d",
                                                       "texture2d",
                                                       "texture3d",
                                                       "texturecube",
                                                       "texture1darray",
                                                       "texture2darray",
                                                       "texture2dms",
                                                       "texture2dmsarray",
                                                       "texturecubearray",
                                                       "sampler",
                                                       "sampler1d",
                                                       "sampler2d",
                                                       "sampler3d",
                                                       "samplercube",
                                                       "sampler_state",
                                                       "samplerstate",
                                                       "samplercomparisonstate",
                                                       "buffer",
                                                       "rwbuffer",
                                                       "structuredbuffer",
                                                       "rwstructuredbuffer",
                                                       "appendstructuredbuffer",
                                                       "consumestructuredbuffer",
                                                       "byteaddressbuffer",
                                                       "rwbyteaddressbuffer",
                                                       "rwtexture1d",
                                                       "rwtexture1darray",
                                                       "rwtexture2d",
                                                       "rwtexture2darray",
                                                       "rwtexture3d",
                                                       "inputpatch",
                                                       "outputpatch",
                                                       "pointstream",
                                                       "linestream",
                                                       "trianglestream",
                                                       "vertexshader",
                                                       "pixelshader",
                                                       "geometryshader",
                                                       "string",
                                                       "void"};

bool swizzle_letters(std::string_view s, std::string_view set, uint8_t size) {
  if (s.empty() || s.size() > 4) return false;
  for (char c : s) {
    size_t at = set.find(c);
    if (at == std::string_view::npos || at >= size) return false;
  }
  return true;
}

// `_m00_m11` (zero-based) or `_11_22` (one-based) components of a rows x columns matrix.
size_t matrix_swizzle_size(std::string_view s, uint8_t rows, uint8_t columns) {
  size_t count = 0;
  while (!s.empty()) {
    if (s[0] != '_') return 0;
    const bool zero_based = s.size() >= 4 && s[1] == 'm';
    const size_t at = zero_based ? 2 : 1;
    if (s.size() < at + 2 || !isdigit(static_cast<unsigned char>(s[at])) ||
        !isdigit(static_cast<unsigned char>(s[at + 1])))
      return 0;
    const int base = zero_based ? 0 : 1;
    const int r = s[at] - '0' - base, c = s[at + 1] - '0' - base;
    if (r < 0 || c < 0 || r >= rows || c >= columns) return 0;
    ++count;
    s.remove_prefix(at + 2);
  }
  return count <= 4 ? count : 0;
}

ShaderType numeric(std::string_view scalar, uint8_t rows, uint8_t columns, TypeClass kind) {
  ShaderType t;
  t.kind = kind;
  t.scalar = scalar;
  t.rows = rows;
  t.columns = columns;
  t.name = std::string(scalar);
  if (kind == TypeClass::vector) t.name += std::to_string(columns);
  if (kind == TypeClass::matrix) t.name += std::to_string(rows) + "x" + std::to_string(columns);
  return t;
}

}  // namespace

std::string ShaderType::spelling() const {
  std::string s = name.empty() ? std::string("?") : name;
  for (uint32_t i = 0; i < array_rank; ++i) s += "[]";
  return s;
}

std::optional<ShaderType> builtin_numeric_type(std::string_view name) {
  for (std::string_view scalar : kScalars) {
    if (!name.starts_with(scalar)) continue;
    std::string_view dims = name.substr(scalar.size());
    auto digit = [](char c) { return c >= '1' && c <= '4'; };
    if (dims.empty()) return numeric(scalar, 1, 1, TypeClass::scalar);
    if (dims.size() == 1 && digit(dims[0]))
      return numeric(scalar, 1, static_cast<uint8_t>(dims[0] - '0'), TypeClass::vector);
    if (dims.size() == 3 && digit(dims[0]) && dims[1] == 'x' && digit(dims[2]))
      return numeric(scalar, static_cast<uint8_t>(dims[0] - '0'), static_cast<uint8_t>(dims[2] - '0'),
                     TypeClass::matrix);
  }
  return std::nullopt;
}

bool is_object_type_name(std::string_view name) {
  if (name.size() > 32) return false;
  std::string lower = ascii_lower(name);
  return std::find(kObjects.begin(), kObjects.end(), lower) != kObjects.end();
}

bool takes_template_arguments(std::string_view name) {
  return name == "vector" || name == "matrix" ||
         (is_object_type_name(name) && !iequals(name, "string") && !iequals(name, "void") &&
          !iequals(name, "sampler_state"));
}

std::optional<ShaderType> swizzle_type(const ShaderType& base, std::string_view swizzle) {
  if (base.array_rank != 0) return std::nullopt;
  if (base.kind == TypeClass::scalar || base.kind == TypeClass::vector) {
    const uint8_t size = base.columns;
    if (!swizzle_letters(swizzle, "xyzw", size) && !swizzle_letters(swizzle, "rgba", size)) return std::nullopt;
    const auto n = static_cast<uint8_t>(swizzle.size());
    return numeric(base.scalar, 1, n, n == 1 ? TypeClass::scalar : TypeClass::vector);
  }
  if (base.kind == TypeClass::matrix) {
    const auto n = static_cast<uint8_t>(matrix_swizzle_size(swizzle, base.rows, base.columns));
    if (n == 0) return std::nullopt;
    return numeric(base.scalar, 1, n, n == 1 ? TypeClass::scalar : TypeClass::vector);
  }
  return std::nullopt;
}

ShaderType element_type(const ShaderType& value) {
  if (value.array_rank != 0) {
    ShaderType e = value;
    --e.array_rank;
    return e;
  }
  if (value.kind == TypeClass::vector) return numeric(value.scalar, 1, 1, TypeClass::scalar);
  if (value.kind == TypeClass::matrix) return numeric(value.scalar, 1, value.columns, TypeClass::vector);
  return {};
}

}  // namespace fx::semantic
