// `fxkit info FILE [-I DIR]... [-D NAME[=VALUE]]... [--profile P] [--cache DIR] --json`:
// the effect's full reflection (schema: docs/info-json-schema.md, docs/info.schema.json).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "command.h"
#include "effect_summary.h"
#include "fx/compile/effect_file.h"
#include "fx/compile/effect_programs.h"
#include "fx/compile/spirv_cache.h"
#include "fx/diagnostic_render.h"
#include "fx/model/class_instances.h"
#include "fx/model/effect_model.h"
#include "fx/state_table.h"

namespace fx::tools {
namespace {

using nlohmann::json;

struct InfoArgs {
  FrontEndFlags front_end;
  std::string file;
  std::string cache_dir;
  bool json = false;
};

std::string lower(std::string_view s) {
  std::string out;
  for (char c : s) out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return out;
}

bool is_texture_type(std::string_view type) {
  std::string t = lower(type);
  return t.rfind("texture", 0) == 0 || t.rfind("rwtexture", 0) == 0 || t == "volumetexture";
}
bool is_sampler_type(std::string_view type) {
  std::string t = lower(type);
  return t.rfind("sampler", 0) == 0 && t != "sampler_state";
}

std::string type_name(const fx::ast::TypeRef& t) {
  return t.template_arg.empty() ? t.name : t.name + "<" + t.template_arg + ">";
}

// The forms `fxkit check --json` writes too (effect_summary.h).
json location(const fx::SourceManager& sm, fx::SourceRange range) { return source_location(sm, range); }

// As `fxkit check --json`: the value typed (a string without its quotes); and as written.
json annotations(const fx::ast::List<fx::ast::Annotation>& list) {
  json out = json::array();
  for (const fx::ast::Annotation& a : list)
    out.push_back({{"name", a.name},
                   {"type", type_name(a.type)},
                   {"value", annotation_value(a.value)},
                   {"value_text", a.value ? fx::spell_expression(*a.value) : ""}});
  return out;
}

json states(const fx::ast::List<fx::ast::StateAssignment>& list) {
  json out = json::array();
  for (const fx::ast::StateAssignment& s : list) {
    json j = {{"name", s.name}, {"value", s.value ? fx::spell_expression(*s.value) : ""}};
    j["index"] = s.index ? json(fx::spell_expression(*s.index)) : json(nullptr);
    out.push_back(std::move(j));
  }
  return out;
}

std::vector<std::string> storage_names(uint32_t bits) {
  static constexpr std::pair<uint32_t, const char*> kNames[] = {
      {fx::ast::kShared, "shared"},      {fx::ast::kStatic, "static"},           {fx::ast::kUniform, "uniform"},
      {fx::ast::kConst, "const"},        {fx::ast::kExtern, "extern"},           {fx::ast::kVolatile, "volatile"},
      {fx::ast::kRowMajor, "row_major"}, {fx::ast::kColumnMajor, "column_major"}};
  std::vector<std::string> out;
  for (auto [bit, name] : kNames)
    if (bits & bit) out.push_back(name);
  return out;
}

json reflected_type(const fx::ReflectedType& t) {
  return {{"glsl", t.glsl_name}, {"rows", t.rows}, {"columns", t.columns}, {"array", t.array_size}};
}

json interface(const std::vector<fx::InterfaceVariable>& vars) {
  json out = json::array();
  for (const fx::InterfaceVariable& v : vars)
    out.push_back(
        {{"name", v.name}, {"semantic", v.semantic}, {"location", v.location}, {"type", reflected_type(v.type)}});
  return out;
}

json blocks(const std::vector<fx::UniformBlock>& list) {
  json out = json::array();
  for (const fx::UniformBlock& b : list) {
    json members = json::array();
    for (const fx::BlockMember& m : b.members)
      members.push_back({{"name", m.name}, {"offset", m.offset}, {"size", m.size}, {"type", reflected_type(m.type)}});
    out.push_back({{"name", b.name}, {"set", b.set}, {"binding", b.binding}, {"size", b.size}, {"members", members}});
  }
  return out;
}

const char* kind_name(fx::DescriptorKind k) {
  switch (k) {
    case fx::DescriptorKind::uniform_buffer: return "uniform_buffer";
    case fx::DescriptorKind::storage_buffer: return "storage_buffer";
    case fx::DescriptorKind::combined_image_sampler: return "combined_image_sampler";
    case fx::DescriptorKind::sampled_image: return "sampled_image";
    case fx::DescriptorKind::sampler: return "sampler";
    case fx::DescriptorKind::storage_image: return "storage_image";
    case fx::DescriptorKind::uniform_texel_buffer: return "uniform_texel_buffer";
    case fx::DescriptorKind::storage_texel_buffer: return "storage_texel_buffer";
  }
  return "unknown";
}

json shader_json(const fx::StageProgram& s, const fx::StageUnit* stage, const fx::SourceManager& sm) {
  json images = json::array();
  for (const fx::ImageBinding& i : s.shader.reflection.images)
    images.push_back({{"name", i.name}, {"set", i.set}, {"binding", i.binding}, {"array", i.array_size}});
  return {{"stage", fx::to_string(s.stage)},
          {"entry", s.unit.entry_point},
          {"function", stage ? stage->function : ""},
          {"profile", stage ? stage->profile : s.unit.profile},
          {"language", fx::to_string(s.unit.language)},
          {"ok", s.shader.ok},
          {"inputs", interface(s.shader.reflection.inputs)},
          {"outputs", interface(s.shader.reflection.outputs)},
          {"uniform_blocks", blocks(s.shader.reflection.uniform_blocks)},
          {"storage_blocks", blocks(s.shader.reflection.storage_blocks)},
          {"push_constants", blocks(s.shader.reflection.push_constants)},
          {"images", images},
          {"diagnostics", fx::render_json(s.diagnostics, sm)}};
}

// Where a parameter landed in the compiled programs: each stage's uniform block has its own
// layout (a stage's `$Global` holds only the globals it reads), so two parameters can both be
// at offset 0 of `$Global`, in different stages' blocks. Each distinct place once, in pass
// order.
struct Placement {
  std::string stage, block;
  uint32_t offset = 0, size = 0;
  bool operator==(const Placement&) const = default;
};
std::vector<Placement> find_placements(const std::vector<const fx::PassProgram*>& programs, const std::string& name) {
  std::vector<Placement> out;
  for (const fx::PassProgram* p : programs)
    for (const fx::StageProgram& s : p->stages)
      for (const fx::UniformBlock& b : s.shader.reflection.uniform_blocks)
        for (const fx::BlockMember& m : b.members) {
          Placement at{fx::to_string(s.shader.reflection.stage), b.name, m.offset, m.size};
          if (m.name == name && std::find(out.begin(), out.end(), at) == out.end()) out.push_back(std::move(at));
        }
  return out;
}

// `model`: the effect model's parameter for `v` (its folded default), or null; `ast` the
// effect it is declared in (an interface variable's class instances).
json parameter_json(const fx::ast::Variable& v, const std::string& cbuffer, const fx::SourceManager& sm,
                    const std::vector<const fx::PassProgram*>& programs, const fx::Parameter* model,
                    const fx::ast::Effect& ast) {
  json dims = json::array();
  for (const fx::ast::ExprPtr& d : v.array_dims) dims.push_back(d ? fx::spell_expression(*d) : "");
  json j = {{"name", v.name},
            {"type", type_name(v.type)},
            {"array", dims},
            {"semantic", v.semantic},
            {"storage", storage_names(v.storage)},
            {"annotations", annotations(v.annotations)},
            {"location", location(sm, v.name_range)}};
  j["default"] = v.initializer ? json(fx::spell_expression(*v.initializer)) : json(nullptr);
  const std::optional<fx::Value>* folded = model ? &model->default_value : nullptr;
  const bool numeric = folded && *folded && (*folded)->is_numeric();
  j["value"] = numeric ? json((*folded)->components) : json(nullptr);
  j["value_text"] = folded && *folded ? json((*folded)->to_string()) : json(nullptr);
  j["cbuffer"] = cbuffer.empty() ? json(nullptr) : json(cbuffer);
  const std::vector<Placement> placements = find_placements(programs, v.name);
  const Placement* at = placements.empty() ? nullptr : &placements.front();
  j["stage"] = at ? json(at->stage) : json(nullptr);
  j["block"] = at ? json(at->block) : json(nullptr);
  j["offset"] = at ? json(at->offset) : json(nullptr);
  j["size"] = at ? json(at->size) : json(nullptr);
  json all = json::array();
  for (const Placement& p : placements)
    all.push_back({{"stage", p.stage}, {"block", p.block}, {"offset", p.offset}, {"size", p.size}});
  j["placements"] = std::move(all);
  json instances = json::array();  // what an interface variable can be bound to (SetClassInstance)
  if (fx::find_interface(ast, v.type.name))
    for (const fx::BindableInstance& instance : fx::bindable_instances(ast, v.type.name))
      instances.push_back(instance.name);
  j["class_instances"] = std::move(instances);
  return j;
}

int run_info(const InfoArgs& args) {
  fx::FrontEndOptions options;
  std::string error;
  if (!args.front_end.to_options(options, error)) {
    std::fprintf(stderr, "fxkit info: %s\n", error.c_str());
    return kUsageError;
  }
  if (!std::filesystem::is_regular_file(args.file)) {
    std::fprintf(stderr, "fxkit info: cannot read '%s'\n", args.file.c_str());
    return kUsageError;
  }
  fx::SpirvCache cache(args.cache_dir);
  fx::ShaderCompiler compiler({}, &cache);
  fx::DiagnosticSink diags;
  std::unique_ptr<fx::EffectFile> effect = fx::EffectFile::parse(args.file, options, diags);
  const fx::SourceManager& sm = effect->sources;
  const fx::ParsedEffect& parsed = effect->parsed;
  effect->build_programs(diags, &compiler);
  const fx::EffectUnits& units = *effect->units;
  std::vector<const fx::PassProgram*> compiled;
  for (const fx::EffectPass& p : units.passes()) compiled.push_back(&effect->programs->program(p));
  // Folded defaults. The model's own diagnostics repeat the front end's, which are reported.
  fx::DiagnosticSink model_diags;
  effect->build_model(model_diags);
  const fx::EffectModel& model = *effect->model;
  auto model_parameter = [&](const fx::ast::Variable& v) -> const fx::Parameter* {
    for (const fx::Parameter& p : model.parameters)
      if (p.decl == &v) return &p;
    return nullptr;
  };

  json parameters = json::array(), textures = json::array(), samplers = json::array();
  json techniques = json::array();
  auto add_technique = [&](const fx::ast::Technique& t, const std::string& group, size_t& pass_cursor) {
    json passes = json::array();
    for (const fx::ast::Pass& p : t.passes) {
      const fx::EffectPass& ep = units.passes().at(pass_cursor);
      const fx::PassProgram& prog = *compiled.at(pass_cursor++);
      json shaders = json::array();
      for (const fx::StageProgram& s : prog.stages) shaders.push_back(shader_json(s, ep.find(s.stage), sm));
      json bindings = json::array();
      for (const fx::ProgramBinding& b : prog.layout.bindings) {
        json stages = json::array();
        for (int st = 0; st <= static_cast<int>(fx::ShaderStage::compute); ++st)
          if (b.stage_mask & (1u << st)) stages.push_back(fx::to_string(static_cast<fx::ShaderStage>(st)));
        bindings.push_back({{"name", b.name},
                            {"kind", kind_name(b.kind)},
                            {"set", b.set},
                            {"binding", b.binding},
                            {"count", b.count},
                            {"stages", stages}});
      }
      const fx::StageProgram* vs = prog.find(fx::ShaderStage::vertex);
      passes.push_back({{"name", ep.pass},
                        {"annotations", annotations(p.annotations)},
                        {"states", states(p.states)},
                        {"ok", prog.ok()},
                        {"unsupported", prog.unsupported},
                        {"shaders", shaders},
                        {"bindings", bindings},
                        {"vertex_inputs", vs ? interface(vs->shader.reflection.inputs) : json::array()},
                        {"location", location(sm, p.range)}});
    }
    std::string name = fx::technique_label(t.name, static_cast<uint32_t>(techniques.size()));
    techniques.push_back({{"name", name},
                          {"group", group},
                          {"version", t.version},
                          {"annotations", annotations(t.annotations)},
                          {"passes", passes},
                          {"location", location(sm, t.range)}});
  };
  size_t pass_cursor = 0;
  for (const fx::ast::Decl& d : parsed.ast.decls) {
    if (d.kind == fx::ast::DeclKind::variable) {
      const fx::ast::Variable& v = *d.variable;
      if (fx::shader_type_stage(v.type.name)) continue;
      if (is_texture_type(v.type.name)) {
        textures.push_back({{"name", v.name},
                            {"type", type_name(v.type)},
                            {"semantic", v.semantic},
                            {"annotations", annotations(v.annotations)},
                            {"location", location(sm, v.name_range)}});
      } else if (is_sampler_type(v.type.name)) {
        json j = {{"name", v.name},          {"type", type_name(v.type)}, {"annotations", annotations(v.annotations)},
                  {"states", json::array()}, {"texture", nullptr},        {"location", location(sm, v.name_range)}};
        if (v.initializer && v.initializer->kind == fx::ast::ExprKind::state_block) {
          j["states"] = states(v.initializer->states);
          for (const fx::ast::StateAssignment& s : v.initializer->states)
            if (lower(s.name) == "texture" && s.value) j["texture"] = s.value->text;
        }
        samplers.push_back(std::move(j));
      } else {
        parameters.push_back(parameter_json(v, "", sm, compiled, model_parameter(v), parsed.ast));
      }
    } else if (d.kind == fx::ast::DeclKind::constant_buffer) {
      for (const fx::ast::Variable& m : d.constant_buffer->members)
        parameters.push_back(parameter_json(m, d.constant_buffer->name, sm, compiled, model_parameter(m), parsed.ast));
    } else if (d.kind == fx::ast::DeclKind::state_object && lower(d.state_object->kind).rfind("sampler", 0) == 0) {
      const fx::ast::StateObject& so = *d.state_object;
      samplers.push_back({{"name", so.name},
                          {"type", so.kind},
                          {"annotations", annotations(so.annotations)},
                          {"states", states(so.states)},
                          {"texture", nullptr},
                          {"location", location(sm, so.name_range)}});
    } else if (d.kind == fx::ast::DeclKind::technique) {
      add_technique(*d.technique, "", pass_cursor);
    } else if (d.kind == fx::ast::DeclKind::group) {
      for (const fx::ast::Technique& t : d.group->techniques) add_technique(t, d.group->name, pass_cursor);
    }
  }
  json out = {{"file", args.file},
              {"ok", parsed.ok && !diags.has_errors()},
              {"profile", std::string(fx::to_string(options.check.profile == fx::EffectProfile::automatic
                                                        ? fx::infer_profile(parsed.ast)
                                                        : options.check.profile))},
              {"includes", parsed.files},
              {"parameters", parameters},
              {"textures", textures},
              {"samplers", samplers},
              {"techniques", techniques},
              {"diagnostics", fx::render_json(diags.diagnostics(), sm)}};
  if (args.json) {
    std::puts(json_text(out).c_str());
  } else {
    std::printf("%s: %zu parameter(s), %zu texture(s), %zu sampler(s), %zu technique(s)\n", args.file.c_str(),
                parameters.size(), textures.size(), samplers.size(), techniques.size());
    for (const json& t : techniques)
      for (const json& p : t["passes"])
        std::printf("  %s.%s: %s, %zu shader(s)\n", t["name"].get<std::string>().c_str(),
                    p["name"].get<std::string>().c_str(), p["ok"].get<bool>() ? "ok" : "not runnable",
                    p["shaders"].size());
    std::fputs(fx::render_text(diags.diagnostics(), sm).c_str(), stderr);
  }
  return diags.has_errors() ? kInputErrors : kSuccess;
}

}  // namespace

void register_info(CLI::App& app, Runner& run) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand("info", "Reflect an effect: parameters, textures, samplers, passes, shaders");
  args->front_end.add_to(*cmd);
  cmd->add_option("--cache", args->cache_dir, "SPIR-V cache directory (default: memory only)");
  cmd->add_flag("--json", args->json, "Print the reflection as JSON (docs/info-json-schema.md)");
  cmd->add_option("FILE", args->file, "Effect file")->required();
  cmd->callback([args, &run] { run = [args] { return run_info(*args); }; });
}

}  // namespace fx::tools
