// The checker's driver: global symbols and duplicate definitions, functions, annotations
// and parameter initializers, techniques and passes, and the effect-profile rules.
#include "fx/checker.h"

#include <algorithm>
#include <array>

#include "checker_internal.h"
#include "fx/name_filter.h"

namespace fx {
namespace check {
namespace {

// Components of a numeric type name (`float3` 3, `float4x4` 16, `int` 1), or 0 when the
// type is not numeric (string, texture, struct names).
int numeric_components(std::string_view type) {
  static constexpr std::string_view kScalars[] = {"bool",       "int",      "uint",     "dword",
                                                  "half",       "float",    "double",   "min16float",
                                                  "min10float", "min16int", "min12int", "min16uint"};
  if (type.empty()) return 0;
  const char first = ascii_lower(type[0]);
  for (std::string_view scalar : kScalars) {
    // The first letter rules out most rows before a case-folding compare.
    if (scalar[0] != first || type.size() < scalar.size() || !iequals(type.substr(0, scalar.size()), scalar)) continue;
    std::string_view rest = type.substr(scalar.size());
    if (rest.empty()) return 1;
    if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') return rest[0] - '0';
    if (rest.size() == 3 && ascii_lower(rest[1]) == 'x' && rest[0] >= '1' && rest[0] <= '4' && rest[2] >= '1' &&
        rest[2] <= '4')
      return (rest[0] - '0') * (rest[2] - '0');
  }
  return 0;
}

// A type an annotation may have: numeric (scalars, vectors, matrices, `vector`/`matrix`
// templates), bool or string.
bool annotation_type(std::string_view type) {
  return numeric_components(type) > 0 || iequals(type, "string") || type == "vector" || type == "matrix";
}

// The first identifier in `e` that names one of `annotations`, or nullptr.
const ast::Expr* annotation_named_in(const ast::Expr& e, const ast::List<ast::Annotation>& annotations) {
  if (e.kind == ast::ExprKind::identifier) {
    for (const ast::Annotation& a : annotations)
      if (a.name == e.text) return &e;
    return nullptr;
  }
  for (const ast::ExprPtr& arg : e.args)
    if (arg)
      if (const ast::Expr* found = annotation_named_in(*arg, annotations)) return found;
  return nullptr;
}

// Leaves of a (possibly nested) initializer list; nullopt if any is not a literal.
std::optional<size_t> literal_leaves(const ast::Expr& e) {
  if (e.kind != ast::ExprKind::init_list) {
    bool literal = e.kind == ast::ExprKind::int_literal || e.kind == ast::ExprKind::float_literal ||
                   e.kind == ast::ExprKind::bool_literal ||
                   (e.kind == ast::ExprKind::unary && e.args.size() == 1 && e.args[0] &&
                    (e.args[0]->kind == ast::ExprKind::int_literal || e.args[0]->kind == ast::ExprKind::float_literal));
    return literal ? std::optional<size_t>(1) : std::nullopt;
  }
  size_t n = 0;
  for (const ast::ExprPtr& a : e.args) {
    if (!a) return std::nullopt;
    std::optional<size_t> k = literal_leaves(*a);
    if (!k) return std::nullopt;
    n += *k;
  }
  return n;
}

bool contains_string(const ast::Expr& e) {
  if (e.kind == ast::ExprKind::string_literal) return true;
  if (e.kind != ast::ExprKind::init_list) return false;
  return std::any_of(e.args.begin(), e.args.end(), [](const ast::ExprPtr& a) { return a && contains_string(*a); });
}

bool only_strings(const ast::Expr& e) {
  if (e.kind == ast::ExprKind::string_literal) return true;
  if (e.kind != ast::ExprKind::init_list) return false;
  return std::all_of(e.args.begin(), e.args.end(), [](const ast::ExprPtr& a) { return a && only_strings(*a); });
}

// A function's parameter types as one string, to tell overloads from redefinitions.
std::string signature(const ast::Function& f) {
  std::string s;
  for (const ast::Variable& p : f.params) {
    s += p.type.name;
    if (!p.type.template_arg.empty()) s += "<" + p.type.template_arg + ">";
    s.append(p.array_dims.size(), '[');
    s += ',';
  }
  return s;
}

// The profile an effect's `fx.N.0` header names, if it has one.
std::optional<EffectProfile> header_profile(const ast::Effect& effect) {
  if (effect.profile_header.empty()) return std::nullopt;
  std::optional<EffectProfile> p = parse_effect_profile(effect.profile_header);
  if (p == EffectProfile::automatic) return std::nullopt;
  return p;
}

}  // namespace

std::string quote(std::string_view text) {
  std::string quoted(1, '\'');
  quoted.append(text).push_back('\'');
  return quoted;
}

Checker::Checker(const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& diags, const CheckOptions& options)
    : effect_(effect), sm_(sm), diags_(diags), options_(options) {
  profile_ = options.profile == EffectProfile::automatic ? header_profile(effect) : options.profile;
}

EffectProfile Checker::profile() const {
  if (!profile_) profile_ = infer_profile(effect_);
  return *profile_;
}

void Checker::run() {
  collect_symbols();
  check_functions();
  check_profile_rules();
  check_shader_code();
  NameTable<SourceRange> techniques, groups;
  auto technique = [&](const ast::Technique& t, NameTable<SourceRange>& names) {
    if (!t.name.empty()) {
      auto [entry, fresh] = names.emplace(t.name, t.name_range);
      if (!fresh) report_duplicate("technique", t.name, t.name_range, entry->second);
    }
    check_technique(t);
  };
  for (const ast::Decl& d : effect_.decls) {
    switch (d.kind) {
      case ast::DeclKind::variable: check_variable(*d.variable); break;
      case ast::DeclKind::constant_buffer:
        for (const ast::Variable& v : d.constant_buffer->members) check_variable(v);
        break;
      case ast::DeclKind::technique: technique(*d.technique, techniques); break;
      case ast::DeclKind::state_object: {
        const ast::StateObject& o = *d.state_object;
        check_annotations(o.annotations);
        if (std::optional<StateBlock> block = state_object_block(o.kind)) {
          check_states(o.states, *block, 10);
          for (const ast::List<ast::StateAssignment>& element : o.element_states) check_states(element, *block, 10);
        }
        break;
      }
      case ast::DeclKind::group: {
        const ast::FxGroup& g = *d.group;
        if (auto [entry, fresh] = groups.emplace(g.name, g.name_range); !fresh)
          report_duplicate("fxgroup", g.name, g.name_range, entry->second);
        check_annotations(g.annotations);
        // fxc refuses a group without techniques (vkd3d's effect-technique-fx_5 tests).
        if (g.techniques.empty())
          diags_.error("empty-fxgroup", g.name_range.valid() ? g.name_range : g.range,
                       "fxgroup " + quote(g.name) + " holds no technique; fxc refuses an empty group");
        NameTable<SourceRange> in_group;
        for (const ast::Technique& t : g.techniques) technique(t, in_group);
        break;
      }
      default: break;
    }
  }
}

void Checker::report_duplicate(std::string_view what, std::string_view name, SourceRange range, SourceRange previous) {
  Diagnostic& d =
      diags_.error("duplicate-definition", range, std::string(what) + " " + quote(name) + " is already defined");
  if (previous.valid()) d.notes.push_back({previous.begin, "previous definition is here"});
}

void Checker::define(std::string_view name, SourceRange range, Symbol symbol, std::string_view what) {
  if (name.empty()) return;
  symbol.range = range;
  auto [entry, fresh] = globals_.emplace(name, symbol);
  if (!fresh) report_duplicate(what, name, range, entry->second.range);
}

void Checker::collect_symbols() {
  globals_.reserve(effect_.decls.size());
  for (const ast::Decl& d : effect_.decls) {
    switch (d.kind) {
      case ast::DeclKind::variable: {
        const ast::Variable& v = *d.variable;
        std::optional<int64_t> size;
        if (v.array_dims.size() == 1 && v.array_dims[0]) size = literal_int(*v.array_dims[0]);
        define(v.name, v.name_range, {Symbol::variable, v.type.name, {}, size.value_or(0)}, "parameter");
        break;
      }
      case ast::DeclKind::constant_buffer:
        for (const ast::Variable& v : d.constant_buffer->members)
          define(v.name, v.name_range, {Symbol::variable, v.type.name, {}}, "parameter");
        break;
      case ast::DeclKind::state_object:
        define(d.state_object->name, d.state_object->name_range, {Symbol::state_object, d.state_object->kind, {}},
               "state object");
        break;
      case ast::DeclKind::structure:
        define(d.structure->name, d.structure->name_range, {Symbol::structure, {}, {}}, "struct");
        structs_.emplace(d.structure->name, d.structure);
        break;
      case ast::DeclKind::type_alias:
        define(d.type_alias->name, d.type_alias->range, {Symbol::type_alias, {}, {}}, "typedef");
        break;
      case ast::DeclKind::glsl_block:
        define(d.glsl_block->name, d.glsl_block->name_range, {Symbol::glsl_block, {}, {}}, "GLSL block");
        break;
      case ast::DeclKind::function: functions_.emplace_back(d.function->name, d.function); break;
      case ast::DeclKind::technique:
        has_technique_ = true;
        has_d3d9_technique_ |= d.technique->version == 9;
        break;
      case ast::DeclKind::group: has_technique_ |= !d.group->techniques.empty(); break;
      default: break;
    }
  }
  std::stable_sort(functions_.begin(), functions_.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  function_names_.reserve(functions_.size());
  for (const auto& [name, f] : functions_) function_names_.emplace(name, f);
}

void Checker::check_functions() {
  for (const auto& [name, f] : functions_)
    if (!f->body.empty()) check_local_annotations(*f);
  std::vector<std::pair<std::string, const ast::Function*>> defined;
  for (auto group = functions_.begin(); group != functions_.end();) {
    std::string_view name = group->first;
    auto group_end = std::find_if(group, functions_.end(), [&](const auto& f) { return f.first != name; });
    if (const Symbol* s = lookup(name)) {
      report_duplicate("function", name, group->second->name_range, s->range);
    }
    if (group_end - group == 1) {  // no overloads: nothing to tell apart
      group = group_end;
      continue;
    }
    // Overloads differ in parameter types; a prototype may precede its definition.
    defined.clear();
    for (; group != group_end; ++group) {
      const ast::Function* f = group->second;
      if (f->body.empty()) continue;
      std::string sig = signature(*f);
      auto prev = std::find_if(defined.begin(), defined.end(), [&](const auto& p) { return p.first == sig; });
      if (prev != defined.end()) {
        report_duplicate("function", name, f->name_range, prev->second->name_range);
      } else {
        defined.emplace_back(std::move(sig), f);
      }
    }
  }
}

void Checker::check_profile_rules() {
  // Only a given profile can be too old for a construct here (see profile_).
  if (profile_) check_against_profile(*profile_);
  if (!has_technique_ && options_.require_technique) {
    SourceRange at;
    if (!effect_.tokens.empty()) at = effect_.tokens.front().range();
    // fxc refuses an fx_2_0 effect without a technique; FX10/11 effects without one are
    // pools and libraries. Only a profile the caller gives says the file is compiled as an
    // fx_2_0 effect: many .fx files are shaders for ps_2_0 and the like, or libraries, and
    // the pre-release `fx.2.0` header of the seed listings (wood.fx) comes without one.
    const bool refused = options_.profile == EffectProfile::fx_2_0;
    diags_.report(refused ? Severity::error : Severity::warning, "no-technique", at,
                  "the effect defines no technique, so it has nothing to apply");
  }
}

void Checker::check_against_profile(EffectProfile profile) {
  auto require = [&](EffectProfile needed, SourceRange range, std::string_view what) {
    if (profile >= needed) return;
    diags_.error("profile-mismatch", range,
                 std::string(what) + " needs effect profile " + std::string(to_string(needed)) +
                     " or later; the effect is " + std::string(to_string(profile)));
  };
  auto technique = [&](const ast::Technique& t) {
    SourceRange at = t.name_range.valid() ? t.name_range : t.range;
    // fxc takes technique10 under every effect profile and technique11 from fx_4_0 on
    // (vkd3d's effect-technique tests: "fx_5_0 keyword fails with fx_2_0 profile").
    if (t.version == 11) require(EffectProfile::fx_4_0, at, "technique11");
    // An inferred profile comes from the newest forms in the file; D3D9 techniques beside
    // them mean the file targets both runtimes (as SDK samples did), which is no mistake.
    bool explicit_profile = options_.profile != EffectProfile::automatic;
    if (t.version == 9 && profile >= EffectProfile::fx_4_0 && explicit_profile)
      diags_.warning("d3d9-technique", at,
                     "a Direct3D 9 'technique' in an " + std::string(to_string(profile)) + " effect; use technique" +
                         (profile == EffectProfile::fx_5_0 ? "11" : "10"));
  };
  for (const ast::Decl& d : effect_.decls) {
    switch (d.kind) {
      case ast::DeclKind::technique: technique(*d.technique); break;
      case ast::DeclKind::group:
        require(EffectProfile::fx_5_0, d.group->name_range, "fxgroup");
        for (const ast::Technique& t : d.group->techniques) technique(t);
        break;
      case ast::DeclKind::state_object:
        require(EffectProfile::fx_4_0,
                d.state_object->name_range.valid() ? d.state_object->name_range : d.state_object->range,
                d.state_object->kind);
        break;
      case ast::DeclKind::constant_buffer:
        require(EffectProfile::fx_4_0, d.constant_buffer->range,
                d.constant_buffer->texture_buffer ? "tbuffer" : "cbuffer");
        break;
      case ast::DeclKind::structure:
        if (d.structure->kind != ast::StructKind::structure)
          require(EffectProfile::fx_5_0, d.structure->name_range,
                  d.structure->kind == ast::StructKind::class_type ? "class" : "interface");
        break;
      default: break;
    }
  }
}

void Checker::check_value_type(std::string_view type_name, size_t array_dims, const ast::Expr& value,
                               std::string_view what, std::string_view name, std::string_view id) {
  // Built only for a report: this runs for every parameter and annotation.
  auto subject = [&] { return std::string(what) + " " + quote(name); };
  if (iequals(type_name, "string")) {
    if (!only_strings(value)) diags_.error(std::string(id), value.range, subject() + " is a string; its value is not");
    return;
  }
  int components = numeric_components(type_name);
  if (components == 0) return;
  if (contains_string(value)) {
    diags_.error(std::string(id), value.range, subject() + " is " + quote(type_name) + "; its value is a string");
    return;
  }
  if (array_dims != 0 || value.kind != ast::ExprKind::init_list) return;
  std::optional<size_t> leaves = literal_leaves(value);
  if (leaves && *leaves != static_cast<size_t>(components))
    diags_.error(std::string(id), value.range,
                 subject() + " is " + quote(type_name) + " with " + std::to_string(components) + " component" +
                     (components == 1 ? "" : "s") + "; its value has " + std::to_string(*leaves));
}

void Checker::check_annotations(const ast::List<ast::Annotation>& annotations) {
  FirstSeen<std::string_view> seen;
  for (const ast::Annotation& a : annotations) {
    if (const SourceRange* previous = seen.insert(a.name, a.range))
      report_duplicate("annotation", a.name, a.range, *previous);
    // fxc's rules for annotations: literal values of numeric, bool or string type.
    if (a.storage & ast::kStatic)
      diags_.error("annotation-static", a.range, "annotation " + quote(a.name) + " cannot be 'static'");
    if (!annotation_type(a.type.name))
      diags_.error("annotation-type", a.type.range,
                   "annotation " + quote(a.name) + " has type " + quote(a.type.name) +
                       "; annotations take numeric, bool and string types");
    if (!a.value) continue;
    if (const ast::Expr* other = annotation_named_in(*a.value, annotations))
      diags_.error("annotation-reference", other->range,
                   "annotation " + quote(a.name) + " refers to annotation " + quote(other->text) +
                       "; an annotation's value cannot use another annotation");
    check_value_type(a.type.name, a.array_dims.size(), *a.value, "annotation", a.name, "annotation-type-mismatch");
  }
}

std::string Checker::object_member(const ast::TypeRef& type, int depth) const {
  const ast::Struct* s = type.definition;
  if (!s)
    if (const ast::Struct* const* named = structs_.find(type.name)) s = *named;
  if (!s || depth > 32) return {};  // struct types nest only this deep in real effects
  for (const ast::Variable& m : s->members) {
    std::string_view t = m.type.name;
    if (starts_with_i(t, "texture") || starts_with_i(t, "sampler") || shader_type_stage(t) || state_object_block(t))
      return std::string(m.name) + " (" + std::string(t) + ")";
    if (std::string inner = object_member(m.type, depth + 1); !inner.empty()) return std::string(m.name) + "." + inner;
  }
  return {};
}

void Checker::check_variable(const ast::Variable& v) {
  check_annotations(v.annotations);
  // fxc keeps objects (textures, samplers, shaders, state objects) out of the constants a
  // struct parameter is laid out in.
  if (!(v.storage & ast::kStatic))
    if (std::string member = object_member(v.type, 0); !member.empty())
      diags_.error("object-in-struct", v.name_range,
                   "parameter " + quote(v.name) + " is a struct holding the object member " + member +
                       "; an effect parameter's struct cannot hold objects");
  if (!v.initializer) return;
  const ast::Expr& init = *v.initializer;
  if (init.kind == ast::ExprKind::state_block) {
    // `sampler_state { }` initializes samplers; `stateblock_state { }` holds pass states.
    if (iequals(init.text, "stateblock_state")) check_states(init.states, StateBlock::pass, 9);
    else check_sampler_state(init.states);
    return;
  }
  check_value_type(v.type.name, v.array_dims.size(), init, "parameter", v.name, "parameter-type-mismatch");
}

void Checker::check_technique(const ast::Technique& t) {
  check_annotations(t.annotations);
  FirstSeen<std::string_view> passes;
  for (const ast::Pass& p : t.passes) {
    if (!p.name.empty()) {
      if (const SourceRange* previous = passes.insert(p.name, p.name_range)) {
        // D3DX9 effects that ship with two passes of one name load: ID3DXEffect addresses
        // passes by index, and a name finds the first. The D3D10/11 effect compilers keep
        // passes in a scope per technique, where a second one is a redefinition (vkd3d,
        // which follows them, reports "already declared in this scope").
        if (t.version == 9 && profile() < EffectProfile::fx_4_0) {
          Diagnostic& d = diags_.warning("duplicate-pass-name", p.name_range,
                                         "pass " + quote(p.name) +
                                             " is already defined in this technique; D3DX9 loads it, but by name only "
                                             "the first is found (address passes by index)");
          if (previous->valid()) d.notes.push_back({previous->begin, "previous definition is here"});
        } else {
          report_duplicate("pass", p.name, p.name_range, *previous);
        }
      }
    }
    check_annotations(p.annotations);
    check_states(p.states, StateBlock::pass, t.version);
  }
}

const Symbol* Checker::lookup(std::string_view name) const { return globals_.find(name); }

std::vector<std::string_view> Checker::names_of(std::initializer_list<Symbol::Kind> kinds) const {
  std::vector<std::string_view> names;
  for (const auto& [name, s] : globals_)
    if (std::find(kinds.begin(), kinds.end(), s.kind) != kinds.end()) names.push_back(name);
  if (std::find(kinds.begin(), kinds.end(), Symbol::function) != kinds.end())
    for (const auto& [name, f] : function_names_) names.push_back(name);
  // Hash order would make did-you-mean ties depend on the standard library.
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace check

std::string_view to_string(EffectProfile profile) {
  switch (profile) {
    case EffectProfile::automatic: return "auto";
    case EffectProfile::fx_2_0: return "fx_2_0";
    case EffectProfile::fx_4_0: return "fx_4_0";
    case EffectProfile::fx_4_1: return "fx_4_1";
    case EffectProfile::fx_5_0: return "fx_5_0";
  }
  return "auto";
}

std::optional<EffectProfile> parse_effect_profile(std::string_view text) {
  std::string t;
  for (char c : text) t.push_back(c == '.' ? '_' : ascii_lower(c));
  if (t == "fx_2_0") return EffectProfile::fx_2_0;
  if (t == "fx_4_0") return EffectProfile::fx_4_0;
  if (t == "fx_4_1") return EffectProfile::fx_4_1;
  if (t == "fx_5_0") return EffectProfile::fx_5_0;
  if (t == "auto") return EffectProfile::automatic;
  return std::nullopt;
}

EffectProfile infer_profile(const ast::Effect& effect) {
  if (std::optional<EffectProfile> p = check::header_profile(effect)) return *p;
  // The checker relies on this reading every construct whose profile it checks (see
  // Checker::profile_): techniques, fxgroups, state objects, cbuffers, pass states.
  EffectProfile needed = EffectProfile::fx_2_0;
  auto need = [&](EffectProfile p) { needed = std::max(needed, p); };
  // Only D3D10/11 pass states raise the profile. Their names, folded to lower case, are in a
  // filter: a state it rules out (any D3D9 state, mostly) needs no table lookup here.
  static const NameFilter kNewerPassStates = [] {
    NameFilter f;
    for (const StateInfo& s : all_states())
      if (s.block == StateBlock::pass && s.api != StateApi::d3d9) f.add(ascii_lower(s.name));
    return f;
  }();
  auto newer_pass_state = [](std::string_view name) -> const StateInfo* {
    std::array<char, 64> folded;
    if (name.size() <= folded.size()) {
      for (size_t i = 0; i < name.size(); ++i) folded[i] = ascii_lower(name[i]);
      if (!kNewerPassStates.may_contain({folded.data(), name.size()})) return nullptr;
    }
    return find_state(name, StateBlock::pass);
  };
  auto technique = [&](const ast::Technique& t) {
    if (t.version == 11) need(EffectProfile::fx_5_0);
    if (t.version == 10) need(EffectProfile::fx_4_0);
    for (const ast::Pass& p : t.passes)
      for (const ast::StateAssignment& s : p.states)
        if (const StateInfo* info = newer_pass_state(s.name))
          need(info->api == StateApi::d3d11   ? EffectProfile::fx_5_0
               : info->api == StateApi::d3d10 ? EffectProfile::fx_4_0
                                              : EffectProfile::fx_2_0);
  };
  for (const ast::Decl& d : effect.decls) {
    switch (d.kind) {
      case ast::DeclKind::technique: technique(*d.technique); break;
      case ast::DeclKind::group:
        need(EffectProfile::fx_5_0);
        for (const ast::Technique& t : d.group->techniques) technique(t);
        break;
      case ast::DeclKind::state_object:
      case ast::DeclKind::constant_buffer: need(EffectProfile::fx_4_0); break;
      case ast::DeclKind::structure:  // dynamic linkage: interfaces and classes
        if (d.structure->kind != ast::StructKind::structure) need(EffectProfile::fx_5_0);
        break;
      default: break;
    }
  }
  return needed;
}

void check_effect(const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& diags,
                  const CheckOptions& options) {
  check::Checker(effect, sm, diags, options).run();
}

}  // namespace fx
