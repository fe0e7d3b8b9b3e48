// State assignments against the state table: names, call forms, indices, value types,
// enumeration values, references to parameters, shaders and state objects.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>

#include "checker_internal.h"
#include "fx/stream_out_decl.h"

namespace fx::check {
namespace {

bool is_object_type(StateValueType t) {
  return t == StateValueType::texture || t == StateValueType::sampler || t == StateValueType::shader ||
         t == StateValueType::state_object;
}
// A state whose values have names: its enumeration's, or TRUE/FALSE for a boolean (the
// sets find_enum and enum_names read).
bool takes_value_names(const StateInfo& info) { return info.enums || info.type == StateValueType::boolean; }
bool takes_vector(StateValueType t) {
  return t == StateValueType::color || t == StateValueType::float4 || t == StateValueType::matrix ||
         t == StateValueType::shader_constant;
}

std::string_view block_phrase(StateBlock block) {
  switch (block) {
    case StateBlock::pass: return "a pass";
    case StateBlock::sampler_state: return "a sampler_state";
    case StateBlock::blend_state: return "a BlendState";
    case StateBlock::depth_stencil_state: return "a DepthStencilState";
    case StateBlock::rasterizer_state: return "a RasterizerState";
    case StateBlock::sampler_object: return "a SamplerState";
  }
  return "a pass";
}

// Shader profiles fxkit accepts in `compile` and CompileShader.
const std::vector<std::string>& shader_profiles() {
  static const std::vector<std::string> profiles = [] {
    std::vector<std::string> p;
    // fxc's targets (vkd3d's profile table lists the same), the shader model 1.0 ones too:
    // D3DX9's stock effects name them, and the DirectX 10 compiler, in its backwards
    // compatibility mode, compiles every ps_1_x target of an effect as ps_2_0.
    for (const char* v :
         {"1_0", "1_1", "2_0", "2_a", "2_sw", "3_0", "3_sw", "4_0", "4_0_level_9_1", "4_0_level_9_3", "4_1", "5_0"})
      p.push_back(std::string("vs_") + v);
    for (const char* v : {"1_0", "1_1", "1_2", "1_3", "1_4", "2_0", "2_a", "2_b", "2_sw", "3_0", "3_sw", "4_0",
                          "4_0_level_9_1", "4_0_level_9_3", "4_1", "5_0"})
      p.push_back(std::string("ps_") + v);
    for (const char* v : {"gs_4_0", "gs_4_1", "gs_5_0", "hs_5_0", "ds_5_0", "cs_4_0", "cs_4_1", "cs_5_0"})
      p.push_back(v);
    return p;
  }();
  return profiles;
}

// A profile folded to lower case into two words, zero-padded: profiles are at most 16
// characters, so telling one apart is a few integer compares, not a case-folding compare
// per row of the list.
using PackedProfile = std::array<uint64_t, 2>;
std::optional<PackedProfile> pack_profile(std::string_view profile) {
  std::array<char, sizeof(PackedProfile)> folded{};
  // A trailing '\0' would pack as the padding does (a string literal may hold one).
  if (profile.size() > folded.size() || (!profile.empty() && profile.back() == '\0')) return std::nullopt;
  for (size_t i = 0; i < profile.size(); ++i) folded[i] = ascii_lower(profile[i]);
  PackedProfile packed;
  std::memcpy(packed.data(), folded.data(), folded.size());
  return packed;
}

bool is_shader_profile(std::string_view profile) {
  static const std::vector<PackedProfile> sorted = [] {
    std::vector<PackedProfile> packed;
    for (const std::string& p : shader_profiles()) packed.push_back(*pack_profile(p));
    std::sort(packed.begin(), packed.end());
    return packed;
  }();
  std::optional<PackedProfile> packed = pack_profile(profile);
  return packed && std::binary_search(sorted.begin(), sorted.end(), *packed);
}

bool is_compile_call(const ast::Expr& e) {
  return e.kind == ast::ExprKind::call &&
         (iequals(e.text, "CompileShader") || starts_with_i(e.text, "ConstructGSWithSO"));
}

bool is_numeric_constructor(std::string_view name) {
  for (std::string_view scalar : {"float", "half", "double", "int", "uint", "bool", "dword"})
    if (starts_with_i(name, scalar)) return true;
  return false;
}

}  // namespace

std::optional<int64_t> literal_int(const ast::Expr& e) {
  switch (e.kind) {
    case ast::ExprKind::int_literal:
    case ast::ExprKind::bool_literal: return static_cast<int64_t>(e.number);
    case ast::ExprKind::identifier:
      if (iequals(e.text, "TRUE")) return 1;
      if (iequals(e.text, "FALSE")) return 0;
      return std::nullopt;
    case ast::ExprKind::unary: {
      if (e.args.size() != 1 || !e.args[0]) return std::nullopt;
      std::optional<int64_t> v = literal_int(*e.args[0]);
      if (!v) return std::nullopt;
      if (e.text == "-") return -*v;
      if (e.text == "+") return *v;
      if (e.text == "~") return ~*v;
      return std::nullopt;
    }
    case ast::ExprKind::binary: {
      if (e.args.size() != 2 || !e.args[0] || !e.args[1]) return std::nullopt;
      std::optional<int64_t> a = literal_int(*e.args[0]), b = literal_int(*e.args[1]);
      if (!a || !b) return std::nullopt;
      if (e.text == "|") return *a | *b;
      if (e.text == "&") return *a & *b;
      if (e.text == "+") return *a + *b;
      if (e.text == "-") return *a - *b;
      if (e.text == "*") return *a * *b;
      if ((e.text == "<<" || e.text == ">>") && *b >= 0 && *b < 63) return e.text == "<<" ? *a << *b : *a >> *b;
      return std::nullopt;
    }
    default: return std::nullopt;
  }
}

bool Checker::profile_allows(StateApi api) const {
  switch (api) {
    case StateApi::d3d9: return true;
    case StateApi::d3d10: return profile() >= EffectProfile::fx_4_0;
    case StateApi::d3d11: return profile() >= EffectProfile::fx_5_0;
  }
  return true;
}

void Checker::check_sampler_state(const ast::List<ast::StateAssignment>& states) {
  if (profile() < EffectProfile::fx_4_0) {
    check_states(states, StateBlock::sampler_state, 9);
    return;
  }
  // An inferred fx_4_0+ profile beside a D3D9 technique: the file targets both runtimes
  // (as the SDK samples did), each compiling the sampler with its own names.
  const bool both = options_.profile == EffectProfile::automatic && has_d3d9_technique_;
  check_states(states, StateBlock::sampler_object, 10, both ? std::optional(StateBlock::sampler_state) : std::nullopt);
}

void Checker::check_states(const ast::List<ast::StateAssignment>& states, StateBlock block, int technique_version,
                           std::optional<StateBlock> also) {
  FirstSeen<StateSlot, StateSlotHash> seen;
  for (const ast::StateAssignment& a : states) check_state(a, block, technique_version, seen, also);
}

// A fix-it replacing `word` where it is written inside `range` (not through a macro).
static std::optional<SourceRange> word_in(const SourceManager& sm, SourceRange range, std::string_view word) {
  if (!range.valid() || sm.is_expansion(range.begin) || word.empty()) return std::nullopt;
  uint32_t length =
      range.end.raw > range.begin.raw ? range.end.raw - range.begin.raw : static_cast<uint32_t>(word.size());
  std::string_view text = sm.text_at(range.begin).substr(0, length);
  for (size_t at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
    auto is_ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    bool starts = at == 0 || !is_ident(text[at - 1]);
    bool ends = at + word.size() == text.size() || !is_ident(text[at + word.size()]);
    if (starts && ends) {
      SourceLocation b = range.begin.offset(static_cast<uint32_t>(at));
      return SourceRange{b, b.offset(static_cast<uint32_t>(word.size()))};
    }
  }
  return std::nullopt;
}

void Checker::check_state(const ast::StateAssignment& a, StateBlock block, int technique_version,
                          FirstSeen<StateSlot, StateSlotHash>& seen, std::optional<StateBlock> also) {
  const StateInfo* info = find_state(a.name, block);
  if (!info && also) info = find_state(a.name, *also);
  if (!info) {
    std::string guess = closest_match(a.name, state_names(block));
    std::string message = "unknown state " + quote(a.name) + " in " + std::string(block_phrase(block));
    if (!guess.empty()) message += "; did you mean " + quote(guess) + "?";
    Diagnostic& d = diags_.error("unknown-state", a.name_range, std::move(message));
    if (!guess.empty()) d.fixits.push_back({a.name_range, guess});
    // A sampler state of the other API: say which profile reads it.
    const bool d3d9_block = block == StateBlock::sampler_state;
    if ((d3d9_block || block == StateBlock::sampler_object) &&
        find_state(a.name, d3d9_block ? StateBlock::sampler_object : StateBlock::sampler_state))
      d.notes.push_back(
          {a.name_range.begin, std::string(d3d9_block ? "a Direct3D 10 sampler state, read in fx_4_0 and later"
                                                      : "a Direct3D 9 sampler state, read in fx_2_0 only") +
                                   "; this effect is " + std::string(to_string(profile()))});
    return;
  }
  if (info->call_args && !a.call_style) {
    diags_.error("state-call-form", a.name_range,
                 quote(info->name) + " is a call: " + std::string(info->name) + "(...);");
    return;
  }
  if (!info->call_args && a.call_style) {
    diags_.error("state-call-form", a.name_range,
                 quote(info->name) + " is assigned, not called: " + std::string(info->name) + " = value;");
    return;
  }
  if (block == StateBlock::pass && !profile_allows(info->api)) {
    diags_.error("profile-mismatch", a.name_range,
                 "state " + quote(info->name) + " needs effect profile " +
                     (info->api == StateApi::d3d11 ? "fx_5_0" : "fx_4_0") + " or later; the effect is " +
                     std::string(to_string(profile())));
  }
  if (block == StateBlock::pass && technique_version >= 10 && info->api == StateApi::d3d9 &&
      info->area != VulkanArea::shader_stage) {
    diags_.warning("mixed-state-api", a.name_range,
                   "Direct3D 9 state " + quote(info->name) + " in a technique" + std::to_string(technique_version) +
                       " pass; Direct3D 10/11 passes set state through state objects");
  }

  int64_t index = 0;
  bool index_known = true;
  if (a.index) {
    if (info->index_count == 0) {
      diags_.error("state-not-indexable", a.index->range, "state " + quote(info->name) + " takes no index");
      index_known = false;
    } else if (block == StateBlock::blend_state && info->target == kEveryTarget &&
               options_.profile == EffectProfile::fx_4_0) {
      // Direct3D 10.0 blends every target alike: only BlendEnable and RenderTargetWriteMask
      // are per target, as fxc's fx_4_0 has it (vkd3d's effect-variables-fx_4 tests).
      diags_.error("state-not-indexable", a.index->range,
                   "state " + quote(info->name) + " takes an index from fx_4_1 on; fx_4_0 blends every target alike");
      index_known = false;
    } else if (std::optional<int64_t> v = literal_int(*a.index)) {
      index = *v;
      if (*v < 0 || *v >= info->index_count) {
        diags_.error("state-index-out-of-range", a.index->range,
                     "index " + std::to_string(*v) + " is out of range for state " + quote(info->name) +
                         "; valid indices are 0.." + std::to_string(info->index_count - 1));
        index_known = false;
      }
    } else {
      index_known = false;  // a constant parameter: checked when folded
    }
  } else if (info->index_required) {
    diags_.error("state-index-required", a.name_range,
                 "state " + quote(info->name) + " needs an index: " + std::string(info->name) + "[n] (0.." +
                     std::to_string(info->index_count - 1) + ")");
  }
  if (index_known) {
    if (SourceRange* previous = seen.insert({info, index}, a.range)) {
      Diagnostic& d = diags_.warning("duplicate-state", a.name_range,
                                     "state " + quote(info->name) + (a.index ? "[" + std::to_string(index) + "]" : "") +
                                         " is set twice in this block; the last value wins");
      if (previous->valid()) d.notes.push_back({previous->begin, "previous assignment is here"});
      *previous = a.range;
    }
  }
  if (!a.value) return;
  if (a.call_style) {
    check_call_args(*info, a);
  } else {
    check_value(*info, *a.value);
  }
}

void Checker::check_call_args(const StateInfo& info, const ast::StateAssignment& a) {
  std::span<const ast::ExprPtr> args = a.value->args;
  if (args.size() != info.call_args) {
    diags_.error("state-call-form", a.value->range,
                 quote(info.name) + " takes " + std::to_string(info.call_args) + " argument" +
                     (info.call_args == 1 ? "" : "s") + ", found " + std::to_string(args.size()));
    return;
  }
  if (args[0]) check_value(info, *args[0]);
  // SetBlendState(state, float4 factor, UINT mask) / SetDepthStencilState(state, UINT ref).
  static const StateInfo factor = [] {
    StateInfo s;
    s.name = "blend factor";
    s.type = StateValueType::float4;
    return s;
  }();
  static const StateInfo integer = [] {
    StateInfo s;
    s.name = "integer argument";
    s.type = StateValueType::integer;
    return s;
  }();
  for (size_t i = 1; i < args.size(); ++i)
    if (args[i]) check_value(info.call_args == 3 && i == 1 ? factor : integer, *args[i]);
}

void Checker::type_mismatch(const StateInfo& info, const ast::Expr& value, std::string_view found) {
  diags_.error(
      "state-type-mismatch", value.range,
      "state " + quote(info.name) + " expects " +
          (info.type == StateValueType::state_object ? "a " + std::string(info.object_kind)
                                                     : "a value of type " + std::string(to_string(info.type))) +
          ", found " + std::string(found));
}

void Checker::undefined(std::string_view what, std::string_view name, SourceRange range,
                        const std::vector<std::string_view>& candidates) {
  std::string guess = closest_match(name, candidates);
  std::string message = "use of undefined " + std::string(what) + " " + quote(name);
  if (!guess.empty()) message += "; did you mean " + quote(guess) + "?";
  Diagnostic& d = diags_.error("undefined-reference", range, std::move(message));
  if (!guess.empty())
    if (std::optional<SourceRange> at = word_in(sm_, range, name)) d.fixits.push_back({*at, guess});
}

void Checker::check_value(const StateInfo& info, const ast::Expr& e) {
  using K = ast::ExprKind;
  StateValueType t = info.type;
  switch (e.kind) {
    case K::string_literal: type_mismatch(info, e, "a string"); return;
    case K::identifier: check_name(info, e); return;
    case K::reference: {
      const Symbol* s = lookup(e.text);
      if (!s || (s->kind != Symbol::variable && s->kind != Symbol::state_object)) {
        undefined("parameter", e.text, e.range, names_of({Symbol::variable, Symbol::state_object}));
        return;
      }
      check_symbol_type(info, *s, e);
      return;
    }
    case K::null:
      if (!is_object_type(t)) type_mismatch(info, e, "NULL");
      return;
    case K::int_literal:
    case K::float_literal:
    case K::bool_literal: check_leaf(info, e); return;
    case K::compile:
    case K::asm_block:
    case K::glsl_list:
      if (t != StateValueType::shader) {
        type_mismatch(info, e, "a shader");
        return;
      }
      check_shader(info, e);
      return;
    case K::call:
      if (is_compile_call(e)) {
        if (t != StateValueType::shader) type_mismatch(info, e, "a shader");
        else check_shader(info, e);
      } else if (is_numeric_constructor(e.text) &&
                 (is_object_type(t) || t == StateValueType::enumeration || t == StateValueType::flags)) {
        type_mismatch(info, e, "a " + quote(e.text) + " value");
      }
      return;
    case K::init_list:
      if (!takes_vector(t)) type_mismatch(info, e, "an initializer list");
      return;
    case K::state_block:
      if (t == StateValueType::sampler && iequals(e.text, "sampler_state")) {
        check_sampler_state(e.states);
      } else {
        type_mismatch(info, e, "a " + quote(e.text) + " block");
      }
      return;
    case K::index:
      // `Blends[1]`, `Textures[i]`: the array must exist; element types are not tracked.
      if (!e.args.empty() && e.args[0] && (e.args[0]->kind == K::identifier || e.args[0]->kind == K::reference)) {
        const Symbol* array = lookup(e.args[0]->text);
        if (!array) {
          undefined("parameter", e.args[0]->text, e.args[0]->range, names_of({Symbol::variable, Symbol::state_object}));
          return;
        }
        // fxc folds a literal index into a parameter array and refuses one past its end
        // (vkd3d's effect-assignments-fx_5 tests: `stencil_refs[10]` of a uint[2]).
        std::optional<int64_t> at = e.args.size() > 1 && e.args[1] ? literal_int(*e.args[1]) : std::nullopt;
        if (array->elements > 0 && at && (*at < 0 || *at >= array->elements))
          diags_.error("array-index-out-of-range", e.args[1]->range,
                       "index " + std::to_string(*at) + " is out of range for " + quote(e.args[0]->text) + " (" +
                           std::to_string(array->elements) + " elements)");
      }
      return;
    case K::unary:
    case K::binary:
    case K::ternary:
    case K::cast:
    case K::member:
      if (is_object_type(t)) {
        // A constant expression that folds to 0 is NULL, as the literal 0 is: fxc takes
        // `SetRasterizerState(1-1)` (vkd3d's effect-pass-states-fx_5 tests).
        if (std::optional<int64_t> v = literal_int(e); v && *v == 0 && e.kind != K::member) return;
        if (e.kind != K::member && e.kind != K::ternary) type_mismatch(info, e, "an expression");
        return;
      }
      if (std::optional<int64_t> v = literal_int(e); v && e.kind != K::member) {
        check_leaf(info, e);  // a literal-only expression: check its value
        return;
      }
      // Names inside the expression must still resolve (enum names, parameters).
      for (size_t i = e.kind == K::ternary ? 1 : 0; i < e.args.size(); ++i)
        if (const ast::Expr* arg = e.args[i]; arg && (arg->kind == K::identifier || arg->kind == K::reference ||
                                                      arg->kind == K::string_literal || arg->args.size()))
          check_value(info, *arg);
      return;
  }
}

void Checker::check_leaf(const StateInfo& info, const ast::Expr& e) {
  StateValueType t = info.type;
  std::optional<int64_t> v = literal_int(e);
  if (is_object_type(t)) {
    if (v != 0) type_mismatch(info, e, "a number");  // 0 is NULL
    return;
  }
  if (t == StateValueType::enumeration && info.enums) {
    if (!v) {
      type_mismatch(info, e, "a non-integer number");
      return;
    }
    const auto& values = info.enums->values;
    if (std::none_of(values.begin(), values.end(), [&](const EnumValue& ev) { return ev.value == *v; }))
      diags_.error("unknown-state-value", e.range, std::to_string(*v) + " is not a value of state " + quote(info.name));
  }
}

void Checker::check_name(const StateInfo& info, const ast::Expr& e) {
  StateValueType t = info.type;
  const bool named_values = takes_value_names(info);
  if (named_values && find_enum(info, e.text)) return;
  if (const Symbol* s = lookup(e.text)) {
    check_symbol_type(info, *s, e);
    return;
  }
  if (iequals(e.text, "NULL") && is_object_type(t)) return;
  if ((iequals(e.text, "TRUE") || iequals(e.text, "FALSE")) && !info.enums && !is_object_type(t)) return;
  if (named_values) {
    std::string guess = closest_match(e.text, enum_names(info));
    std::string message = "unknown value " + quote(e.text) + " for state " + quote(info.name);
    if (!guess.empty()) message += "; did you mean " + quote(guess) + "?";
    Diagnostic& d = diags_.error("unknown-state-value", e.range, std::move(message));
    if (!guess.empty()) d.fixits.push_back({e.range, guess});
    return;
  }
  switch (t) {
    case StateValueType::shader:
      undefined("shader", e.text, e.range, names_of({Symbol::variable, Symbol::glsl_block}));
      return;
    case StateValueType::state_object:
      undefined(std::string(info.object_kind), e.text, e.range, names_of({Symbol::state_object}));
      return;
    default: undefined("parameter", e.text, e.range, names_of({Symbol::variable})); return;
  }
}

void Checker::check_symbol_type(const StateInfo& info, const Symbol& s, const ast::Expr& e) {
  auto found = [&] {
    switch (s.kind) {
      case Symbol::state_object: return std::string(s.type) + " " + quote(e.text);
      case Symbol::glsl_block: return "GLSL block " + quote(e.text);
      case Symbol::structure: return "struct " + quote(e.text);
      case Symbol::type_alias: return "typedef " + quote(e.text);
      default: return quote(s.type) + " parameter " + quote(e.text);
    }
  };
  bool variable = s.kind == Symbol::variable;
  bool ok = true;
  switch (info.type) {
    case StateValueType::texture: ok = variable && starts_with_i(s.type, "texture"); break;
    case StateValueType::sampler: ok = variable && starts_with_i(s.type, "sampler"); break;
    case StateValueType::shader: ok = s.kind == Symbol::glsl_block || (variable && shader_type_stage(s.type)); break;
    case StateValueType::state_object: {
      // A D3D10/11 state object of the row's block, or a D3D9 `stateblock` variable.
      std::optional<StateBlock> block = state_object_block(info.object_kind);
      ok = (s.kind == Symbol::state_object || variable) &&
           (block ? state_object_block(s.type) == block : iequals(s.type, info.object_kind));
      break;
    }
    default: {
      std::string type = ascii_lower(s.type);
      bool object_var =
          type.rfind("texture", 0) == 0 || type.rfind("sampler", 0) == 0 || type == "string" || shader_type_stage(type);
      ok = variable && !object_var;
      break;
    }
  }
  if (!ok) type_mismatch(info, e, found());
}

void Checker::check_shader(const StateInfo& info, const ast::Expr& e) {
  using K = ast::ExprKind;
  switch (e.kind) {
    case K::compile: check_compile(info, e.text, e.range, e.callee, e.range); return;
    case K::call:
      if (iequals(e.text, "CompileShader")) {
        if (e.args.size() >= 2 && e.args[0] && e.args[1] && e.args[1]->kind == K::call)
          check_compile(info, e.args[0]->text, e.args[0]->range, e.args[1]->text, e.args[1]->range);
      } else if (!e.args.empty() && e.args[0]) {
        // ConstructGSWithSO(shader, ...): the shader may be a vertex shader, whose output is
        // then streamed out with no geometry stage.
        const ast::Expr& shader = *e.args[0];
        if (iequals(e.text, "ConstructGSWithSO")) check_stream_out(e);
        std::string_view profile =
            shader.kind == K::compile ? std::string_view(shader.text)
            : shader.kind == K::call && iequals(shader.text, "CompileShader") && !shader.args.empty() && shader.args[0]
                ? std::string_view(shader.args[0]->text)
                : std::string_view();
        if (iequals(e.text, "ConstructGSWithSO") && starts_with_i(profile, profile_prefix(PassStage::vertex))) {
          StateInfo vertex = info;
          vertex.stage = PassStage::vertex;
          check_value(vertex, shader);
        } else {
          check_value(info, shader);
        }
      }
      return;
    case K::glsl_list:
      for (const ast::ExprPtr& a : e.args) {
        if (!a || a->kind != K::identifier) continue;
        const Symbol* s = lookup(a->text);
        if (!s || s->kind != Symbol::glsl_block)
          undefined("GLSL block", a->text, a->range, names_of({Symbol::glsl_block}));
      }
      return;
    default: return;
  }
}

void Checker::check_stream_out(const ast::Expr& construct) {
  for (size_t i = 1; i < construct.args.size(); ++i) {
    const ast::Expr* arg = construct.args[i];
    if (!arg) continue;
    if (arg->kind == ast::ExprKind::int_literal) {
      // fx_5_0: ConstructGSWithSO(shader, decl0, decl1, decl2, decl3, rasterized stream)
      if (arg->number >= kStreamOutSlots)
        diags_.error("bad-stream-out-decl", arg->range,
                     "rasterized stream " + std::string(arg->text) + " is out of range: 0 to " +
                         std::to_string(kStreamOutSlots - 1) + ", or -1 for none");
      continue;
    }
    if (arg->kind != ast::ExprKind::string_literal) continue;
    const std::string_view text = arg->text;
    for (const StreamOutProblem& p : parse_stream_out_decl(text).problems) {
      const SourceRange at = stream_out_text_range(sm_, arg->range, text, p.offset, p.length);
      diags_.error("bad-stream-out-decl", at, "stream-output declaration: " + p.message);
    }
  }
}

void Checker::check_compile(const StateInfo& info, std::string_view profile, SourceRange profile_range,
                            std::string_view function, SourceRange range) {
  if (!is_shader_profile(profile)) {
    const std::vector<std::string>& profiles = shader_profiles();
    std::vector<std::string_view> names(profiles.begin(), profiles.end());
    std::string guess = closest_match(profile, names);
    std::string message = "unknown shader profile " + quote(profile);
    if (!guess.empty()) message += "; did you mean " + quote(guess) + "?";
    Diagnostic& d = diags_.error("unknown-shader-profile", profile_range, std::move(message));
    if (!guess.empty())
      if (std::optional<SourceRange> at = word_in(sm_, profile_range, profile)) d.fixits.push_back({*at, guess});
  } else if (std::string_view stage = info.stage ? profile_prefix(*info.stage) : std::string_view();
             !stage.empty() && !starts_with_i(profile, stage)) {
    diags_.error(
        "shader-stage-mismatch", profile_range,
        "state " + quote(info.name) + " needs a " + std::string(stage) + "_* profile, found " + quote(profile));
  }
  if (!function.empty() && !function_names_.find(function))
    undefined("function", function, range, names_of({Symbol::function}));
}

}  // namespace fx::check
