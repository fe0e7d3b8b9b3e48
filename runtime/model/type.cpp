// Type resolution: HLSL/effect type names (D3D9, D3D10/11 and pre-release spellings),
// structs, typedefs and array dimensions.
#include "fx/model/type.h"

#include <cctype>
#include <optional>

#include "fx/model/value.h"
#include "fx/state_table.h"
#include "model_internal.h"

namespace fx {
namespace {

std::optional<BaseType> scalar_name(std::string_view n) {
  if (n == "bool") return BaseType::boolean;
  if (n == "int" || n == "min16int" || n == "min12int" || n == "signed int" || n == "int32_t") return BaseType::int32;
  if (n == "uint" || n == "dword" || n == "DWORD" || n == "unsigned int" || n == "unsigned" || n == "min16uint" ||
      n == "uint32_t")
    return BaseType::uint32;
  if (n == "half" || n == "min16float" || n == "min10float" || n == "float16_t") return BaseType::half;
  if (n == "float" || n == "float32_t") return BaseType::float32;
  if (n == "double" || n == "float64_t") return BaseType::float64;
  return std::nullopt;
}

// "float3" -> (float, 1, 3); "half4x4" -> (half, 4, 4).
std::optional<Type> numeric_name(std::string_view n) {
  if (auto b = scalar_name(n)) return make_numeric(*b);
  size_t i = n.size();
  while (i > 0 && (std::isdigit(static_cast<unsigned char>(n[i - 1])) || n[i - 1] == 'x')) --i;
  if (i == n.size() || i == 0) return std::nullopt;
  auto base = scalar_name(n.substr(0, i));
  if (!base) return std::nullopt;
  std::string_view dims = n.substr(i);
  auto digit = [](char c) { return c >= '1' && c <= '4'; };
  if (dims.size() == 1 && digit(dims[0])) return make_numeric(*base, 1, static_cast<uint8_t>(dims[0] - '0'));
  if (dims.size() == 3 && digit(dims[0]) && dims[1] == 'x' && digit(dims[2]))
    return make_numeric(*base, static_cast<uint8_t>(dims[0] - '0'), static_cast<uint8_t>(dims[2] - '0'));
  return std::nullopt;
}

// Template arguments as the parser spells them: "float,3" / "float, 3, 4".
std::vector<std::string> split_args(std::string_view s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != ' ' && c != '\t') cur.push_back(c);
  }
  if (!cur.empty() || !out.empty()) out.push_back(cur);
  return out;
}

std::optional<uint8_t> small_dim(const std::string& s) {
  if (s.size() == 1 && s[0] >= '1' && s[0] <= '4') return static_cast<uint8_t>(s[0] - '0');
  return std::nullopt;
}

Type object_type(TypeClass cls, std::string kind) {
  Type t;
  t.cls = cls;
  t.object_kind = std::move(kind);
  return t;
}

