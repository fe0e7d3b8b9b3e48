// Building the effect model: parameters (types, folded defaults, annotations), textures
// and their procedural-generator annotations, samplers, state objects, techniques and
// passes. State values are resolved in state_resolve.cpp, summaries in pass_summary.cpp.
#include "fx/model/effect_model.h"

#include <algorithm>

#include "fx/ascii_case.h"
#include "fx/pass_states.h"
#include "model_build.h"
#include "model_internal.h"

namespace fx {
namespace {

using model_detail::ResolveContext;

// Folds an initializer; errors that make the effect wrong (division by zero, a bad
// swizzle) are errors, a merely non-foldable default (a function call) is a warning and
// the parameter starts at zero.
std::optional<Value> fold_default(const ast::Expr& e, const ConstantScope& scope, DiagnosticSink& diags,
                                  const std::string& name) {
  DiagnosticSink local;
  auto v = fold_constant(e, scope, local, false);
  for (const Diagnostic& d : local.diagnostics()) {
    if (!v && d.id == "not-constant") {
      diags.warning(
          "unfolded-initializer", e.range,
          "the default of '" + name + "' is not a constant fxkit can fold (" + d.message + "); it starts at zero");
      break;
    }
    Diagnostic& copy = diags.report(d.severity, d.id, d.range, d.message);
    copy.notes = d.notes;
  }
  return v;
}

class Builder {
 public:
  Builder(const ast::Effect& effect, DiagnosticSink& diags)
      : effect_(effect), diags_(diags), ctx_{model_, diags, {}, {}, {}, {}} {
    model_.ast = &effect;
    // Initializers and annotations see `static`/`const` parameters; state values see every
    // parameter's default (the value the pass uses until the app sets it).
    const_scope_.lookup = [this](std::string_view n) -> const Value* {
      uint32_t i = model_.find_parameter(n);
      if (i == kNoIndex) return nullptr;
      const Parameter& p = model_.parameters[i];
      if (!(p.storage & (ast::kStatic | ast::kConst)) || !p.default_value) return nullptr;
      return &*p.default_value;
    };
    const_scope_.types = &model_.types;
    ctx_.scope.lookup = [this](std::string_view n) -> const Value* {
      uint32_t i = model_.find_parameter(n);
      if (i == kNoIndex || !model_.parameters[i].default_value) return nullptr;
      return &*model_.parameters[i].default_value;
    };
    ctx_.scope.types = &model_.types;
  }

  EffectModel run() {
    for (const ast::Decl& d : effect_.decls) {
      switch (d.kind) {
        case ast::DeclKind::structure:
          if (d.structure) model_.types.add_struct(*d.structure, diags_, &const_scope_);
          if (d.structure && d.structure->kind != ast::StructKind::structure)
            ctx_.class_linkage_types.insert(d.structure->name);
          break;
        case ast::DeclKind::type_alias:
          if (d.type_alias) model_.types.add_typedef(*d.type_alias, diags_, &const_scope_);
          break;
        case ast::DeclKind::variable:
          if (d.variable) add_parameter(*d.variable, "");
          break;
        case ast::DeclKind::constant_buffer:
          if (d.constant_buffer)
            for (const ast::Variable& v : d.constant_buffer->members) add_parameter(v, d.constant_buffer->name);
          break;
        case ast::DeclKind::function:
          if (d.function) model_.functions.push_back(d.function->name);
          break;
        case ast::DeclKind::glsl_block:
          if (d.glsl_block) {
            model_.glsl_blocks.push_back(d.glsl_block->name);
            ctx_.glsl_blocks[d.glsl_block->name] = true;
          }
          break;
        case ast::DeclKind::state_object:
          if (d.state_object) add_state_object(*d.state_object);
          break;
        case ast::DeclKind::technique:
          if (d.technique) add_technique(*d.technique, "");
          break;
        case ast::DeclKind::group:
          if (d.group)
            for (const ast::Technique& t : d.group->techniques) add_technique(t, d.group->name);
          break;
        case ast::DeclKind::directive: break;
      }
    }
    // After every sampler: a `texture` takes the shape of the sampler that reads it.
    for (TextureInfo& t : model_.textures) t.shader = texture_shader(model_, model_.parameters[t.parameter], diags_);
    plan_scripts(model_, diags_);
    return std::move(model_);
  }

