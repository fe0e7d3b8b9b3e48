// The effect syntax tree. Every node carries its source range. Shader code (function
// bodies, structs, GLSL blocks, asm) is kept as token ranges for the shader compiler,
// not interpreted here. Names and other texts are ast::Text, views into the effect's Arena.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "fx/arena.h"
#include "fx/node_blocks.h"
#include "fx/source_location.h"
#include "fx/token.h"

namespace fx::ast {

// Half-open range of indices into Effect::tokens.
struct TokenSpan {
  uint32_t first = 0, last = 0;
  bool empty() const { return first == last; }
};

// Storage classes and modifiers in front of a declaration (bit set).
enum StorageClass : uint32_t {
  kShared = 1u << 0,
  kStatic = 1u << 1,
  kUniform = 1u << 2,
  kConst = 1u << 3,
  kExtern = 1u << 4,
  kVolatile = 1u << 5,
  kRowMajor = 1u << 6,
  kColumnMajor = 1u << 7,
  kGroupShared = 1u << 8,
  kIn = 1u << 9,
  kOut = 1u << 10,
  kInOut = 1u << 11,
  kNoInterpolation = 1u << 12,
  kLinear = 1u << 13,
  kCentroid = 1u << 14,
  kPrecise = 1u << 15,
  kNoPerspective = 1u << 16,
  kSample = 1u << 17,
  kInline = 1u << 18,
  // Geometry shader input primitives in front of a parameter (`triangle VSOut v[3]`).
  kPoint = 1u << 19,
  kLine = 1u << 20,
  kTriangle = 1u << 21,
  kLineAdj = 1u << 22,
  kTriangleAdj = 1u << 23,
  // Resource element normalisation (`unorm float4`), for typed buffers and textures.
  kUnorm = 1u << 24,
  kSnorm = 1u << 25,
};

// A type as written: `float4x4`, `texture2D`, `Texture2D<float4>`, `sampler_state`, a
// struct or typedef name. Resolution to a semantic type is the compiler's job.
struct Struct;
struct TypeRef {
  Text name;          // empty for an anonymous `struct { ... } member;`
  Text template_arg;  // `Texture2D<float4>` -> "float4" (empty if none)
  SourceRange range;
  // A struct defined in place, as the type of a member: `struct [Name] { ... } member;`.
  const Struct* definition = nullptr;
};

struct Expr;
// An expression node, owned by its effect's ExprPool (null where a part is missing).
using ExprPtr = Expr*;
struct StateAssignment;

enum class ExprKind : uint8_t {
  int_literal,     // number, text
  float_literal,   // number, text
  bool_literal,    // number (0/1)
  string_literal,  // text (unquoted)
  identifier,      // text: a parameter, a state enum value (`Clamp`), a constant, a type
  reference,       // `<name>`: text is the parameter name
  null,            // NULL
  unary,           // text: operator; args[0]
  binary,          // text: operator; args[0], args[1]
  ternary,         // args[0] ? args[1] : args[2]
  call,            // text: callee or constructor type (`float4`, `CompileShader`); args
  index,           // args[0][args[1]]
  member,          // args[0].text
  init_list,       // { args... }
  compile,         // `compile profile Fn(args)`: text = profile, callee = Fn, args
  asm_block,       // `asm { }`: code; decl in decl_code when `decl { } asm { }`
  state_block,     // `sampler_state { states }` (or `stateblock_state`), text = keyword
  glsl_list,       // `{ A, B }` naming GLSL blocks concatenated into one stage
  cast,            // `(float3)x`: text = type as written; args[0]
};

struct Expr {
  ExprKind kind{};
  SourceRange range;
  Text text;
  Text callee;                    // compile: the entry function
  double number = 0;              // numeric literals
  std::span<const ExprPtr> args;  // stored in the effect's ExprPool
  List<StateAssignment> states;   // state_block
  TokenSpan code;                 // asm_block: tokens between the braces
  TokenSpan decl_code;            // asm_block: `decl { }` tokens (empty if absent)
};

// Owns an effect's expression nodes and argument lists. Both live in blocks, so a tree
// costs one allocation per block instead of one per node, lies in memory in parse order
// for the checker's walks, and is freed block by block. Addresses never move.
class ExprPool {
 public:
  // A new node of `kind`, otherwise value-initialized.
  ExprPtr make(ExprKind kind);
  // A stored copy of `items`, for Expr::args.
  std::span<const ExprPtr> list(std::span<const ExprPtr> items);
  std::span<const ExprPtr> list(std::initializer_list<ExprPtr> items) {
    return list(std::span<const ExprPtr>(items.begin(), items.size()));
  }

