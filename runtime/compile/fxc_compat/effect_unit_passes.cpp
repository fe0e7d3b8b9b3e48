// The passes of an effect's units: each stage's shader resolved from its state (compile,
// CompileShader, shader variables and arrays, GLSL blocks, BindInterfaces, stream output),
// compile-time argument wrappers, and the fixed-function and dynamic-linkage reasons.
#include <algorithm>
#include <cctype>
#include <optional>

#include "effect_unit_builder.h"
#include "fx/ascii_case.h"
#include "fx/compile/program_link.h"
#include "fx/emulation/assembly.h"
#include "fx/emulation/fixed_function.h"
#include "fx/pass_states.h"
#include "fx/state_table.h"
#include "numeric_type.h"

namespace fx {

using namespace detail;

void EffectUnitBuilder::collect_passes() {
  uint32_t technique_index = 0;
  for (const ast::Decl& d : effect_.decls) {
    if (d.kind == ast::DeclKind::technique) add_technique(*d.technique, "", technique_index++);
    if (d.kind == ast::DeclKind::group)
      for (const ast::Technique& t : d.group->techniques) add_technique(t, d.group->name, technique_index++);
  }
}

void EffectUnitBuilder::add_technique(const ast::Technique& t, const std::string& group, uint32_t index) {
  uint32_t pass_index = 0;
  technique_ = &t;
  for (const ast::Pass& p : t.passes) {
    pass_ = &p;
    EffectPass pass;
    pass.group = group;
    pass.technique = technique_label(t.name, index);
    pass.pass = p.name.empty() ? "pass" + std::to_string(pass_index) : p.name;
    pass.technique_index = index;
    pass.pass_index = pass_index++;
    pass.range = p.range;
    bool null_pixel = false;
    for (const ast::StateAssignment* applied : applied_pass_states(effect_, p)) {
      const ast::StateAssignment& s = *applied;
      std::optional<ShaderStage> stage = stage_of_state(s.name);
      if (!stage || !s.value) continue;
      StageUnit ps;
      ps.stage = *stage;
      ps.range = s.range;
      const ast::Expr* value = s.value;
      if (s.call_style) value = value->args.empty() ? nullptr : value->args[0];
      if (!value || !resolve(*value, ps, 0)) {  // NULL: the fixed-function stage
        null_pixel = null_pixel || *stage == ShaderStage::fragment;
        continue;
      }
      // `SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), "..."))`: stream
      // output straight from a vertex shader, with no geometry stage. It is that pass's
      // vertex shader unless the pass sets one itself.
      if (ps.stage == ShaderStage::geometry && ps.kind == StageSourceKind::hlsl &&
          ascii_lower(ps.profile).rfind("vs_", 0) == 0) {
        if (pass.find(ShaderStage::vertex)) continue;
        ps.stage = ShaderStage::vertex;
      }
      // A later assignment of the same stage wins, as in D3D.
      std::erase_if(pass.stages, [&](const StageUnit& o) { return o.stage == ps.stage; });
      pass.stages.push_back(std::move(ps));
    }
    std::stable_sort(pass.stages.begin(), pass.stages.end(),
                     [](const StageUnit& a, const StageUnit& b) { return a.stage < b.stage; });
    add_fixed_function_stages(t, pass, null_pixel);
    u_.passes_.push_back(std::move(pass));
  }
}

const EffectModel& EffectUnitBuilder::model() {
  if (!model_) {
    DiagnosticSink scratch;
    model_ = std::make_unique<EffectModel>(build_effect_model(effect_, sm_, scratch));
  }
  return *model_;
}

void EffectUnitBuilder::add_fixed_function_stages(const ast::Technique& t, EffectPass& pass, bool null_pixel) {
  if (t.version != 9) return;  // technique10/11: no pixel shader means no fragment stage
  bool glsl = false, compute = false;
  for (const StageUnit& s : pass.stages) {
    glsl = glsl || s.kind == StageSourceKind::glsl;
    compute = compute || s.stage == ShaderStage::compute;
  }
  if (glsl || compute) return;
  const StageUnit* vs = pass.find(ShaderStage::vertex);
  const StageUnit* ps = pass.find(ShaderStage::fragment);
  if (vs && ps) return;
  // Generated beside assembly or another generated stage, whose interface is D3D's full
  // register set; as the vertex stage of an HLSL pixel shader whose inputs are colours,
  // texture coordinates and fog (read from its entry's declaration: the generated stage
  // writes exactly those); and as the pixel stage of an HLSL vertex shader, reading exactly
  // the colours, texture coordinates and fog it writes (the rest at D3D's defaults).
  auto beside_hlsl = [](const StageUnit* other) { return other && other->kind != StageSourceKind::assembly; };
  std::optional<FixedFunctionState::PixelShaderInputs> hlsl_pixel_inputs;
  if (!vs && ps && ps->kind == StageSourceKind::hlsl) hlsl_pixel_inputs = pixel_shader_inputs(*ps);
  std::optional<FixedFunctionState::VertexShaderOutputs> hlsl_vertex_outputs;
  if (vs && !ps && vs->kind == StageSourceKind::hlsl) hlsl_vertex_outputs = vertex_shader_outputs(*vs);
  if ((beside_hlsl(vs) && !hlsl_vertex_outputs) || (beside_hlsl(ps) && !hlsl_pixel_inputs)) {
    if (!vs) pass.unsupported.push_back("fixed-function vertex processing: the pass sets no VertexShader");
    if (!ps)
      pass.unsupported.push_back(std::string("fixed-function pixel processing (texture stage states): ") +
                                 (null_pixel ? "PixelShader = NULL" : "the pass sets no PixelShader"));
    return;
  }
  const bool vertex = vs != nullptr, pixel = ps != nullptr;
  const EffectModel& m = model();
  if (pass.technique_index >= m.techniques.size() ||
      pass.pass_index >= m.techniques[pass.technique_index].passes.size())
    return;
  DiagnosticSink scratch;  // fixed_function_state reports nothing the model did not
  FixedFunctionState state =
      fixed_function_state(m, m.techniques[pass.technique_index].passes[pass.pass_index], scratch);
  if (hlsl_pixel_inputs) state.pixel_shader_inputs = *hlsl_pixel_inputs;
  if (hlsl_vertex_outputs) state.vertex_shader_outputs = *hlsl_vertex_outputs;
  auto add = [&](ShaderStage stage, FixedFunctionShader shader, const char* what) {
    StageUnit s;
    s.stage = stage;
    s.kind = StageSourceKind::fixed_function;
    s.profile = "fixed_function";
    s.entry_point = shader.entry;
    s.translated = std::move(shader.source);
    s.emulation = what;
    s.range = pass.range;
    pass.stages.push_back(std::move(s));
  };
  if (!vertex)
    add(ShaderStage::vertex, generate_fixed_function_vertex_shader(state),
        "fixed-function vertex processing as generated HLSL");
  if (!pixel)
    add(ShaderStage::fragment, generate_fixed_function_pixel_shader(state),
        "fixed-function texture stages as generated HLSL");
  std::stable_sort(pass.stages.begin(), pass.stages.end(),
                   [](const StageUnit& a, const StageUnit& b) { return a.stage < b.stage; });
}

namespace {

// A varying the fixed-function stages exchange, by its D3D semantic.
struct FixedVarying {
  enum Kind { diffuse, specular, fog, texcoord, system, other } kind = other;
  int index = 0;  // TEXCOORDn
};

FixedVarying fixed_varying(std::string semantic) {
  for (char& c : semantic) c = char(std::toupper(static_cast<unsigned char>(c)));
  if (semantic == "VPOS" || semantic == "VFACE" || semantic.starts_with("SV_")) return {FixedVarying::system};
  if (semantic == "COLOR" || semantic == "COLOR0") return {FixedVarying::diffuse};
  if (semantic == "COLOR1") return {FixedVarying::specular};
  if (semantic == "FOG" || semantic == "FOG0") return {FixedVarying::fog};
  if (!semantic.starts_with("TEXCOORD")) return {};
  const std::string index = semantic.substr(8);
  if (index.size() > 1 || (index.size() == 1 && (index[0] < '0' || index[0] > '7'))) return {};
  return {FixedVarying::texcoord, index.empty() ? 0 : index[0] - '0'};
}

// Components of a float vector type (float, half3, min16float2, double4), 0 for any other.
int float_components(const ast::TypeRef& t) {
  std::string_view name = t.name;
  for (std::string_view base : {"min16float", "min10float", "float", "half", "double"})
    if (name.starts_with(base)) {
      name.remove_prefix(base.size());
      if (name.empty()) return 1;
      return name.size() == 1 && name[0] >= '1' && name[0] <= '4' ? name[0] - '0' : 0;
    }
  return 0;
}

}  // namespace

const ast::Function* EffectUnitBuilder::entry_function(const StageUnit& s) const {
  std::string name = s.entry_point;
  if (name.ends_with("__fx_args")) name.resize(name.size() - std::string_view("__fx_args").size());
  for (const ast::Function* f : functions_)
    if (f->name == name && !f->body.empty()) return f;
  return nullptr;
}

const ast::Struct* EffectUnitBuilder::structure(std::string_view name) const {
  for (const ast::Decl& d : effect_.decls)
    if (d.kind == ast::DeclKind::structure && d.structure->name == name) return d.structure;
  return nullptr;
}

std::optional<FixedFunctionState::PixelShaderInputs> EffectUnitBuilder::pixel_shader_inputs(const StageUnit& ps) const {
  const ast::Function* entry = entry_function(ps);
  if (!entry) return std::nullopt;
  FixedFunctionState::PixelShaderInputs in;
  in.known = true;
  in.diffuse = in.specular = in.fog = false;
  // One varying by its semantic; false for one the generated vertex stage cannot write.
  auto take = [&in](const std::string& semantic) {
    const FixedVarying v = fixed_varying(semantic);
    switch (v.kind) {
      case FixedVarying::system: return true;
      case FixedVarying::diffuse: return in.diffuse = true;
      case FixedVarying::specular: return in.specular = true;
      case FixedVarying::fog: return in.fog = true;
      case FixedVarying::texcoord: in.texcoords |= uint8_t(1u << v.index); return true;
      case FixedVarying::other: return false;
    }
    return false;
  };
  // A varying and, for an array (`float2 uv[5] : TEXCOORD1`), the semantics its elements
  // take one by one (TEXCOORD1..TEXCOORD5).
  auto take_all = [&take](const ast::Variable& v) {
    if (v.array_dims.empty()) return take(v.semantic);
    if (v.array_dims.size() != 1 || !v.array_dims[0] || v.array_dims[0]->kind != ast::ExprKind::int_literal)
      return false;
    const auto count =
        uint32_t(std::clamp<int64_t>(int64_t(v.array_dims[0]->number), 0, 16));  // past TEXCOORD7 take() refuses
    const std::vector<std::string> semantics = consecutive_semantics(v.semantic, count);
    return std::all_of(semantics.begin(), semantics.end(), take);
  };
  for (const ast::Variable& p : entry->params) {
    if (p.storage & (ast::kUniform | ast::kOut)) continue;
    if (!p.semantic.empty()) {
      if (!take_all(p)) return std::nullopt;
      continue;
    }
    const ast::Struct* fields = structure(p.type.name);  // an input struct: each member has a semantic
    if (!fields) return std::nullopt;                    // a compile-time argument, or nothing D3D links
    for (const ast::Variable& m : fields->members)
      if (m.semantic.empty() || !take_all(m)) return std::nullopt;
  }
  return in;
}

std::optional<FixedFunctionState::VertexShaderOutputs> EffectUnitBuilder::vertex_shader_outputs(
    const StageUnit& vs) const {
  if (!vs.choices.empty()) {  // a shader array: what every choice writes, at the fewest components
    std::optional<FixedFunctionState::VertexShaderOutputs> all;
    for (const StageUnit& c : vs.choices) {
      if (c.kind != StageSourceKind::hlsl) return std::nullopt;
      StageUnit single = c;
      single.choices.clear();
      std::optional<FixedFunctionState::VertexShaderOutputs> o = vertex_shader_outputs(single);
      if (!o) return std::nullopt;
      if (!all) {
        all = o;
        continue;
      }
      all->diffuse = std::min(all->diffuse, o->diffuse);
      all->specular = std::min(all->specular, o->specular);
      all->fog = std::min(all->fog, o->fog);
      for (int t = 0; t < 8; ++t) all->texcoords[t] = std::min(all->texcoords[t], o->texcoords[t]);
    }
    return all;
  }
  const ast::Function* entry = entry_function(vs);
  if (!entry) return std::nullopt;
  FixedFunctionState::VertexShaderOutputs out;
  out.known = true;
  // One output: a value the pixel stage reads, or one it leaves alone (position, point size,
  // clip distances, semantics the texture stages have no use for).
  auto take = [&out](const std::string& semantic, const ast::TypeRef& type) {
    const FixedVarying v = fixed_varying(semantic);
    const uint8_t n = static_cast<uint8_t>(float_components(type));
    switch (v.kind) {
      case FixedVarying::diffuse: out.diffuse = n; break;
      case FixedVarying::specular: out.specular = n; break;
      case FixedVarying::fog: out.fog = n; break;
      case FixedVarying::texcoord: out.texcoords[v.index] = n; break;
      default: break;
    }
  };
  // A value with a semantic, or a struct whose members have them.
  auto value = [&](const ast::TypeRef& type, const ast::Text& semantic, bool array) {
    if (array) return false;
    if (!semantic.empty()) {
      take(semantic, type);
      return true;
    }
    const ast::Struct* fields = type.definition ? type.definition : structure(type.name);
    if (!fields) return type.name == "void";
    for (const ast::Variable& m : fields->members) {
      if (!m.array_dims.empty()) return false;
      if (!m.semantic.empty()) take(m.semantic, m.type);
    }
    return true;
  };
  if (!value(entry->return_type, entry->semantic, false)) return std::nullopt;
  for (const ast::Variable& p : entry->params)
    if ((p.storage & (ast::kOut | ast::kInOut)) && !(p.storage & ast::kUniform) &&
        !value(p.type, p.semantic, !p.array_dims.empty()))
      return std::nullopt;
  return out;
}

const ast::Variable* EffectUnitBuilder::shader_variable(std::string_view name) const {
  for (const ast::Variable* v : variables_)
    if (v->name == name && shader_type_stage(v->type.name)) return v;
  return nullptr;
}

bool EffectUnitBuilder::resolve(const ast::Expr& e, StageUnit& stage, int depth) {
  if (depth > 8) return invalid(stage, "shader variables refer to each other in a cycle");
  switch (e.kind) {
    case ast::ExprKind::null: return false;
    case ast::ExprKind::int_literal: return e.number != 0 && invalid(stage, "a number is not a shader");
    case ast::ExprKind::compile: {
      std::vector<const ast::Expr*> args;
      for (const ast::ExprPtr& a : e.args) args.push_back(a);
      return hlsl(stage, e.text, e.callee, args, e.range);
    }
    case ast::ExprKind::call: {
      if (iequals(e.text, "CompileShader") && e.args.size() == 2 && e.args[0] && e.args[1] &&
          e.args[1]->kind == ast::ExprKind::call) {
        std::vector<const ast::Expr*> args;
        for (const ast::ExprPtr& a : e.args[1]->args) args.push_back(a);
        return hlsl(stage, e.args[0]->text, e.args[1]->text, args, e.range);
      }
      // BindInterfaces(shader, instances...): the shader's interface parameters take the instances.
      if (iequals(e.text, "BindInterfaces") && !e.args.empty() && e.args[0]) {
        std::vector<const ast::Expr*> outer = std::move(bound_interfaces_);
        bound_interfaces_.clear();
        for (size_t i = 1; i < e.args.size(); ++i) bound_interfaces_.push_back(e.args[i]);
        const bool resolved = resolve(*e.args[0], stage, depth + 1);
        bound_interfaces_ = std::move(outer);
        return resolved;
      }
      // ConstructGSWithSO(shader, declarations...): the stage's output stream is captured.
      if (iequals(e.text, "ConstructGSWithSO") && !e.args.empty() && e.args[0]) {
        stage.stream_output = stream_output_decl(e, sm_);
        return resolve(*e.args[0], stage, depth + 1);
      }
      // SetXShader(shader).
      if (stage_of_state(e.text) && !e.args.empty() && e.args[0]) return resolve(*e.args[0], stage, depth + 1);
      return invalid(stage, "'" + e.text + "(...)' does not name a shader");
    }
    case ast::ExprKind::identifier:
    case ast::ExprKind::reference: {
      if (iequals(e.text, "NULL")) return false;
      for (const std::string& g : glsl_names_)
        if (g == e.text) return glsl(stage, {e.text});
      if (const ast::Variable* v = shader_variable(e.text)) {
        if (v->initializer) return resolve(*v->initializer, stage, depth + 1);
        return invalid(stage, "shader variable '" + e.text + "' has no initializer");
      }
      return invalid(stage, "'" + e.text + "' names no shader");
    }
    case ast::ExprKind::glsl_list: {
      std::vector<std::string> names;
      for (const ast::ExprPtr& a : e.args) names.push_back(a->text);
      return glsl(stage, std::move(names));
    }
    case ast::ExprKind::asm_block: return assembly(e, stage);
    case ast::ExprKind::index: return shader_array(e, stage, depth);
    default: return invalid(stage, "the value does not name a shader");
  }
}

namespace {

// `bool Ps1xPrecision = true;` among `list`.
bool precision_annotation(const ast::List<ast::Annotation>& list) {
  for (const ast::Annotation& a : list)
    if (iequals(a.name, "Ps1xPrecision") && a.value && a.value->number != 0 &&
        (a.value->kind == ast::ExprKind::bool_literal || a.value->kind == ast::ExprKind::int_literal))
      return true;
  return false;
}

}  // namespace

bool EffectUnitBuilder::assembly(const ast::Expr& e, StageUnit& stage) {
  stage.kind = StageSourceKind::assembly;
  if (stage.stage != ShaderStage::vertex && stage.stage != ShaderStage::fragment)
    return invalid(stage, "shader model 1 assembly is a vertex or pixel shader");
  // Shader model 2 and 3 assembly is valid D3D9 that fxkit does not translate: the stage
  // says so, with no error in the effect.
  if (std::optional<emulation::AsmVersion> v = emulation::assembly_version(effect_, e.code); v && v->major != 1) {
    stage.unsupported = std::string(v->pixel ? "ps_" : "vs_") + std::to_string(v->major) + "_" +
                        std::to_string(v->minor) + " assembly is not translated (shader model 1 only)";
    return true;
  }
  std::optional<emulation::AsmProgram> program = emulation::parse_assembly(effect_, e.code, e.decl_code, sink_);
  if (!program) return invalid(stage, "the assembly has errors");
  const bool pixel = stage.stage == ShaderStage::fragment;
  if (program->version.pixel != pixel)
    return invalid(stage, std::string("a ") + (pixel ? "pixel" : "vertex") + " shader state holds " +
                              program->version.spelled() + " assembly");
  static const ast::Pass no_pass{};
  emulation::AssemblyBindings bindings =
      emulation::bind_pass_states(pass_ ? *pass_ : no_pass, pixel, variables_, sink_);
  emulation::AssemblyOptions options;
  options.hardware_precision = u_.options_.ps1x_precision ||
                               (technique_ && precision_annotation(technique_->annotations)) ||
                               (pass_ && precision_annotation(pass_->annotations));
  std::optional<emulation::AssemblyTranslation> t = emulation::translate_assembly(*program, bindings, options, sink_);
  if (!t) return invalid(stage, "the assembly has errors");
  stage.profile = std::string(pixel ? "ps_" : "vs_") + std::to_string(program->version.major) + "_" +
                  std::to_string(program->version.minor);
  stage.entry_point = t->entry_point;
  // glslang's messages about the translation point at the asm block.
  PresumedLocation at = sm_.presumed(e.range.begin);
  stage.translated = (at.valid() ? detail::line_directive(at.line, at.file) + "\n" : std::string()) + t->hlsl;
  stage.emulation = std::move(t->emulation);
  if (options.hardware_precision && pixel) stage.emulation += ", ps.1.x precision modelled";
  return true;
}

bool EffectUnitBuilder::shader_array(const ast::Expr& e, StageUnit& stage, int depth) {
  const ast::Expr* base = e.args.size() == 2 ? e.args[0] : nullptr;
  const ast::Variable* array =
      base && (base->kind == ast::ExprKind::identifier || base->kind == ast::ExprKind::reference)
          ? shader_variable(base->text)
          : nullptr;
  if (!array || array->array_dims.empty() || !array->initializer ||
      array->initializer->kind != ast::ExprKind::init_list)
    return invalid(stage, "an indexed shader must be an element of a shader array with an initializer");
  std::vector<StageUnit> choices;
  for (const ast::ExprPtr& element : array->initializer->args) {
    StageUnit c;
    c.stage = stage.stage;
    c.range = element ? element->range : stage.range;
    if (!element || !resolve(*element, c, depth + 1)) invalid(c, "the array element is NULL");
    choices.push_back(std::move(c));
  }
  if (choices.empty()) return invalid(stage, "the shader array '" + base->text + "' is empty");
  std::optional<int64_t> index = initial_value(*e.args[1], 0);
  size_t choice =
      index && *index >= 0 && static_cast<size_t>(*index) < choices.size() ? static_cast<size_t>(*index) : 0;
  SourceRange range = stage.range;
  stage = choices[choice];
  stage.range = range;
  stage.choice = choice;
  spell(e.args[1], stage.selector);
  stage.choices = std::move(choices);
  return true;
}

std::optional<int64_t> EffectUnitBuilder::initial_value(const ast::Expr& e, int depth) const {
  if (depth > 8) return std::nullopt;
  auto variable = [&](std::string_view name) -> const ast::Variable* {
    for (const ast::Variable* v : variables_)
      if (v->name == name && v->initializer) return v;
    return nullptr;
  };
  switch (e.kind) {
    case ast::ExprKind::int_literal:
    case ast::ExprKind::float_literal: return static_cast<int64_t>(e.number);
    case ast::ExprKind::identifier:
    case ast::ExprKind::reference:
      if (const ast::Variable* v = variable(e.text); v && v->array_dims.empty())
        return initial_value(*v->initializer, depth + 1);
      return std::nullopt;
    case ast::ExprKind::index: {
      if (e.args.size() != 2 || !e.args[0] || !e.args[1]) return std::nullopt;
      const ast::Variable* v = variable(e.args[0]->text);
      std::optional<int64_t> i = initial_value(*e.args[1], depth + 1);
      if (!v || !i || v->initializer->kind != ast::ExprKind::init_list || *i < 0 ||
          static_cast<size_t>(*i) >= v->initializer->args.size() || !v->initializer->args[*i])
        return std::nullopt;
      return initial_value(*v->initializer->args[*i], depth + 1);
    }
    default: return std::nullopt;
  }
}

bool EffectUnitBuilder::invalid(StageUnit& stage, std::string reason) {
  stage.kind = StageSourceKind::invalid;
  stage.unsupported = std::move(reason);
  return true;
}

bool EffectUnitBuilder::glsl(StageUnit& stage, std::vector<std::string> names) {
  stage.kind = StageSourceKind::glsl;
  stage.entry_point = "main";
  for (const std::string& n : names) {
    bool known = false;
    for (const std::string& g : glsl_names_) known = known || g == n;
    // The checker reports unknown block names (undefined-reference).
    if (!known) return invalid(stage, "no GLSL block named '" + n + "'");
  }
  stage.glsl_blocks = std::move(names);
  stage.profile = "glsl";
  for (const EffectUnits::GlslBlockText& b : u_.glsl_blocks_)
    if (b.name == stage.glsl_blocks.front() && !b.version.empty()) {
      std::string digits;
      for (char c : b.version.substr(8))
        if (std::isdigit(static_cast<unsigned char>(c))) digits.push_back(c);
        else if (!digits.empty()) break;
      if (!digits.empty()) stage.profile = digits;
    }
  return true;
}

const ast::Function* EffectUnitBuilder::function(std::string_view name, size_t args) const {
  const ast::Function* first = nullptr;
  for (const ast::Function* f : functions_) {
    if (f->name != name || f->body.empty()) continue;
    size_t uniforms = 0;
    for (const ast::Variable& p : f->params) uniforms += (p.storage & ast::kUniform) != 0;
    if (uniforms == args) return f;
    if (!first && uniforms >= args) first = f;
  }
  return first;
}

bool EffectUnitBuilder::hlsl(StageUnit& stage, const std::string& profile, const std::string& name,
                             const std::vector<const ast::Expr*>& args, SourceRange range) {
  stage.kind = StageSourceKind::hlsl;
  stage.profile = profile;
  stage.function = name;
  stage.entry_point = name;
  const ast::Function* f = function(name, args.size());
  // The checker reports unknown functions (undefined-reference).
  if (!f) return invalid(stage, "no shader function '" + name + "' with a body");
  // Interface parameters: a `uniform` one takes a compile-time argument (the SDK's
  // PSMainUniform(g_abstractLight)), any other an instance BindInterfaces binds.
  const size_t interfaces = std::count_if(f->params.begin(), f->params.end(), [&](const ast::Variable& p) {
    return is_interface_parameter(linkage_, p) && !(p.storage & ast::kUniform);
  });
  if (interfaces != bound_interfaces_.size()) {
    sink_.error("unsupported-interface-binding", range,
                "'" + name + "' takes " + std::to_string(interfaces) + " interface parameter(s), but " +
                    std::to_string(bound_interfaces_.size()) +
                    " instance(s) are bound: bind one to each with BindInterfaces(shader, instances...)");
    return invalid(stage, "its interface parameters are not bound");
  }
  // Entry points overloaded by their uniform parameters (`PS()` beside `PS(uniform int mode)`)
  // share a name glslang cannot take as an entry point: a wrapper calls the one chosen.
  const bool overloaded = std::count_if(functions_.begin(), functions_.end(), [&](const ast::Function* g) {
                            return g->name == name && !g->body.empty();
                          }) > 1;
  if (args.empty() && interfaces == 0 && !overloaded &&
      !(stage.stage == ShaderStage::fragment && has_d3d9_system_value(*f)) && !has_bool_varying(*f))
    return true;
  std::vector<const ast::Variable*> uniforms;
  for (const ast::Variable& p : f->params)
    if (p.storage & ast::kUniform) uniforms.push_back(&p);
  if (args.size() > uniforms.size()) {
    sink_.error("effect-shader-arguments", range,
                "'" + name + "' takes " + std::to_string(uniforms.size()) + " uniform parameter(s), but " +
                    std::to_string(args.size()) + " compile-time argument(s) are given");
    return invalid(stage, "too many compile-time arguments");
  }
  for (size_t k = 0; k < args.size(); ++k) {
    const ast::Expr* a = args[k];
    std::string text;
    if (const ast::Struct* iface = a ? linkage_.interface_named(uniforms[k]->type.name) : nullptr) {
      if (!spell_bound_instance(*a, *iface, text))
        return invalid(stage, "an interface argument is not a class instance or interface variable");
      stage.arguments.push_back(std::move(text));
      continue;
    }
    if (!a || a->kind == ast::ExprKind::compile || a->kind == ast::ExprKind::asm_block ||
        a->kind == ast::ExprKind::state_block || !spell(a, text)) {
      sink_.error("effect-shader-argument", a ? a->range : range,
                  "a compile-time argument of '" + name + "' must be a constant expression");
      return invalid(stage, "a compile-time argument is not a constant expression");
    }
    stage.arguments.push_back(std::move(text));
  }
  // The arguments in parameter order: compile-time ones to uniform parameters, bound
  // instances to the other interface parameters.
  if (interfaces) {
    std::vector<std::string> ordered;
    size_t uniform = 0, bound = 0;
    for (const ast::Variable& p : f->params) {
      if ((p.storage & ast::kUniform) && uniform == stage.arguments.size()) {
        sink_.error("unsupported-interface-binding", range,
                    "'" + name + "' takes interface parameters: give each of its uniform parameters an argument too");
        return invalid(stage, "a uniform parameter has no argument");
      }
      if (p.storage & ast::kUniform) {
        ordered.push_back(stage.arguments[uniform++]);
      } else if (const ast::Struct* iface = linkage_.interface_named(p.type.name)) {
        std::string text;
        if (!spell_bound_instance(*bound_interfaces_[bound++], *iface, text))
          return invalid(stage, "a bound instance is not a class instance or interface variable");
        ordered.push_back(std::move(text));
      }
    }
    stage.arguments = std::move(ordered);
  }
  stage.entry_point = name + "__fx_args";
  for (const EffectUnits::Wrapper& w : u_.wrappers_)
    if (w.function == name && w.arguments == stage.arguments) return true;
  u_.wrappers_.push_back({name, stage.arguments, wrapper(*f, stage.arguments)});
  return true;
}

namespace {

bool is_d3d9_system_value(std::string_view semantic) { return iequals(semantic, "VPOS") || iequals(semantic, "VFACE"); }

// D3D9 pixel shader system values that glslang reads as user varyings: VPOS is the pixel's
// integer position (SV_Position is its centre), VFACE is +1 front, -1 back. The wrapper
// parameter that stands for one, and the expression of type `type` it passes on.
std::pair<std::string, std::string> system_value(std::string_view semantic, const std::string& name,
                                                 const std::string& type) {
  if (iequals(semantic, "VPOS"))
    return {"float4 " + name + " : SV_Position", "(" + type + ")float4(" + name + ".xy - 0.5, 0, 0)"};
  return {"bool " + name + " : SV_IsFrontFace", "(" + type + ")(" + name + " ? 1.0 : -1.0)"};
}

// A bool scalar or vector with a user semantic: Vulkan has no bool inputs and outputs (a
// builtin such as SV_IsFrontFace excepted); fxc passes bools between stages as 32-bit
// integers, and the wrapper carries them as uint.
bool is_bool_varying(const ast::TypeRef& type, std::string_view semantic) {
  return type.template_arg.empty() && !type.definition && type.name.starts_with("bool") &&
         numeric_components(type.name) && !semantic.empty() && !iequals(semantic.substr(0, 3), "SV_");
}
bool is_bool_varying(const ast::Variable& v) { return v.array_dims.empty() && is_bool_varying(v.type, v.semantic); }

// `bool3` -> `uint3`.
std::string carried_type(std::string_view bool_type) { return "uint" + std::string(bool_type.substr(4)); }

std::string safe_name(std::string_view name) {
  std::string safe = detail::glslang_safe_name(name, false);
  return safe.empty() ? std::string(name) : safe;
}

}  // namespace

const ast::Struct* EffectUnitBuilder::system_value_struct(const ast::Variable& p) const {
  if (p.storage & (ast::kOut | ast::kInOut | ast::kUniform)) return nullptr;
  for (const ast::Decl& d : effect_.decls) {
    if (d.kind != ast::DeclKind::structure || d.structure->kind != ast::StructKind::structure ||
        d.structure->name != p.type.name)
      continue;
    bool any = false;
    for (const ast::Variable& m : d.structure->members) {
      if (!m.array_dims.empty() || m.type.definition || m.semantic.empty()) return nullptr;
      any = any || is_d3d9_system_value(m.semantic);
    }
    return any ? d.structure : nullptr;
  }
  return nullptr;
}

bool EffectUnitBuilder::has_d3d9_system_value(const ast::Function& f) const {
  for (const ast::Variable& p : f.params)
    if (is_d3d9_system_value(p.semantic) || system_value_struct(p)) return true;
  return false;
}

const ast::Struct* EffectUnitBuilder::bool_varying_struct(const ast::Variable& p) const {
  const ast::Struct* s = p.type.template_arg.empty() && !p.type.definition ? structure(p.type.name) : nullptr;
  const bool array_input = p.array_dims.size() == 1 && p.array_dims[0] && !(p.storage & (ast::kOut | ast::kInOut));
  if (!s || s->kind != ast::StructKind::structure || !(p.array_dims.empty() || array_input)) return nullptr;
  bool any = false;
  for (const ast::Variable& m : s->members) {
    if (m.type.definition || !m.type.template_arg.empty()) return nullptr;
    any = any || is_bool_varying(m);
  }
  return any ? s : nullptr;
}

bool EffectUnitBuilder::has_bool_varying(const ast::Function& f) const {
  ast::Variable result;
  result.type = f.return_type;
  result.semantic = f.semantic;
  if (is_bool_varying(result) || bool_varying_struct(result)) return true;
  for (const ast::Variable& p : f.params)
    if (!takes_argument(p) && !system_value_struct(p) && (is_bool_varying(p) || bool_varying_struct(p))) return true;
  return false;
}

std::string EffectUnitBuilder::carrier_struct(const ast::Struct& s, std::string& helpers) const {
  const std::string name = safe_name(s.name), carrier = "fx_io_" + std::string(s.name);
  if (helpers.find("struct " + carrier + " ") != std::string::npos) return carrier;
  std::string members, in, out;
  for (const ast::Variable& m : s.members) {
    const std::string member = safe_name(m.name), type = std::string(m.type.name);
    const bool converted = is_bool_varying(m);
    for (auto [bit, word] : {std::pair{ast::kNoInterpolation, "nointerpolation "},
                             {ast::kLinear, "linear "},
                             {ast::kCentroid, "centroid "},
                             {ast::kNoPerspective, "noperspective "},
                             {ast::kSample, "sample "},
                             {ast::kRowMajor, "row_major "},
                             {ast::kColumnMajor, "column_major "}})
      if (m.storage & bit) members += word;
    members += (converted ? carried_type(type) : type) + " " + member;
    for (const ast::ExprPtr dim : m.array_dims) {
      std::string size;
      spell(dim, size);
      members += "[" + size + "]";
    }
    if (!m.semantic.empty()) members += " : " + std::string(m.semantic);
    members += "; ";
    in += "r." + member + " = " + (converted ? "(" + type + ")" : "") + "v." + member + "; ";
    out += "r." + member + " = " + (converted ? "(" + carried_type(type) + ")" : "") + "v." + member + "; ";
  }
  helpers += "struct " + carrier + " { " + members + "};\n";
  helpers += name + " " + carrier + "_in(" + carrier + " v) { " + name + " r; " + in + "return r; }\n";
  helpers += carrier + " " + carrier + "_out(" + name + " v) { " + carrier + " r; " + out + "return r; }\n";
  return carrier;
}

std::string EffectUnitBuilder::retyped(const ast::Variable& p, const std::string& type) const {
  // The whole declaration joined (a modifier's spelling depends on what follows it), then its
  // first word that is the type name replaced.
  std::string text = join_tokens(toks_, p.tokens);
  const std::string_view name = p.type.name;
  for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1))
    if ((at == 0 || !is_word_char(text[at - 1])) &&
        (at + name.size() == text.size() || !is_word_char(text[at + name.size()])))
      return text.replace(at, name.size(), type);
  return text;
}