 private:
  std::vector<Annotation> annotations(const ast::List<ast::Annotation>& list) {
    std::vector<Annotation> out;
    for (const ast::Annotation& a : list) {
      if (!a.value) continue;
      auto v = fold_constant(*a.value, const_scope_, diags_);
      if (!v) continue;
      // `< float a[] = {1, 2}; >`: sized by its value, as a parameter by its initializer.
      std::optional<uint32_t> scalars;
      if (!a.array_dims.empty() && !a.array_dims[0] && v->is_numeric())
        scalars = static_cast<uint32_t>(v->components.size());
      Type t = model_.types.resolve(a.type, 0, a.array_dims, diags_, &const_scope_, scalars);
      if (t.cls == TypeClass::error) continue;
      auto converted = convert_value(*v, t, a.value->range, diags_);
      if (!converted) continue;
      out.push_back({a.name, std::move(*converted), a.range, a.value->range});
    }
    return out;
  }

  void add_parameter(const ast::Variable& v, const std::string& cbuffer) {
    if (v.name.empty() || model_.parameter_index.count(v.name)) return;  // duplicates: the checker's report
    // A stateblock holds pass states, which the passes that name it apply (fx/pass_states.h).
    if (iequals(v.type.name, "stateblock")) return;
    Parameter p;
    p.name = v.name;
    p.type = model_.types.resolve(v.type, v.storage, v.array_dims, diags_, &const_scope_, initializer_scalars(v));
    p.semantic = v.semantic;
    p.storage = v.storage;
    p.constant_buffer = cbuffer;
    p.register_binding = v.register_binding;
    p.range = v.range;
    p.name_range = v.name_range;
    p.decl = &v;
    p.annotations = annotations(v.annotations);
    const TypeClass cls = p.type.cls;
    p.shader_visible = !(v.storage & ast::kStatic) &&
                       (p.type.is_numeric() || cls == TypeClass::structure || cls == TypeClass::texture ||
                        cls == TypeClass::sampler || cls == TypeClass::view);
    const uint32_t index = static_cast<uint32_t>(model_.parameters.size());
    if (v.initializer) initialize(p, *v.initializer, index);
    model_.parameter_index.emplace(p.name, index);
    model_.parameters.push_back(std::move(p));
    if (cls == TypeClass::texture) add_texture(index);
  }

  // The scalars of an unsized array's initializer (`float2 Offsets[] = { ... };`), which
  // size the array; folding errors are reported when the default is folded.
  std::optional<uint32_t> initializer_scalars(const ast::Variable& v) {
    if (!v.initializer || v.array_dims.empty() || v.array_dims[0]) return std::nullopt;
    DiagnosticSink quiet;
    std::optional<Value> folded = fold_constant(*v.initializer, const_scope_, quiet, false);
    if (!folded || !folded->is_numeric()) return std::nullopt;
    return static_cast<uint32_t>(folded->components.size());
  }

  void initialize(Parameter& p, const ast::Expr& init, uint32_t index) {
    switch (p.type.cls) {
      case TypeClass::sampler:
        if (init.kind == ast::ExprKind::state_block)
          add_sampler(p.name, init.states, index, kNoIndex, init.range, false);
        else if (init.kind == ast::ExprKind::init_list)
          for (size_t i = 0; i < init.args.size(); ++i)
            if (init.args[i] && init.args[i]->kind == ast::ExprKind::state_block)
              add_sampler(p.name + "[" + std::to_string(i) + "]", init.args[i]->states, index, kNoIndex,
                          init.args[i]->range, false);
        return;
      case TypeClass::shader: ctx_.shader_variables[p.name] = &init; return;
      case TypeClass::texture:
      case TypeClass::view:
      case TypeClass::state_object:
      case TypeClass::error:
      case TypeClass::void_type: return;
      default: break;
    }
    if (init.kind == ast::ExprKind::state_block) {
      diags_.error("initializer-mismatch", init.range, "sampler_state initialises a " + p.type.to_string());
      return;
    }
    if (auto v = fold_default(init, const_scope_, diags_, p.name))
      p.default_value = convert_value(*v, p.type, init.range, diags_);
  }