// Texture, sampler, shader and state-object names (case-insensitive, as fxc).
std::optional<Type> object_name(std::string_view name, std::string_view template_arg) {
  std::string n = ascii_lower(name);
  static const std::pair<const char*, TextureShape> textures[] = {{"texture", TextureShape::any},
                                                                  {"texture1d", TextureShape::tex1d},
                                                                  {"texture2d", TextureShape::tex2d},
                                                                  {"texture3d", TextureShape::tex3d},
                                                                  {"texturecube", TextureShape::cube},
                                                                  {"volumetexture", TextureShape::tex3d},
                                                                  {"cubetexture", TextureShape::cube},
                                                                  {"texture1darray", TextureShape::tex1d_array},
                                                                  {"texture2darray", TextureShape::tex2d_array},
                                                                  {"texture2dms", TextureShape::tex2dms},
                                                                  {"texture2dmsarray", TextureShape::tex2dms_array},
                                                                  {"texturecubearray", TextureShape::cube_array},
                                                                  {"buffer", TextureShape::buffer}};
  for (auto& [spelling, shape] : textures)
    if (n == spelling) {
      Type t;
      t.cls = TypeClass::texture;
      t.texture = shape;
      t.element = std::string(template_arg);
      return t;
    }
  static const std::pair<const char*, SamplerShape> samplers[] = {{"sampler", SamplerShape::any},
                                                                  {"sampler1d", SamplerShape::s1d},
                                                                  {"sampler2d", SamplerShape::s2d},
                                                                  {"sampler3d", SamplerShape::s3d},
                                                                  {"samplercube", SamplerShape::cube},
                                                                  {"samplerstate", SamplerShape::sampler_object},
                                                                  {"sampler_state", SamplerShape::sampler_object},
                                                                  {"samplercomparisonstate", SamplerShape::comparison}};
  for (auto& [spelling, shape] : samplers)
    if (n == spelling) {
      Type t;
      t.cls = TypeClass::sampler;
      t.sampler = shape;
      return t;
    }
  static const std::pair<const char*, ViewKind> views[] = {
      {"structuredbuffer", ViewKind::structured_buffer},
      {"rwstructuredbuffer", ViewKind::rw_structured_buffer},
      {"appendstructuredbuffer", ViewKind::append_structured_buffer},
      {"consumestructuredbuffer", ViewKind::consume_structured_buffer},
      {"byteaddressbuffer", ViewKind::byte_address_buffer},
      {"rwbyteaddressbuffer", ViewKind::rw_byte_address_buffer},
      {"rwbuffer", ViewKind::rw_buffer},
      {"rwtexture1d", ViewKind::rw_texture1d},
      {"rwtexture1darray", ViewKind::rw_texture1d_array},
      {"rwtexture2d", ViewKind::rw_texture2d},
      {"rwtexture2darray", ViewKind::rw_texture2d_array},
      {"rwtexture3d", ViewKind::rw_texture3d}};
  for (auto& [spelling, kind] : views)
    if (n == spelling) {
      Type t;
      t.cls = TypeClass::view;
      t.view = kind;
      t.element = std::string(template_arg);
      return t;
    }
  if (std::optional<PassStage> stage = shader_type_stage(n))
    return object_type(TypeClass::shader, std::string(shader_type_name(*stage)));
  // State objects, and the views a D3D10 effect declares for the application to set (FX11's
  // RenderTargetView / DepthStencilView variables; no shader reads them).
  static const char* objects[] = {"BlendState", "DepthStencilState", "RasterizerState", "RenderTargetView",
                                  "DepthStencilView"};
  for (const char* s : objects)
    if (iequals(n, s)) return object_type(TypeClass::state_object, s);
  return std::nullopt;
}

// Pre-release HLSL (2001-2002) names, as in the seeds' wood shader.
std::optional<Type> pre_release_name(std::string_view n) {
  if (n == "vec2") return make_numeric(BaseType::float32, 1, 2);
  if (n == "vec3") return make_numeric(BaseType::float32, 1, 3);
  if (n == "vec4") return make_numeric(BaseType::float32, 1, 4);
  if (n == "mat3") return make_numeric(BaseType::float32, 3, 3);
  if (n == "mat4") return make_numeric(BaseType::float32, 4, 4);
  return std::nullopt;
}

std::vector<std::string_view> known_names(const TypeTable& table) {
  static const char* builtins[] = {"bool",
                                   "int",
                                   "uint",
                                   "dword",
                                   "half",
                                   "float",
                                   "double",
                                   "float2",
                                   "float3",
                                   "float4",
                                   "float4x4",
                                   "float3x3",
                                   "float3x4",
                                   "float4x3",
                                   "half2",
                                   "half3",
                                   "half4",
                                   "int2",
                                   "int3",
                                   "int4",
                                   "bool2",
                                   "bool3",
                                   "bool4",
                                   "vector",
                                   "matrix",
                                   "string",
                                   "texture",
                                   "texture1D",
                                   "texture2D",
                                   "texture3D",
                                   "textureCUBE",
                                   "Texture2D",
                                   "Texture3D",
                                   "TextureCube",
                                   "sampler",
                                   "sampler1D",
                                   "sampler2D",
                                   "sampler3D",
                                   "samplerCUBE",
                                   "SamplerState",
                                   "SamplerComparisonState",
                                   "StructuredBuffer",
                                   "RWStructuredBuffer",
                                   "ByteAddressBuffer",
                                   "RWByteAddressBuffer",
                                   "RWTexture2D",
                                   "VertexShader",
                                   "PixelShader",
                                   "BlendState",
                                   "DepthStencilState",
                                   "RasterizerState",
                                   "void"};
  std::vector<std::string_view> out(std::begin(builtins), std::end(builtins));
  for (auto& [name, _] : table.structs()) out.push_back(name);
  return out;
}

}  // namespace