 private:
  NodeBlocks<Expr> nodes_;
  std::vector<std::unique_ptr<ExprPtr[]>> lists_;
  size_t lists_used_ = 0, lists_capacity_ = 0;  // of lists_.back()
};

struct Annotation {
  uint32_t storage = 0;  // StorageClass bits written in front (fxc allows none of `static`)
  TypeRef type;          // string, float, float2, int, bool, ... (may carry array dims below)
  Text name;
  List<ExprPtr> array_dims;
  ExprPtr value = nullptr;
  SourceRange range;
};

struct StateAssignment {
  Text name;  // as written; the state table is case-insensitive
  SourceRange name_range;
  ExprPtr index = nullptr;  // `Texture[3]` (null if not indexed)
  ExprPtr value = nullptr;
  SourceRange range;
  // D3D10/11 call form `SetVertexShader(CompileShader(vs_4_0, VS()));`: name is the
  // function, value is the ExprKind::call (text = name), index is null.
  bool call_style = false;
};

struct Variable {
  uint32_t storage = 0;  // StorageClass bits
  TypeRef type;
  Text name;
  SourceRange name_range;
  List<ExprPtr> array_dims;  // `float4 a[4][2]`: {4, 2}; an empty dim is null
  Text semantic;             // `: POSITION` (empty if none)
  Text register_binding;     // `: register(c0)` (empty if none)
  Text packoffset;           // `: packoffset(c0.y)` -> "c0.y" (empty if none)
  List<Annotation> annotations;
  ExprPtr initializer = nullptr;
  SourceRange range;
  TokenSpan tokens;  // the whole declaration, for the shader compiler
};

// What declared a Struct: HLSL `struct`, or fx_5_0 dynamic linkage's `interface` (methods
// only) and `class` (data members and methods, `class C : I, J`).
enum class StructKind : uint8_t { structure, interface_type, class_type };

struct Function;
struct Struct {
  StructKind kind = StructKind::structure;
  Text name;
  SourceRange name_range;
  List<Text> bases;  // `class C : I, J` -> I, J: the interfaces it implements
  List<Variable> members;
  List<Function> methods;  // interface and class member functions
  SourceRange range;
  TokenSpan tokens;
};

struct Typedef {
  TypeRef type;
  Text name;
  List<ExprPtr> array_dims;
  SourceRange range;
  TokenSpan tokens;
};

struct Function {
  TypeRef return_type;
  uint32_t storage = 0;  // `inline`, `static` etc. in front of it
  Text name;
  SourceRange name_range;
  List<Variable> params;  // storage carries in/out/inout/uniform
  Text semantic;
  List<Text> attributes;  // `[numthreads(8,8,1)]` as written
  TokenSpan body;         // tokens between the braces (empty for a prototype)
  SourceRange range;
  TokenSpan tokens;  // the whole definition
  // A method defined outside its class (`float3 C::M(float3 n) { ... }` after
  // `class C { float3 M(float3 n); };`): "C", and the prototype in the class it completes.
  // The definition replaces that prototype in C's `methods`; it is no file-scope Decl.
  Text owner;
  TokenSpan prototype;
};

struct Pass {
  Text name;  // may be empty
  SourceRange name_range;
  List<Annotation> annotations;
  List<StateAssignment> states;
  SourceRange range;
};

struct Technique {
  int version = 9;  // 9: technique, 10: technique10, 11: technique11
  Text name;        // may be empty
  SourceRange name_range;
  List<Annotation> annotations;
  List<Pass> passes;
  SourceRange range;
};

// D3D10/11 state objects: `BlendState name { ... };`, also arrays `SamplerState s[2] {...}`.
struct StateObject {
  Text kind;  // BlendState, DepthStencilState, RasterizerState, SamplerState,
              // SamplerComparisonState (as written)
  Text name;
  SourceRange name_range;
  List<ExprPtr> array_dims;
  List<Annotation> annotations;
  List<StateAssignment> states;
  // An array written with one `{ ... }` per element (`BlendState B[2] { { ... }, { ... } };`):
  // each element's states, and `states` is empty.
  List<List<StateAssignment>> element_states;
  Text register_binding;
  SourceRange range;
};

struct ConstantBuffer {
  bool texture_buffer = false;  // tbuffer
  bool shared = false;          // `shared cbuffer`: in the effect pool (fx_4_0/fx_5_0)
  Text name;
  SourceRange name_range;
  Text register_binding;
  List<Variable> members;
  SourceRange range;
  TokenSpan tokens;
};

struct FxGroup {
  Text name;
  SourceRange name_range;
  List<Annotation> annotations;
  List<Technique> techniques;
  SourceRange range;
};

// A named block of GLSL source: `GLSLShader Name { ...GLSL... }` (nvFX style). Passes
// name one or a list of blocks per stage: `VertexShader = Name;` or `= { Common, Name };`.
struct GlslBlock {
  Text name;
  SourceRange name_range;
  TokenSpan code;
  SourceRange range;
};

// A kept preprocessor directive at file scope (#pragma ...), in order among declarations.
struct Directive {
  Text text;
  SourceRange range;
  TokenSpan tokens;
};

enum class DeclKind : uint8_t {
  variable,
  structure,
  type_alias,
  function,
  technique,
  state_object,
  constant_buffer,
  group,
  glsl_block,
  directive,
};

// Owns an effect's declarations (the nodes a Decl points to), each type in blocks of its
// own: parsing makes no allocation per declaration, teardown frees blocks rather than
// nodes, and the checker's walks over a type's nodes read memory in source order.
class DeclPool {
 public:
  // A new value-initialized node of type T (Variable, Function, Technique, ...).
  template <class T>
  T* make() {
    return std::get<NodeBlocks<T>>(nodes_).make();
  }