  void add_texture(uint32_t parameter) {
    const Parameter& p = model_.parameters[parameter];
    TextureInfo t;
    t.parameter = parameter;
    t.shape = p.type.texture;
    for (const Annotation& a : p.annotations) {
      if (iequals(a.name, "Generator") && a.value.is_string()) {
        t.generator = a.value.text;
        t.generator_range = a.range;
      } else if ((iequals(a.name, "ResourceName") || iequals(a.name, "File")) && a.value.is_string()) {
        t.resource_name = a.value.text;
        t.resource_range = a.range;
      } else if (a.value.is_string()) {
        t.generator_params.set(a.name, a.value.text);
      } else if (a.value.components.size() == 1) {
        t.generator_params.set(a.name, a.value.number());
      }
    }
    if (!t.generator.empty()) {
      std::vector<std::string_view> names = shading::generator_names();
      if (std::none_of(names.begin(), names.end(), [&](std::string_view n) { return iequals(n, t.generator); })) {
        Diagnostic& d =
            diags_.error("unknown-generator", t.generator_range, "unknown texture generator '" + t.generator + "'");
        std::string guess = closest_match(t.generator, names);
        if (!guess.empty()) d.message += "; did you mean '" + guess + "'?";
      }
    }
    model_.textures.push_back(std::move(t));
  }

  void add_sampler(std::string name, const ast::List<ast::StateAssignment>& states, uint32_t parameter, uint32_t object,
                   SourceRange range, bool d3d10) {
    std::vector<ResolvedState> resolved;
    StateBlock block = d3d10 ? StateBlock::sampler_object : StateBlock::sampler_state;
    for (const ast::StateAssignment& a : states) {
      ResolvedState r;
      if (model_detail::resolve_state(a, block, ctx_, r, nullptr, nullptr)) resolved.push_back(std::move(r));
    }
    SamplerInfo s;
    s.name = std::move(name);
    s.parameter = parameter;
    s.state_object = object;
    s.range = range;
    s.desc = model_detail::describe_sampler(resolved, d3d10, s.texture);
    if (object != kNoIndex) model_.state_objects[object].states = std::move(resolved);
    model_.samplers.push_back(std::move(s));
  }

  // A state object, or an array of them written with one `{ }` per element: each element is
  // an object of its own named `B[i]`, and `B` alone names element 0.
  void add_state_object(const ast::StateObject& o) {
    if (o.element_states.empty()) return add_state_object(o, o.name, o.states);
    if (model_.state_object_index.count(o.name)) return;
    for (size_t i = 0; i < o.element_states.size(); ++i)
      add_state_object(o, o.name + "[" + std::to_string(i) + "]", o.element_states[i]);
    if (uint32_t first = model_.find_state_object(o.name + "[0]"); first != kNoIndex)
      model_.state_object_index.emplace(o.name, first);
  }

  void add_state_object(const ast::StateObject& o, const std::string& name,
                        const ast::List<ast::StateAssignment>& states) {
    auto block = state_object_block(o.kind);
    if (!block || name.empty() || model_.state_object_index.count(name)) return;
    StateObjectInfo info;
    info.block = *block;
    info.name = name;
    info.range = o.range;
    info.annotations = annotations(o.annotations);
    const uint32_t index = static_cast<uint32_t>(model_.state_objects.size());
    model_.state_object_index.emplace(name, index);
    model_.state_objects.push_back(std::move(info));
    if (*block == StateBlock::sampler_object) {
      model_.state_objects[index].sampler = static_cast<uint32_t>(model_.samplers.size());
      add_sampler(name, states, kNoIndex, index, o.range, true);
      return;
    }
    std::vector<ResolvedState> resolved;
    for (const ast::StateAssignment& a : states) {
      ResolvedState r;
      if (model_detail::resolve_state(a, *block, ctx_, r, nullptr, nullptr)) resolved.push_back(std::move(r));
    }
    model_.state_objects[index].states = std::move(resolved);
  }