bool EffectUnitBuilder::takes_argument(const ast::Variable& p) const {
  return (p.storage & ast::kUniform) || is_interface_parameter(linkage_, p);
}

bool EffectUnitBuilder::spell_bound_instance(const ast::Expr& e, const ast::Struct& iface, std::string& out) {
  const ast::Expr* base = e.kind == ast::ExprKind::index && !e.args.empty() ? e.args[0] : &e;
  std::string spelled;
  if (base && base->kind == ast::ExprKind::identifier && spell(&e, spelled)) {
    for (const ast::Variable* v : linkage_.interface_variables)
      if (v->name == base->text && v->type.name == iface.name) return out = spelled, true;
    // A class instance binds statically: its id, a constant the dispatcher's switch folds.
    spelled.erase(std::remove(spelled.begin(), spelled.end(), ' '), spelled.end());
    if (std::optional<int> id = linkage_.instance_id(iface, spelled)) return out = std::to_string(*id), true;
  }
  sink_.error("unsupported-interface-binding", e.range,
              "BindInterfaces binds an interface variable or a class instance of a class implementing '" +
                  std::string(iface.name) + "', written as its name or name[literal]");
  return false;
}

std::string EffectUnitBuilder::wrapper(const ast::Function& f, const std::vector<std::string>& args) const {
  std::string text;
  std::string helpers;  // the structs that carry bool varyings as uint, and their conversions
  PresumedLocation at = sm_.presumed(f.name_range.begin);
  if (at.valid()) text += detail::line_directive(at.line, at.file) + "\n";
  for (const ast::Text& a : f.attributes) text += "[" + a + "] ";
  std::string result_type(f.return_type.name);
  if (!f.return_type.template_arg.empty()) result_type += "<" + std::string(f.return_type.template_arg) + ">";
  ast::Variable result;
  result.type = f.return_type;
  result.semantic = f.semantic;
  std::string result_conversion;
  if (const ast::Struct* s = bool_varying_struct(result)) {
    result_type = carrier_struct(*s, helpers);
    result_conversion = result_type + "_out";
  } else if (is_bool_varying(result)) {
    result_type = carried_type(result_type);
    result_conversion = "(" + result_type + ")";
  }
  text += result_type + " " + f.name + "__fx_args(";
  std::string call = f.name + "(";
  std::string prelude;   // builds the input structs that carry D3D9 system values, bool varyings
  std::string postlude;  // writes the outputs that carry bool varyings
  size_t bound = 0;
  bool first_param = true;
  for (size_t i = 0; i < f.params.size(); ++i) {
    const ast::Variable& p = f.params[i];
    if (i) call += ", ";
    if (takes_argument(p) && bound < args.size()) {
      // As the parameter's type, as fxc converts it: glslang passes `1` to a `uniform bool`
      // parameter unconverted, and its SPIR-V then branches on an int.
      const bool convert = p.array_dims.empty() && p.type.template_arg.empty() && numeric_components(p.type.name);
      call += convert ? "(" + std::string(p.type.name) + ")(" + args[bound++] + ")" : args[bound++];
      continue;
    }
    if (!first_param) text += ", ";
    first_param = false;
    const std::string param = "fx_" + std::to_string(i);
    if (is_d3d9_system_value(p.semantic)) {
      auto [declaration, value] = system_value(p.semantic, param, p.type.name);
      text += declaration;
      call += value;
      continue;
    }
    if (const ast::Struct* s = system_value_struct(p)) {  // its members one by one
      prelude += std::string(s->name) + " " + param + "; ";
      for (size_t m = 0; m < s->members.size(); ++m) {
        const ast::Variable& member = s->members[m];
        const std::string name = param + "_" + std::to_string(m);
        std::string type = member.type.name;
        if (!member.type.template_arg.empty()) type += "<" + std::string(member.type.template_arg) + ">";
        if (m) text += ", ";
        std::string value = name;
        if (is_d3d9_system_value(member.semantic)) {
          auto [declaration, converted] = system_value(member.semantic, name, type);
          text += declaration;
          value = converted;
        } else {
          if (member.storage & ast::kNoInterpolation) text += "nointerpolation ";
          if (member.storage & ast::kCentroid) text += "centroid ";
          if (is_bool_varying(member)) value = "(" + type + ")" + name;
          text +=
              (is_bool_varying(member) ? carried_type(type) : type) + " " + name + " : " + std::string(member.semantic);
        }
        prelude += param + "." + safe_name(member.name) + " = " + value + "; ";
      }
      call += param;
      continue;
    }
    const bool in = !(p.storage & ast::kOut), out = p.storage & (ast::kOut | ast::kInOut);
    const std::string name = safe_name(p.name);
    if (is_bool_varying(p)) {  // carried as uint, converted as fxc converts
      const std::string type(p.type.name), carried = carried_type(type);
      text += retyped(p, carried);
      if (!out) {
        call += "(" + type + ")" + name;
        continue;
      }
      prelude += type + " " + param + (in ? " = (" + type + ")" + name : "") + "; ";
      postlude += name + " = (" + carried + ")" + param + "; ";
      call += param;
      continue;
    }
    if (const ast::Struct* s = bool_varying_struct(p)) {  // a copy with the bool varyings as uint
      const std::string carrier = carrier_struct(*s, helpers);
      text += retyped(p, carrier);
      if (!p.array_dims.empty()) {  // a geometry shader's input vertices
        std::string size;
        spell(p.array_dims[0], size);
        prelude += safe_name(s->name) + " " + param + "[" + size + "]; for (int fx_k = 0; fx_k < " + size +
                   "; ++fx_k) " + param + "[fx_k] = " + carrier + "_in(" + name + "[fx_k]); ";
        call += param;
      } else if (!out) {
        call += carrier + "_in(" + name + ")";
      } else {
        prelude += safe_name(s->name) + " " + param + (in ? " = " + carrier + "_in(" + name + ")" : "") + "; ";
        postlude += name + " = " + carrier + "_out(" + param + "); ";
        call += param;
      }
      continue;
    }
    text += join_tokens(toks_, p.tokens);
    call += name;
  }
  text += ")";
  if (!f.semantic.empty()) text += " : " + f.semantic;
  call = result_conversion.empty() ? call + ")" : result_conversion + "(" + call + "))";
  if (f.return_type.name == "void") text += " { " + prelude + call + "; " + postlude + "}\n";
  else if (postlude.empty()) text += " { " + prelude + "return " + call + "; }\n";
  else text += " { " + prelude + result_type + " fx_result = " + call + "; " + postlude + "return fx_result; }\n";
  return helpers + text;
}

}  // namespace fx