 private:
  std::tuple<NodeBlocks<Variable>, NodeBlocks<Struct>, NodeBlocks<Typedef>, NodeBlocks<Function>, NodeBlocks<Technique>,
             NodeBlocks<StateObject>, NodeBlocks<ConstantBuffer>, NodeBlocks<FxGroup>, NodeBlocks<GlslBlock>,
             NodeBlocks<Directive>>
      nodes_;
};

// One top-level declaration; exactly the member matching `kind` is set. The nodes are
// owned by the effect's DeclPool.
struct Decl {
  DeclKind kind{};
  Variable* variable = nullptr;
  Struct* structure = nullptr;
  Typedef* type_alias = nullptr;
  Function* function = nullptr;
  Technique* technique = nullptr;
  StateObject* state_object = nullptr;
  ConstantBuffer* constant_buffer = nullptr;
  FxGroup* group = nullptr;
  GlslBlock* glsl_block = nullptr;
  Directive* directive = nullptr;
};

// Every node is trivially destructible (its texts and lists live in the Arena), so an
// effect's teardown frees blocks and destroys no node.
static_assert(std::is_trivially_destructible_v<Expr> && std::is_trivially_destructible_v<Variable> &&
              std::is_trivially_destructible_v<Function> && std::is_trivially_destructible_v<Technique> &&
              std::is_trivially_destructible_v<StateObject> && std::is_trivially_destructible_v<FxGroup> &&
              std::is_trivially_destructible_v<Directive>);

struct Effect {
  std::string profile_header;  // from a leading `fx.2.0`-style line, if any
  std::vector<Token> tokens;   // the preprocessed token stream the spans index
  std::vector<Decl> decls;     // in source order
  DeclPool declarations;       // every node the decls point to
  ExprPool expressions;        // every Expr the declarations point to
  Arena arena;                 // the texts and lists inside those nodes
  // Set by the front end (fx/frontend.h) when it reported an error: the tree may be partial
  // and its shader code unchecked, so none of it goes to the shader compiler.
  bool front_end_failed = false;
};

}  // namespace fx::ast