  void add_technique(const ast::Technique& t, const std::string& group) {
    TechniqueInfo info;
    info.name = t.name;
    info.version = t.version;
    info.group = group;
    info.annotations = annotations(t.annotations);
    info.range = t.range;
    for (const ast::Pass& p : t.passes) {
      PassInfo pass;
      pass.name = p.name;
      pass.annotations = annotations(p.annotations);
      pass.range = p.range;
      for (const ast::StateAssignment* a : applied_pass_states(effect_, p)) {
        ResolvedState r;
        if (model_detail::resolve_state(*a, StateBlock::pass, ctx_, r, &pass.shaders, &pass.unsupported))
          pass.states.push_back(std::move(r));
      }
      pass.summary = model_detail::summarize_pass(pass.states, model_);
      // A pixel shader replaces the texture stages' blending, as in D3D9, and reads the
      // bump-environment states itself: those are not a reason the pass cannot run.
      const ShaderBinding* pixel = pass.shader(PassStage::pixel);
      if (pixel && pixel->source != ShaderSource::null)
        std::erase_if(pass.unsupported,
                      [](const UnsupportedState& u) { return u.info && pixel_shader_replaces_or_reads(*u.info); });
      info.passes.push_back(std::move(pass));
    }
    model_.techniques.push_back(std::move(info));
  }

  const ast::Effect& effect_;
  DiagnosticSink& diags_;
  EffectModel model_;
  ConstantScope const_scope_;
  ResolveContext ctx_;
};

}  // namespace

const Annotation* find_annotation(const std::vector<Annotation>& list, std::string_view name) {
  for (const Annotation& a : list)
    if (a.name == name) return &a;
  return nullptr;
}

const ShaderBinding* PassInfo::shader(PassStage stage) const {
  for (const ShaderBinding& s : shaders)
    if (s.stage == stage) return &s;
  return nullptr;
}

SamplerDesc PassInfo::stage_sampler(uint32_t stage, uint32_t& texture) const {
  std::vector<ResolvedState> indexed;
  for (const ResolvedState& s : states)
    if (s.info && s.index == stage &&
        (s.info->block == StateBlock::sampler_state || s.info->field == StateField::texture))
      indexed.push_back(s);
  return model_detail::describe_sampler(indexed, false, texture);
}

bool pixel_shader_replaces_or_reads(const StateInfo& info) {
  if (info.field == StateField::stage_color_op || info.field == StateField::stage_alpha_op) return true;
  for (std::string_view name :
       {"ColorArg0", "ColorArg1", "ColorArg2", "AlphaArg0", "AlphaArg1", "AlphaArg2", "ResultArg", "BumpEnvMat00",
        "BumpEnvMat01", "BumpEnvMat10", "BumpEnvMat11", "BumpEnvLScale", "BumpEnvLOffset"})
    if (iequals(info.name, name)) return true;
  return false;
}

uint32_t EffectModel::find_parameter(std::string_view name) const {
  auto it = parameter_index.find(std::string(name));
  return it == parameter_index.end() ? kNoIndex : it->second;
}

uint32_t EffectModel::find_state_object(std::string_view name) const {
  auto it = state_object_index.find(std::string(name));
  return it == state_object_index.end() ? kNoIndex : it->second;
}

const TechniqueInfo* EffectModel::find_technique(std::string_view name) const {
  for (const TechniqueInfo& t : techniques)
    if (t.name == name) return &t;
  for (uint32_t i = 0; i < techniques.size(); ++i)
    if (techniques[i].name.empty() && technique_label(i) == name) return &techniques[i];
  return nullptr;
}

std::string technique_label(std::string_view name, uint32_t index) {
  return name.empty() ? "technique" + std::to_string(index) : std::string(name);
}

std::string EffectModel::technique_label(uint32_t index) const {
  return fx::technique_label(index < techniques.size() ? techniques[index].name : "", index);
}

const TextureInfo* EffectModel::texture_of(uint32_t parameter) const {
  for (const TextureInfo& t : textures)
    if (t.parameter == parameter) return &t;
  return nullptr;
}

EffectModel build_effect_model(const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& diags) {
  (void)sm;  // locations are SourceRanges already; kept for notes that need file lookups
  return Builder(effect, diags).run();
}

}  // namespace fx
