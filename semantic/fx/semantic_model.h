// The semantic model of an effect's shader code: every global name (parameters, cbuffer
// members, functions, structs and their members, typedefs, state objects, GLSL blocks),
// the scopes of function bodies (parameters and locals, with the tokens they are visible
// in), and for each identifier of a body the declaration it names and its type. Unknown
// identifiers and wrong member names are diagnosed with a located did-you-mean; what the
// model does not understand (code from macros, local structs) it leaves alone rather than
// guess. Used by the language server (tools/lsp); needs the parser only.
#pragma once
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "fx/ast.h"
#include "fx/diagnostic.h"
#include "fx/intrinsics.h"
#include "fx/shader_type.h"
#include "fx/source_manager.h"

namespace fx::semantic {

enum class SymbolKind : uint8_t {
  parameter,           // a global variable (effect parameter, static global, texture, sampler)
  cbuffer_member,      // a variable declared in a cbuffer or tbuffer
  constant_buffer,     // the cbuffer itself
  function,            // a function (or a method of a class)
  function_parameter,  // a parameter of a function
  local,               // a variable declared in a function body
  structure,           // a struct, class or interface
  member,              // a data member of a struct or class
  type_alias,          // a typedef
  state_object,        // a D3D10/11 BlendState, SamplerState, ...
  glsl_block,          // a named GLSL block
};
// "parameter", "cbuffer member", "function", ... for hover text.
std::string_view to_string(SymbolKind kind);

struct Symbol {
  SymbolKind kind = SymbolKind::parameter;
  std::string_view name;
  ShaderType type;                          // values: declared type; functions: return type
  SourceRange name_range;                   // where the name is declared
  SourceRange range;                        // the whole declaration
  std::string_view container;               // members: the struct; cbuffer members: the cbuffer; locals and
                                            // function parameters: the function
  const ast::Variable* variable = nullptr;  // parameters, members, cbuffer and function parameters
  const ast::Function* function = nullptr;  // functions
  const ast::Struct* structure = nullptr;   // structures
  const ast::ConstantBuffer* constant_buffer = nullptr;
  const ast::StateObject* state_object = nullptr;
  const ast::Typedef* type_alias = nullptr;
  ast::TokenSpan visible;  // locals and function parameters: the tokens that see them
};

// An identifier of shader code and what it names: a symbol or an intrinsic.
struct Reference {
  uint32_t token = 0;  // index into ast::Effect::tokens
  const Symbol* symbol = nullptr;
  const Intrinsic* intrinsic = nullptr;
  ShaderType type;           // the value's type where known
  bool declaration = false;  // the identifier declares `symbol` (a local's name)
};

// How much of the shader code's identifiers the model resolved (for measurement).
struct ResolutionCounts {
  size_t identifiers = 0;  // identifiers in function bodies that are no keyword or built-in type
  size_t resolved = 0;     // to a declaration
  size_t intrinsics = 0;   // to an intrinsic function
  size_t methods = 0;      // `.name` on a resource object (`tex.Sample`): no declaration to go to
  size_t unresolved = 0;   // left alone: from a macro, or in code the model does not model
  size_t diagnosed = 0;    // reported as unknown-identifier or unknown-member
};

class SemanticModel {
 public:
  // Builds the model of `effect` (which, with `sm`, must outlive it). Diagnostics go to
  // diagnostics() and are reported by report().
  SemanticModel(const ast::Effect& effect, const SourceManager& sm);
  SemanticModel(const SemanticModel&) = delete;
  SemanticModel& operator=(const SemanticModel&) = delete;

  // unknown-identifier and unknown-member findings, in token order.
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  void report(DiagnosticSink& sink) const;

  const ast::Effect& effect() const { return effect_; }
  // Global symbols in declaration order (members and locals are not globals).
  const std::vector<const Symbol*>& globals() const { return globals_; }
  // The global named `name` (the first overload of a function), or nullptr.
  const Symbol* global(std::string_view name) const;
  // The data members of a struct, in order.
  std::span<const Symbol* const> members(const ast::Struct& s) const;
  // The symbol of a struct's member `name`, or nullptr.
  const Symbol* member(const ast::Struct& s, std::string_view name) const;
  // The reference at token `token`, or nullptr if that token is no resolved identifier.
  const Reference* reference_at(uint32_t token) const;
  // Every resolved reference, by token.
  const std::vector<Reference>& references() const { return references_; }
  // The names visible at token `token`: the locals and parameters of the function whose
  // body holds it, innermost first, then every global.
  std::vector<const Symbol*> visible_at(uint32_t token) const;
  // The function whose body holds token `token`, or nullptr.
  const Symbol* function_at(uint32_t token) const;
  // The type a declaration writes (`float4`, a struct name, a typedef of either) with its
  // array rank; unknown when the name is neither built in nor declared.
  ShaderType resolve_type(const ast::TypeRef& type, size_t array_rank) const;
  ShaderType resolve_type_name(std::string_view name) const;

  const ResolutionCounts& counts() const { return counts_; }

 private:
  friend class BodyResolver;
  Symbol& add(Symbol s);
  Symbol& add_global(Symbol s);  // also listed and indexed by name
  void add_globals();
  void add_variable(SymbolKind kind, const ast::Variable& v, std::string_view container);
  void add_struct(const ast::Struct& s);
  void resolve_bodies();

  const ast::Effect& effect_;
  const SourceManager& sm_;
  std::deque<Symbol> symbols_;  // every symbol; a deque keeps their addresses
  std::vector<const Symbol*> globals_;
  std::unordered_map<std::string_view, const Symbol*> global_index_;
  std::unordered_map<const ast::Struct*, std::vector<const Symbol*>> members_;
  std::unordered_map<const ast::Function*, const Symbol*> function_symbols_;
  std::vector<const Symbol*> locals_;  // locals and function parameters, by body
  std::vector<Reference> references_;  // sorted by token
  std::vector<Diagnostic> diagnostics_;
  ResolutionCounts counts_;
};

}  // namespace fx::semantic
