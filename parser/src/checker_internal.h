// The checker's shared state: a symbol table of the effect's global names and the checks
// split over checker.cpp (symbols, duplicates, annotations, profile rules) and
// checker_states.cpp (state assignments against the state table). Private to fxkit_parser.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "fx/ascii_case.h"
#include "fx/ast.h"
#include "fx/checker.h"
#include "fx/state_table.h"
#include "name_table.h"

namespace fx::check {

// First occurrences of keys in one block (annotations, passes, states): blocks are small,
// so the first kSmall keys are scanned in place without allocating; larger blocks switch
// to a hash index, so a huge block stays linear.
template <class Key, class Hash = std::hash<Key>>
class FirstSeen {
 public:
  // Records `value` for a new key and returns nullptr, or returns the value recorded for
  // an earlier equal key (which the caller may update).
  SourceRange* insert(const Key& key, SourceRange value) {
    if (!overflow_.empty()) {
      auto [it, fresh] = overflow_.emplace(key, value);
      return fresh ? nullptr : &it->second;
    }
    for (size_t i = 0; i < count_; ++i)
      if (small_.entries[i].first == key) return &small_.entries[i].second;
    if (count_ < kSmall) {
      std::construct_at(&small_.entries[count_++], key, value);
      return nullptr;
    }
    overflow_.reserve(2 * kSmall);
    for (size_t i = 0; i < count_; ++i) overflow_.emplace(small_.entries[i].first, small_.entries[i].second);
    overflow_.emplace(key, value);
    return nullptr;
  }

 private:
  static constexpr size_t kSmall = 16;
  using Entry = std::pair<Key, SourceRange>;
  static_assert(std::is_trivially_destructible_v<Entry>);
  // Entries [0, count_) are constructed, the rest left raw: one FirstSeen is made per
  // annotation list and state block, mostly of a few keys, and clearing all 16 entries
  // was most of the stores of check_annotations and check_states.
  union Storage {
    Storage() {}
    Entry entries[kSmall];
  } small_;
  size_t count_ = 0;
  std::unordered_map<Key, SourceRange, Hash> overflow_;
};

// A state row and index, as a FirstSeen key.
using StateSlot = std::pair<const StateInfo*, int64_t>;
struct StateSlotHash {
  size_t operator()(const StateSlot& s) const {
    return std::hash<const void*>()(s.first) * 31 + std::hash<int64_t>()(s.second);
  }
};

// A global name of the effect.
struct Symbol {
  enum Kind : uint8_t { variable, state_object, structure, type_alias, glsl_block, function };
  Kind kind = variable;
  std::string_view type;  // variable: its type name; state_object: its kind
  SourceRange range;      // the name, for "previous definition" notes
  int64_t elements = 0;   // variable: a one-dimensional array's literal size, 0 otherwise
};

// 'text' for messages.
std::string quote(std::string_view text);
// True if `s` begins with `prefix`, ignoring ASCII case (`Texture2D` is a "texture").
inline bool starts_with_i(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && iequals(s.substr(0, prefix.size()), prefix);
}
// The value of an integer-valued literal expression (`3`, `-1`, `1 << 4`, `TRUE`), if any.
std::optional<int64_t> literal_int(const ast::Expr& e);

class Checker {
 public:
  Checker(const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& diags, const CheckOptions& options);
  void run();

 private:
  // --- checker.cpp ---
  void collect_symbols();
  void define(std::string_view name, SourceRange range, Symbol symbol, std::string_view what);
  void check_functions();
  void check_profile_rules();
  void check_against_profile(EffectProfile profile);
  void check_annotations(const ast::List<ast::Annotation>& annotations);
  void check_variable(const ast::Variable& v);
  // The first object-typed member of a struct type (nested structs too), as "a.b (texture)";
  // empty when there is none or `type` is no struct.
  std::string object_member(const ast::TypeRef& type, int depth) const;
  void check_technique(const ast::Technique& t);
  void check_value_type(std::string_view type_name, size_t array_dims, const ast::Expr& value, std::string_view what,
                        std::string_view name, std::string_view id);
  void report_duplicate(std::string_view what, std::string_view name, SourceRange range, SourceRange previous);

  // --- checker_shader_code.cpp ---
  // The effect's shader code (functions, globals, structs, cbuffers, GLSL blocks) within
  // what glslang survives: one error per declaration that is not.
  enum class ShaderCode : uint8_t { hlsl, glsl };
  void check_shader_code();
  void check_shader_code(ast::TokenSpan span, ShaderCode code);

  // --- checker_states.cpp ---
  // `also`: a second block whose names count too (see check_sampler_state).
  void check_states(const ast::List<ast::StateAssignment>& states, StateBlock block, int technique_version,
                    std::optional<StateBlock> also = std::nullopt);
  void check_state(const ast::StateAssignment& a, StateBlock block, int technique_version,
                   FirstSeen<StateSlot, StateSlotHash>& seen, std::optional<StateBlock> also);
  void check_call_args(const StateInfo& info, const ast::StateAssignment& a);
  void check_value(const StateInfo& info, const ast::Expr& value);
  void check_leaf(const StateInfo& info, const ast::Expr& value);
  void check_name(const StateInfo& info, const ast::Expr& value);
  void check_shader(const StateInfo& info, const ast::Expr& value);
  // ConstructGSWithSO's declaration strings (and fx_5_0's rasterized stream) after its shader.
  void check_stream_out(const ast::Expr& construct);
  void check_compile(const StateInfo& info, std::string_view profile, SourceRange profile_range,
                     std::string_view function, SourceRange range);
  void check_symbol_type(const StateInfo& info, const Symbol& symbol, const ast::Expr& value);
  void type_mismatch(const StateInfo& info, const ast::Expr& value, std::string_view found);
  void undefined(std::string_view what, std::string_view name, SourceRange range,
                 const std::vector<std::string_view>& candidates);
  bool profile_allows(StateApi api) const;
  // Checks a `sampler_state { }` initializer's states as fxc reads them: D3D9 sampler
  // states under fx_2_0, the D3D10 SamplerState fields under fx_4_0 and later.
  void check_sampler_state(const ast::List<ast::StateAssignment>& states);
  EffectProfile profile() const;
  // fxc's rules for a function body's local declarations (checker_locals.cpp).
  void check_local_annotations(const ast::Function& f);

  const Symbol* lookup(std::string_view name) const;
  std::vector<std::string_view> names_of(std::initializer_list<Symbol::Kind> kinds) const;

  const ast::Effect& effect_;
  const SourceManager& sm_;
  DiagnosticSink& diags_;
  CheckOptions options_;
  // Given by the options or the effect's header; otherwise inferred on first use (profile()).
  // An inferred profile is at least what each technique, fxgroup, state object, cbuffer
  // and technique pass state needs, since inference reads exactly those: none of them can
  // mismatch it, so most effects never need it, and its walk over every pass is saved.
  mutable std::optional<EffectProfile> profile_;
  bool has_technique_ = false;       // in the effect or one of its fxgroups
  bool has_d3d9_technique_ = false;  // a `technique` (not technique10/11) at file scope
  // Keys view names owned by the effect, which outlives the checker.
  NameTable<Symbol> globals_;
  NameTable<const ast::Struct*> structs_;  // struct, class and interface types by name
  // Every function by name, overloads in source order (sorted once collected).
  std::vector<std::pair<std::string_view, const ast::Function*>> functions_;
  NameTable<const ast::Function*> function_names_;  // the first overload of each name
};

}  // namespace fx::check