uint32_t Type::element_count() const {
  uint64_t n = 1;
  for (uint32_t d : array_dims) n *= d;
  return static_cast<uint32_t>(n);
}

uint32_t Type::element_components() const {
  if (is_numeric()) return static_cast<uint32_t>(rows) * cols;
  if (cls == TypeClass::structure && structure) return structure->components;
  return 1;
}

uint32_t Type::component_count() const { return element_components() * element_count(); }

Type Type::element_type() const {
  Type t = *this;
  if (!t.array_dims.empty()) t.array_dims.erase(t.array_dims.begin());
  return t;
}

Type Type::without_arrays() const {
  Type t = *this;
  t.array_dims.clear();
  return t;
}

std::string Type::to_string() const {
  std::string s;
  switch (cls) {
    case TypeClass::error: s = "<error>"; break;
    case TypeClass::void_type: s = "void"; break;
    case TypeClass::scalar: s = std::string(fx::to_string(base)); break;
    case TypeClass::vector: s = std::string(fx::to_string(base)) + std::to_string(cols); break;
    case TypeClass::matrix:
      s = std::string(fx::to_string(base)) + std::to_string(rows) + "x" + std::to_string(cols);
      break;
    case TypeClass::structure: s = "struct " + (structure ? structure->name : std::string("?")); break;
    case TypeClass::string: s = "string"; break;
    case TypeClass::texture: {
      static const char* names[] = {"texture",          "Texture1D",        "Texture2D",      "Texture3D",
                                    "TextureCube",      "Texture1DArray",   "Texture2DArray", "Texture2DMS",
                                    "Texture2DMSArray", "TextureCubeArray", "Buffer"};
      s = names[static_cast<int>(texture)];
      if (!element.empty()) s += "<" + element + ">";
      break;
    }
    case TypeClass::sampler: {
      static const char* names[] = {
          "sampler", "sampler1D", "sampler2D", "sampler3D", "samplerCUBE", "SamplerState", "SamplerComparisonState"};
      s = names[static_cast<int>(sampler)];
      break;
    }
    case TypeClass::shader:
    case TypeClass::state_object: s = object_kind; break;
    case TypeClass::view: {
      static const char* names[] = {"StructuredBuffer",
                                    "RWStructuredBuffer",
                                    "AppendStructuredBuffer",
                                    "ConsumeStructuredBuffer",
                                    "ByteAddressBuffer",
                                    "RWByteAddressBuffer",
                                    "RWBuffer",
                                    "RWTexture1D",
                                    "RWTexture1DArray",
                                    "RWTexture2D",
                                    "RWTexture2DArray",
                                    "RWTexture3D"};
      s = names[static_cast<int>(view)];
      if (!element.empty()) s += "<" + element + ">";
      break;
    }
  }
  for (uint32_t d : array_dims) s.append("[").append(std::to_string(d)).append("]");
  return s;
}

bool Type::same_as(const Type& o) const {
  if (cls != o.cls || array_dims != o.array_dims) return false;
  switch (cls) {
    case TypeClass::scalar:
    case TypeClass::vector:
    case TypeClass::matrix: return base == o.base && rows == o.rows && cols == o.cols;
    case TypeClass::structure:
      if (!structure || !o.structure) return structure == o.structure;
      if (structure->name != o.structure->name || structure->members.size() != o.structure->members.size())
        return false;
      for (size_t i = 0; i < structure->members.size(); ++i)
        if (structure->members[i].name != o.structure->members[i].name ||
            !structure->members[i].type.same_as(o.structure->members[i].type))
          return false;
      return true;
    case TypeClass::texture: return texture == o.texture;
    case TypeClass::sampler: return sampler == o.sampler;
    case TypeClass::view: return view == o.view && element == o.element;
    case TypeClass::shader:
    case TypeClass::state_object: return object_kind == o.object_kind;
    default: return true;
  }
}

const StructMember* StructType::find(std::string_view n) const {
  for (const StructMember& m : members)
    if (m.name == n) return &m;
  return nullptr;
}

