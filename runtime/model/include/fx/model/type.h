// Semantic types of effect parameters: ast::TypeRef (as written) resolved to scalar,
// vector, matrix, array, struct, string, texture, sampler, shader and state-object types.
// Stable: the Type fields and TypeTable::resolve. Parameter stores, reflection matching and
// `fxkit info` read these.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/ast.h"
#include "fx/diagnostic.h"

namespace fx {

// The class of a type.
enum class TypeClass : uint8_t {
  error,  // could not be resolved (a diagnostic was reported)
  void_type,
  scalar,
  vector,
  matrix,
  structure,
  string,
  texture,       // texture, texture2D, Texture2D<float4>, ...
  sampler,       // sampler, sampler2D, SamplerState, ...
  shader,        // VertexShader / PixelShader / ... variables
  state_object,  // BlendState, DepthStencilState, RasterizerState objects
  view,          // D3D11 buffers and unordered-access views: StructuredBuffer<T>, RWTexture2D<T>, ...
};

// Component type of scalars, vectors and matrices. DWORD is uint.
enum class BaseType : uint8_t { boolean, int32, uint32, half, float32, float64 };

// Texture shapes. `texture` (D3D9, untyped) is `any`.
enum class TextureShape : uint8_t {
  any,
  tex1d,
  tex2d,
  tex3d,
  cube,
  tex1d_array,
  tex2d_array,
  tex2dms,
  tex2dms_array,
  cube_array,
  buffer,
};

// D3D11 resource views that are not sampled textures (TypeClass::view); `Buffer<T>` is a
// texture of shape `buffer`. Their element type is Type::element.
enum class ViewKind : uint8_t {
  structured_buffer,
  rw_structured_buffer,
  append_structured_buffer,
  consume_structured_buffer,
  byte_address_buffer,
  rw_byte_address_buffer,
  rw_buffer,
  rw_texture1d,
  rw_texture1d_array,
  rw_texture2d,
  rw_texture2d_array,
  rw_texture3d,
};

// Sampler kinds; sampler_object covers D3D10 SamplerState, comparison SamplerComparisonState.
enum class SamplerShape : uint8_t {
  any,
  s1d,
  s2d,
  s3d,
  cube,
  sampler_object,
  comparison,
};

// How a matrix is packed in a constant buffer, in HLSL terms (the row_major/column_major
// keywords): column_major (the fxc default) stores each HLSL column in one 16-byte register.
// Not the order of the application's floats: that is fxkit::MatrixOrder.
enum class MatrixPacking : uint8_t { column_major, row_major };

struct StructType;
struct ConstantScope;  // fx/model/value.h

// A resolved type. Vectors have rows == 1, cols == N; matrices rows x cols as in
// `float3x4` (3 rows, 4 columns). Arrays wrap any element type (array_dims outermost first).
struct Type {
  TypeClass cls = TypeClass::error;
  BaseType base = BaseType::float32;
  uint8_t rows = 1, cols = 1;
  MatrixPacking order = MatrixPacking::column_major;  // matrices only
  std::vector<uint32_t> array_dims;                   // `float a[4][2]` -> {4, 2}
  std::shared_ptr<const StructType> structure;        // TypeClass::structure
  TextureShape texture = TextureShape::any;
  SamplerShape sampler = SamplerShape::any;
  ViewKind view = ViewKind::structured_buffer;  // TypeClass::view
  std::string object_kind;                      // shader / state_object: "VertexShader", "BlendState", ...
  std::string element;                          // texture or view template argument (`Texture2D<float4>` -> "float4")

  bool is_numeric() const { return cls == TypeClass::scalar || cls == TypeClass::vector || cls == TypeClass::matrix; }
  bool is_array() const { return !array_dims.empty(); }
  // Product of the array dimensions (1 when not an array).
  uint32_t element_count() const;
  // Scalars in one element: rows*cols for numerics, the members' total for structs, 1 else.
  uint32_t element_components() const;
  // element_components() * element_count().
  uint32_t component_count() const;
  // The type of one array element (drops the outermost dimension).
  Type element_type() const;
  // The same type without any array dimensions.
  Type without_arrays() const;
  // HLSL spelling: "float4x4", "float3[4]", "Texture2D<float4>", "struct Light".
  std::string to_string() const;
  // Same shape, base, struct and object kind (matrix order ignored).
  bool same_as(const Type& other) const;
};

struct StructMember {
  std::string name;
  Type type;
  std::string semantic;
  uint32_t component_offset = 0;  // scalars before this member in the flattened struct
};

struct StructType {
  std::string name;
  std::vector<StructMember> members;
  uint32_t components = 0;  // flattened scalar count
  const StructMember* find(std::string_view name) const;
};

// A scalar/vector/matrix type of the given shape.
Type make_numeric(BaseType base, uint8_t rows = 1, uint8_t cols = 1);
// Spelling of a base type: "bool", "int", "uint", "half", "float", "double".
std::string_view to_string(BaseType base);

// Structs and typedefs declared in an effect, and the resolution of type names.
class TypeTable {
 public:
  // Declares `ast::Struct` (members resolved now; later redefinitions are reported).
  void add_struct(const ast::Struct& decl, DiagnosticSink& diags, const ConstantScope* scope = nullptr);
  // Declares `typedef T name[dims];` (dims must fold to integers; reported otherwise).
  void add_typedef(const ast::Typedef& decl, DiagnosticSink& diags, const ConstantScope* scope = nullptr);
  // Array dimensions fold through `scope` (`float a[N]` with `static const int N`).
  // Resolves a type as written plus the declaration's storage (row_major/column_major)
  // and array dimensions. Unknown names -> `unknown-type` with a did-you-mean;
  // bad dimensions -> `bad-array-size`. Returns TypeClass::error after a diagnostic.
  // `initializer_scalars`: the scalars of the declaration's folded initializer, which size
  // an unsized outermost dimension (`float2 a[] = { ... };`, as fxc); without one such a
  // dimension is `bad-array-size`.
  Type resolve(const ast::TypeRef& ref, uint32_t storage, const ast::List<ast::ExprPtr>& dims, DiagnosticSink& diags,
               const ConstantScope* scope = nullptr, std::optional<uint32_t> initializer_scalars = {}) const;
  // Resolves a name alone (no diagnostics); TypeClass::error if unknown.
  Type lookup(std::string_view name) const;
  const std::map<std::string, std::shared_ptr<const StructType>, std::less<>>& structs() const { return structs_; }

 private:
  // The struct type of a definition, registered or not (a member's anonymous struct).
  std::shared_ptr<StructType> make_struct(const ast::Struct& decl, DiagnosticSink& diags,
                                          const ConstantScope* scope) const;

  std::map<std::string, std::shared_ptr<const StructType>, std::less<>> structs_;
  std::map<std::string, Type, std::less<>> typedefs_;
};

}  // namespace fx
