// Resolution of state assignments (pass states, sampler_state, state objects) to typed
// values: enum values, flags, colours, parameter references, shader bindings and state
// object references. Names were checked against the state table by the checker; this
// file reports only what needs values (non-constant expressions, bad references).
#include <algorithm>
#include <cmath>

#include "fx/model/value.h"
#include "model_build.h"
#include "model_internal.h"

namespace fx::model_detail {
namespace {

// `(.5f, .5f, .5f, .5f)` parses as a comma expression: collect its operands in order.
void flatten_comma(const ast::Expr& e, std::vector<const ast::Expr*>& out) {
  if (e.kind == ast::ExprKind::binary && e.text == "," && e.args.size() == 2 && e.args[0] && e.args[1]) {
    flatten_comma(*e.args[0], out);
    flatten_comma(*e.args[1], out);
  } else {
    out.push_back(&e);
  }
}

std::optional<Value> fold_list(const ast::Expr& e, ResolveContext& ctx, bool quiet) {
  std::vector<const ast::Expr*> parts;
  flatten_comma(e, parts);
  if (parts.size() == 1) return fold_constant(e, ctx.scope, ctx.diags, quiet);
  Value out;
  out.type = make_numeric(BaseType::float32, 1, static_cast<uint8_t>(std::min<size_t>(parts.size(), 4)));
  for (const ast::Expr* p : parts) {
    auto v = fold_constant(*p, ctx.scope, ctx.diags, quiet);
    if (!v || !v->is_numeric()) return std::nullopt;
    out.components.insert(out.components.end(), v->components.begin(), v->components.end());
  }
  if (out.components.size() > 4 || out.components.size() != parts.size()) {
    out.type = make_numeric(BaseType::float32);
    out.type.array_dims = {static_cast<uint32_t>(out.components.size())};
  }
  return out;
}

// The parameter an identifier or `<ref>` names (possibly parenthesised), or kNoIndex.
uint32_t parameter_named(const ast::Expr& e, const EffectModel& model) {
  if (e.kind == ast::ExprKind::identifier || e.kind == ast::ExprKind::reference) return model.find_parameter(e.text);
  if (e.kind == ast::ExprKind::index && !e.args.empty() && e.args[0]) return parameter_named(*e.args[0], model);
  return kNoIndex;
}

bool is_null(const ast::Expr& e) {
  return e.kind == ast::ExprKind::null || (e.kind == ast::ExprKind::identifier && iequals(e.text, "NULL")) ||
         (e.kind == ast::ExprKind::int_literal && e.number == 0);
}

// Enumeration and flags values: names, integers and `|` combinations.
std::optional<int64_t> enum_value(const ast::Expr& e, const StateInfo& info, ResolveContext& ctx) {
  if (e.kind == ast::ExprKind::identifier) {
    if (auto v = find_enum(info, e.text)) return *v;
    if (const Value* c = ctx.scope.lookup ? ctx.scope.lookup(e.text) : nullptr; c && c->is_numeric())
      return static_cast<int64_t>(c->number());
    return std::nullopt;  // the checker reported an unknown enum name
  }
  if (e.kind == ast::ExprKind::binary && (e.text == "|" || e.text == "+") && e.args.size() == 2 && e.args[0] &&
      e.args[1]) {
    auto a = enum_value(*e.args[0], info, ctx), b = enum_value(*e.args[1], info, ctx);
    if (!a || !b) return std::nullopt;
    return e.text == "|" ? (*a | *b) : (*a + *b);
  }
  auto v = fold_constant(e, ctx.scope, ctx.diags, true);
  if (v && v->is_numeric()) return static_cast<int64_t>(v->number());
  return std::nullopt;
}

// D3DCOLOR 0xAARRGGBB -> r, g, b, a in [0, 1].
std::array<float, 4> unpack_color(uint32_t c) {
  return {((c >> 16) & 0xFF) / 255.0f, ((c >> 8) & 0xFF) / 255.0f, (c & 0xFF) / 255.0f, ((c >> 24) & 0xFF) / 255.0f};
}

// The first part of `e` only the effect runtime could compute when the pass is applied: a
// call of a function of the effect, or a parameter the application sets that has no value
// to fold. fxc compiles such a state into an expression (a D3D9 preshader, an fx_4/fx_5
// FXLVM expression) that D3DX evaluates at apply time.
const ast::Expr* runtime_part(const ast::Expr& e, const EffectModel& model) {
  if (e.kind == ast::ExprKind::call &&
      std::find(model.functions.begin(), model.functions.end(), e.text) != model.functions.end())
    return &e;
  if (e.kind == ast::ExprKind::identifier || e.kind == ast::ExprKind::reference) {
    uint32_t p = model.find_parameter(e.text);
    if (p != kNoIndex && !model.parameters[p].is_static() && !model.parameters[p].default_value) return &e;
  }
  for (const ast::ExprPtr& a : e.args)
    if (a)
      if (const ast::Expr* part = runtime_part(*a, model)) return part;
  return nullptr;
}

void not_constant(ResolveContext& ctx, const ast::Expr& e, const StateInfo& info) {
  if (const ast::Expr* part = runtime_part(e, ctx.model)) {
    std::string what = part->kind == ast::ExprKind::call ? "a call of '" + std::string(part->text) + "'"
                                                         : "the parameter '" + std::string(part->text) + "'";
    ctx.diags.error("unsupported-state-expression", e.range,
                    "the value of '" + std::string(info.name) + "' depends on " + what +
                        ": fxc compiles it to an expression the effect runtime evaluates when the pass is "
                        "applied, which fxkit does not run; set the state to a constant or to a parameter");
    return;
  }
  // Re-fold loudly so the user sees what is not constant.
  if (!fold_constant(e, ctx.scope, ctx.diags, false)) return;
  ctx.diags.error("bad-state-value", e.range,
                  "value of '" + std::string(info.name) + "' is not a " + std::string(to_string(info.type)));
}

ShaderBinding shader_from(const ast::Expr& e, PassStage stage, ResolveContext& ctx, int depth = 0) {
  ShaderBinding b;
  b.stage = stage;
  b.range = e.range;
  b.expr = &e;
  if (depth > 8) return b;
  auto fold_args = [&](std::span<const ast::ExprPtr> args) {
    for (const ast::ExprPtr& a : args) {
      if (!a) continue;
      // `PS(g_abstractLight)`, `PS(g_lamps[1])`: an interface variable or class instance.
      const ast::Expr* base = a->kind == ast::ExprKind::index && !a->args.empty() && a->args[0] ? a->args[0] : a;
      auto named = ctx.model.parameter_index.find(base->text);
      if (base->kind == ast::ExprKind::identifier && named != ctx.model.parameter_index.end() &&
          ctx.model.parameters[named->second].decl &&
          ctx.class_linkage_types.count(std::string(ctx.model.parameters[named->second].decl->type.name)))
        continue;
      auto v = fold_constant(*a, ctx.scope, ctx.diags, true);
      // `PS(TwelveKernel)`, a global the application sets, for a `uniform` parameter: fxc
      // binds the parameter to it (the DirectX SDK's DepthOfField passes its kernel so).
      if (!v && base->kind == ast::ExprKind::identifier && named != ctx.model.parameter_index.end() &&
          ctx.model.parameters[named->second].is_uniform())
        continue;
      if (!v) {
        ctx.diags.error("not-constant", a->range, "compile-time shader argument must be a constant");
        continue;
      }
      b.args.push_back(std::move(*v));
    }
  };
  switch (e.kind) {
    case ast::ExprKind::compile:
      b.source = ShaderSource::hlsl_compile;
      b.profile = e.text;
      b.entry = e.callee;
      fold_args(e.args);
      return b;
    case ast::ExprKind::asm_block:
      b.source = ShaderSource::asm_block;
      b.asm_code = e.code;
      b.decl_code = e.decl_code;
      return b;
    case ast::ExprKind::glsl_list:
    case ast::ExprKind::init_list:
      b.source = ShaderSource::glsl_blocks;
      b.profile = "glsl";
      for (const ast::ExprPtr& a : e.args)
        if (a && a->kind == ast::ExprKind::identifier) {
          if (!ctx.glsl_blocks.count(a->text))
            ctx.diags.error("unknown-glsl-block", a->range, "no GLSL block named '" + a->text + "'");
          b.glsl_blocks.push_back(a->text);
        }
      return b;
    case ast::ExprKind::call: {
      if (iequals(e.text, "CompileShader") && e.args.size() >= 2 && e.args[0] && e.args[1]) {
        b.source = ShaderSource::hlsl_compile;
        b.profile = e.args[0]->text;
        const ast::Expr& fn = *e.args[1];
        b.entry = fn.text;
        fold_args(fn.args);
        return b;
      }
      // BindInterfaces(shader, instances...): the instances are the compiler's (class linkage).
      if ((iequals(e.text, "ConstructGSWithSO") || iequals(e.text, "BindInterfaces")) && !e.args.empty() && e.args[0]) {
        ShaderBinding inner = shader_from(*e.args[0], stage, ctx, depth + 1);
        inner.range = e.range;
        inner.stream_output = inner.stream_output || iequals(e.text, "ConstructGSWithSO");
        return inner;
      }
      // D3D10 pass call form: SetPixelShader(x).
      if (e.args.size() == 1 && e.args[0]) return shader_from(*e.args[0], stage, ctx, depth + 1);
      break;
    }
    case ast::ExprKind::identifier:
    case ast::ExprKind::reference:
    case ast::ExprKind::index: {
      if (is_null(e)) return b;
      const ast::Expr* base = &e;
      std::optional<size_t> element;
      if (e.kind == ast::ExprKind::index && e.args.size() == 2 && e.args[0] && e.args[1]) {
        base = e.args[0];
        auto i = fold_constant(*e.args[1], ctx.scope, ctx.diags, true);
        if (i && i->is_numeric() && i->number() >= 0) element = static_cast<size_t>(i->number());
      }
      if (base->kind == ast::ExprKind::identifier && ctx.glsl_blocks.count(base->text)) {
        b.source = ShaderSource::glsl_blocks;
        b.profile = "glsl";
        b.glsl_blocks.push_back(base->text);
        return b;
      }
      auto it = ctx.shader_variables.find(base->text);
      if (it != ctx.shader_variables.end() && it->second) {
        const ast::Expr* init = it->second;
        if (init->kind == ast::ExprKind::init_list) {
          size_t k = element.value_or(0);
          init = k < init->args.size() ? init->args[k] : nullptr;
        }
        if (init) {
          ShaderBinding inner = shader_from(*init, stage, ctx, depth + 1);
          inner.variable = base->text;
          return inner;
        }
      }
      ctx.diags.error("unknown-shader", e.range, "'" + base->text + "' is not a shader variable or GLSL block");
      return b;
    }
    case ast::ExprKind::null: return b;
    case ast::ExprKind::int_literal:  // `SetGeometryShader(0)`: fx_4_0 takes 0 for NULL
      if (is_null(e)) return b;
      break;
    default: break;
  }
  ctx.diags.error("bad-state-value", e.range,
                  "not a shader: expected compile, CompileShader, asm, a GLSL block or NULL");
  return b;
}

// Whether the value names a parameter: `out` refers to it then.
bool refers_to_parameter(const ast::Expr& value, ResolveContext& ctx, ResolvedState& out) {
  const uint32_t p = parameter_named(value, ctx.model);
  if (p == kNoIndex) return false;
  out.kind = StateValueKind::parameter;
  out.target = p;
  return true;
}

// The components of a vector written as constants (`(.5, .5, .5, .5)`, `float4(...)`);
// nullopt, reported, when they are not constant.
std::optional<Value> constant_components(const ast::Expr& value, const StateInfo& info, ResolveContext& ctx) {
  auto v = fold_list(value, ctx, true);
  if (v && v->is_numeric()) return v;
  not_constant(ctx, value, info);
  return std::nullopt;
}

// A number (bool, int, float state): a constant, or a parameter the application sets.
bool resolve_number(const ast::Expr& value, const StateInfo& info, ResolveContext& ctx, ResolvedState& out) {
  if (uint32_t p = parameter_named(value, ctx.model); p != kNoIndex && !ctx.model.parameters[p].is_static()) {
    out.kind = StateValueKind::parameter;
    out.target = p;
  }
  auto v = fold_constant(value, ctx.scope, ctx.diags, true);
  if (!v || !v->is_numeric()) {
    if (out.kind == StateValueKind::parameter) return true;  // the app sets it
    not_constant(ctx, value, info);
    return false;
  }
  if (out.kind != StateValueKind::parameter)
    out.kind = info.type == StateValueType::boolean   ? StateValueKind::boolean
               : info.type == StateValueType::integer ? StateValueKind::integer
                                                      : StateValueKind::floating;
  out.floating = v->number();
  out.integer = static_cast<int64_t>(convert_component(v->number(), BaseType::uint32));
  if (info.type == StateValueType::boolean) out.integer = v->number() != 0;
  if (info.type == StateValueType::integer && v->number() < 0) out.integer = static_cast<int64_t>(v->number());
  return true;
}

// A colour or float4 state: a parameter (its default until the application sets it), a
// packed D3DCOLOR, one value for all four or up to four components.
bool resolve_vector(const ast::Expr& value, const StateInfo& info, ResolveContext& ctx, ResolvedState& out) {
  if (refers_to_parameter(value, ctx, out)) {
    const Parameter& param = ctx.model.parameters[out.target];
    if (param.default_value)
      for (size_t i = 0; i < 4 && i < param.default_value->components.size(); ++i)
        out.vector[i] = static_cast<float>(param.default_value->components[i]);
    return true;
  }
  auto v = constant_components(value, info, ctx);
  if (!v) return false;
  out.kind = StateValueKind::vector;
  if (info.type == StateValueType::color && v->components.size() == 1 &&
      (v->type.base == BaseType::int32 || v->type.base == BaseType::uint32)) {
    out.vector = unpack_color(static_cast<uint32_t>(static_cast<int64_t>(v->number())));
  } else if (v->components.size() == 1) {
    out.vector.fill(static_cast<float>(v->number()));
  } else {
    for (size_t i = 0; i < 4 && i < v->components.size(); ++i) out.vector[i] = static_cast<float>(v->components[i]);
  }
  out.constant = std::move(*v);
  return true;
}

// A matrix, texture or sampler state: NULL or a parameter of that class.
bool resolve_parameter_reference(const ast::Expr& value, const StateInfo& info, ResolveContext& ctx,
                                 ResolvedState& out) {
  if (is_null(value)) {
    out.kind = StateValueKind::null;
    return true;
  }
  uint32_t p = parameter_named(value, ctx.model);
  if (p == kNoIndex) {
    ctx.diags.error("bad-state-value", value.range,
                    "'" + std::string(info.name) + "' needs a " + std::string(to_string(info.type)) +
                        " parameter, found '" + value.text + "'");
    return false;
  }
  const Type& t = ctx.model.parameters[p].type;
  TypeClass want = info.type == StateValueType::texture   ? TypeClass::texture
                   : info.type == StateValueType::sampler ? TypeClass::sampler
                                                          : TypeClass::matrix;
  if (t.cls != want && t.cls != TypeClass::error) {
    std::string message = "'";
    message.append(info.name).append("' needs a ").append(to_string(info.type)).append(", '");
    message.append(ctx.model.parameters[p].name).append("' is a ").append(t.to_string());
    ctx.diags.error("state-type-mismatch", value.range, std::move(message));
    return false;
  }
  out.kind = StateValueKind::parameter;
  out.target = p;
  return true;
}

// A shader constant state (VertexShaderConstant4[n]): a parameter or up to four components.
bool resolve_shader_constant(const ast::Expr& value, const StateInfo& info, ResolveContext& ctx, ResolvedState& out) {
  if (refers_to_parameter(value, ctx, out)) return true;
  auto v = constant_components(value, info, ctx);
  if (!v) return false;
  out.kind = StateValueKind::vector;
  for (size_t i = 0; i < 4 && i < v->components.size(); ++i) out.vector[i] = static_cast<float>(v->components[i]);
  out.constant = std::move(*v);
  return true;
}

// A shader state: its binding, replacing an earlier one of the same stage in `shaders`.
bool resolve_shader(const ast::Expr& value, const StateInfo& info, ResolveContext& ctx, ResolvedState& out,
                    std::vector<ShaderBinding>* shaders) {
  const std::optional<PassStage> stage = info.stage;
  if (!stage) return false;
  ShaderBinding b = shader_from(value, *stage, ctx);
  out.kind = b.source == ShaderSource::null && is_null(value) ? StateValueKind::null : StateValueKind::shader;
  if (shaders) {
    auto it = std::find_if(shaders->begin(), shaders->end(), [&](const ShaderBinding& s) { return s.stage == *stage; });
    if (it != shaders->end()) {
      *it = std::move(b);
      out.target = static_cast<uint32_t>(it - shaders->begin());
    } else {
      out.target = static_cast<uint32_t>(shaders->size());
      shaders->push_back(std::move(b));
    }
  }
  return true;
}

// A state object state (SetBlendState(b)): NULL or a state object of the kind it needs.
bool resolve_state_object(const ast::Expr& value, const StateInfo& info, ResolveContext& ctx, ResolvedState& out) {
  if (is_null(value)) {
    out.kind = StateValueKind::null;
    return true;
  }
  // `Blends[1]`: the element, when the array was written one `{ }` per element.
  const bool indexed = value.kind == ast::ExprKind::index && value.args.size() == 2 && value.args[0];
  std::string name = indexed ? std::string(value.args[0]->text) : std::string(value.text);
  uint32_t o = kNoIndex;
  if (indexed && value.args[1] && value.args[1]->kind == ast::ExprKind::int_literal)
    o = ctx.model.find_state_object(name + "[" + std::to_string(static_cast<int64_t>(value.args[1]->number)) + "]");
  if (o == kNoIndex) o = ctx.model.find_state_object(name);
  if (o == kNoIndex) {
    ctx.diags.error("unknown-state-object", value.range, "no state object named '" + name + "'");
    return false;
  }
  const StateObjectInfo& obj = ctx.model.state_objects[o];
  if (!info.object_kind.empty() && !iequals(to_string(obj.block), info.object_kind)) {
    ctx.diags.error("state-type-mismatch", value.range,
                    "'" + std::string(info.name) + "' needs a " + std::string(info.object_kind) + ", '" + name +
                        "' is a " + std::string(to_string(obj.block)));
    return false;
  }
  out.kind = StateValueKind::state_object;
  out.target = o;
  return true;
}

// The state an assignment sets and its index (`Texture[1]`); a fixed-function state is
// also listed in `unsupported`. Null when the state is unknown (the checker reported it),
// has no value, or its index is no non-negative constant.
const StateInfo* resolve_target(const ast::StateAssignment& a, StateBlock block, ResolveContext& ctx,
                                ResolvedState& out, std::vector<UnsupportedState>* unsupported) {
  const StateInfo* info = find_state(a.name, block);
  if (!info || !a.value) return nullptr;
  out = ResolvedState{};
  out.info = info;
  out.range = a.range;
  if (a.index) {
    auto i = fold_constant(*a.index, ctx.scope, ctx.diags, true);
    if (!i || !i->is_numeric() || i->number() < 0) {
      ctx.diags.error("bad-state-index", a.index->range, "state index must be a non-negative integer constant");
      return nullptr;
    }
    out.index = static_cast<uint32_t>(i->number());
    out.indexed = true;
  }
  if (info->lands == StateLanding::fixed_function && unsupported)
    unsupported->push_back(
        {info, out.index, a.range, "'" + std::string(info->name) + "' is " + std::string(info->reason)});
  return info;
}

// The value expression of an assignment: in the call form (SetBlendState(b, factor, mask))
// its first argument, the others folded into `out.call_args`. Null when a call has none.
const ast::Expr* state_value(const ast::StateAssignment& a, ResolveContext& ctx, ResolvedState& out) {
  const ast::Expr* value = a.value;
  if (!a.call_style) return value;
  if (value->args.empty() || !value->args[0]) return nullptr;
  for (size_t i = 1; i < value->args.size(); ++i)
    if (value->args[i])
      if (auto v = fold_list(*value->args[i], ctx, true)) out.call_args.push_back(std::move(*v));
  return value->args[0];
}

}  // namespace

bool resolve_state(const ast::StateAssignment& a, StateBlock block, ResolveContext& ctx, ResolvedState& out,
                   std::vector<ShaderBinding>* shaders, std::vector<UnsupportedState>* unsupported) {
  const StateInfo* info = resolve_target(a, block, ctx, out, unsupported);
  if (!info) return false;
  const ast::Expr* value = state_value(a, ctx, out);
  if (!value) return false;
  switch (info->type) {
    case StateValueType::boolean:
    case StateValueType::integer:
    case StateValueType::floating: return resolve_number(*value, *info, ctx, out);
    case StateValueType::enumeration:
    case StateValueType::flags: {
      auto v = enum_value(*value, *info, ctx);
      if (!v) return false;  // reported by the checker
      out.kind = StateValueKind::enumeration;
      out.integer = *v;
      return true;
    }
    case StateValueType::color:
    case StateValueType::float4: return resolve_vector(*value, *info, ctx, out);
    case StateValueType::matrix:
    case StateValueType::texture:
    case StateValueType::sampler: return resolve_parameter_reference(*value, *info, ctx, out);
    case StateValueType::shader_constant: return resolve_shader_constant(*value, *info, ctx, out);
    case StateValueType::shader: return resolve_shader(*value, *info, ctx, out, shaders);
    case StateValueType::state_object: return resolve_state_object(*value, *info, ctx, out);
  }
  return false;
}

}  // namespace fx::model_detail