Type make_numeric(BaseType base, uint8_t rows, uint8_t cols) {
  Type t;
  t.base = base;
  t.rows = rows;
  t.cols = cols;
  t.cls = rows > 1 ? TypeClass::matrix : cols > 1 ? TypeClass::vector : TypeClass::scalar;
  return t;
}

std::string_view to_string(BaseType base) {
  switch (base) {
    case BaseType::boolean: return "bool";
    case BaseType::int32: return "int";
    case BaseType::uint32: return "uint";
    case BaseType::half: return "half";
    case BaseType::float32: return "float";
    case BaseType::float64: return "double";
  }
  return "?";
}

Type TypeTable::lookup(std::string_view name) const {
  if (auto t = numeric_name(name)) return *t;
  if (name == "vector") return make_numeric(BaseType::float32, 1, 4);
  if (name == "matrix") return make_numeric(BaseType::float32, 4, 4);
  if (name == "string") {
    Type t;
    t.cls = TypeClass::string;
    return t;
  }
  if (name == "void") {
    Type t;
    t.cls = TypeClass::void_type;
    return t;
  }
  if (auto it = structs_.find(name); it != structs_.end()) {
    Type t;
    t.cls = TypeClass::structure;
    t.structure = it->second;
    return t;
  }
  if (auto it = typedefs_.find(name); it != typedefs_.end()) return it->second;
  if (auto t = object_name(name, {})) return *t;
  if (auto t = pre_release_name(name)) return *t;
  // fxc reads these in any case (`Matrix transform;`, `FLOAT scale;`): vkd3d, which follows
  // it, looks up dword, float, matrix, vector and string case-insensitively.
  if (std::string lower = ascii_lower(name); lower != name)
    for (std::string_view word : {"dword", "float", "matrix", "vector", "string"})
      if (lower == word) return lookup(word);
  return {};
}

Type TypeTable::resolve(const ast::TypeRef& ref, uint32_t storage, const ast::List<ast::ExprPtr>& dims,
                        DiagnosticSink& diags, const ConstantScope* scope,
                        std::optional<uint32_t> initializer_scalars) const {
  Type t;
  std::string_view name = ref.name;
  if (name == "struct" || name == "const") name = ref.template_arg;  // defensive: never produced today
  if (!ref.template_arg.empty() && (iequals(name, "vector") || iequals(name, "matrix"))) {
    name = iequals(name, "vector") ? "vector" : "matrix";
    std::vector<std::string> args = split_args(ref.template_arg);
    auto base = args.empty() ? std::nullopt : scalar_name(args[0]);
    bool ok = base.has_value();
    if (ok && name == "vector") {
      auto n = args.size() == 2 ? small_dim(args[1]) : std::nullopt;
      ok = n.has_value();
      if (ok) t = make_numeric(*base, 1, *n);
    } else if (ok) {
      auto r = args.size() == 3 ? small_dim(args[1]) : std::nullopt;
      auto c = args.size() == 3 ? small_dim(args[2]) : std::nullopt;
      ok = r && c;
      if (ok) t = make_numeric(*base, *r, *c);
      if (ok && *r == 1) t.cls = TypeClass::matrix;  // matrix<float,1,4> stays a matrix
    }
    if (!ok) {
      diags.error("unknown-type", ref.range,
                  "bad template arguments '" + ref.template_arg + "' for '" + std::string(name) +
                      "' (expected <scalar, 1..4" + (name == "matrix" ? ", 1..4" : "") + ">)");
      return {};
    }
  } else if (auto obj = ref.template_arg.empty() ? std::nullopt : object_name(name, ref.template_arg)) {
    t = *obj;
  } else if (ref.definition && ref.definition->name.empty()) {  // `struct { float3 dir; } light;`
    t.cls = TypeClass::structure;
    t.structure = make_struct(*ref.definition, diags, scope);
  } else {
    t = lookup(name);
    if (t.cls == TypeClass::error) {
      Diagnostic& d = diags.error("unknown-type", ref.range, "unknown type '" + std::string(name) + "'");
      std::string guess = closest_match(name, known_names(*this));
      if (!guess.empty()) {
        d.message += "; did you mean '" + guess + "'?";
        d.fixits.push_back({ref.range, guess});
      }
      return {};
    }
  }
  if (t.cls == TypeClass::matrix) {
    if (storage & ast::kRowMajor) t.order = MatrixPacking::row_major;
    if (storage & ast::kColumnMajor) t.order = MatrixPacking::column_major;
  }
  std::vector<uint32_t> extra;
  bool unsized = false;  // the outermost dimension is the initializer's element count
  for (const ast::ExprPtr& dim : dims) {
    if (!dim && extra.empty() && initializer_scalars) {
      unsized = true;
      extra.push_back(1);
      continue;
    }
    if (!dim) {
      diags.error("bad-array-size", ref.range,
                  extra.empty() ? "array dimension must be given for an effect parameter without an initializer"
                                : "only the outermost array dimension may be left unsized");
      return {};
    }
    ConstantScope empty;
    auto v = fold_constant(*dim, scope ? *scope : empty, diags);
    if (!v) return {};
    double n = v->number();
    if (!v->is_numeric() || n < 1 || n > 65536 || n != static_cast<double>(static_cast<int64_t>(n))) {
      diags.error("bad-array-size", dim->range, "array size must be an integer in 1..65536, not " + v->to_string());
      return {};
    }
    extra.push_back(static_cast<uint32_t>(n));
  }
  // Declarator dimensions come first: `typedef float4 T[2]; T a[3];` is float4[3][2].
  extra.insert(extra.end(), t.array_dims.begin(), t.array_dims.end());
  t.array_dims = std::move(extra);
  if (unsized) {
    const uint32_t element = t.component_count();  // the outermost dimension is 1 yet
    if (element == 0 || *initializer_scalars == 0 || *initializer_scalars % element != 0) {
      diags.error("bad-array-size", ref.range,
                  "the initializer's " + std::to_string(*initializer_scalars) +
                      " values do not fill whole elements of " + t.element_type().to_string() + " (" +
                      std::to_string(element) + " each)");
      return {};
    }
    t.array_dims[0] = *initializer_scalars / element;
  }
  if (t.component_count() > (1u << 22)) {
    diags.error("bad-array-size", ref.range,
                "parameter too large (" + std::to_string(t.component_count()) + " components)");
    return {};
  }
  return t;
}

void TypeTable::add_struct(const ast::Struct& decl, DiagnosticSink& diags, const ConstantScope* scope) {
  if (decl.name.empty()) return;
  if (structs_.count(decl.name)) return;  // redefinitions are the checker's report
  // An interface variable holds the id of the class instance bound to it (docs/fx11-parity.md).
  if (decl.kind == ast::StructKind::interface_type) {
    typedefs_.emplace(decl.name, make_numeric(BaseType::int32));
    return;
  }
  // A named struct defined in place as a member's type is a type of its own from there on.
  for (const ast::Variable& m : decl.members)
    if (m.type.definition && !m.type.definition->name.empty()) add_struct(*m.type.definition, diags, scope);
  structs_.emplace(decl.name, make_struct(decl, diags, scope));
}

std::shared_ptr<StructType> TypeTable::make_struct(const ast::Struct& decl, DiagnosticSink& diags,
                                                   const ConstantScope* scope) const {
  auto st = std::make_shared<StructType>();
  st->name = decl.name;
  // A class derived from a class (`class Hemi : Ambient`) holds the base's members first.
  if (decl.kind == ast::StructKind::class_type)
    for (const ast::Text& base : decl.bases)
      if (auto it = structs_.find(base); it != structs_.end() && it->second)
        for (const StructMember& m : it->second->members) {
          st->members.push_back(m);
          st->members.back().component_offset = st->components;
          st->components += m.type.component_count();
        }
  for (const ast::Variable& m : decl.members) {
    StructMember member;
    member.name = m.name;
    member.type = resolve(m.type, m.storage, m.array_dims, diags, scope);
    if (member.type.cls == TypeClass::error) continue;
    member.semantic = m.semantic;
    member.component_offset = st->components;
    // Resource members (texture/sampler in a struct) take no constant space; they count one.
    st->components += member.type.component_count();
    st->members.push_back(std::move(member));
  }
  return st;
}

void TypeTable::add_typedef(const ast::Typedef& decl, DiagnosticSink& diags, const ConstantScope* scope) {
  if (decl.name.empty() || typedefs_.count(decl.name)) return;
  Type t = resolve(decl.type, 0, decl.array_dims, diags, scope);
  if (t.cls != TypeClass::error) typedefs_.emplace(decl.name, std::move(t));
}

}  // namespace fx
