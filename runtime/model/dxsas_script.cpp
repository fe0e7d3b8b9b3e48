// DXSAS Script annotations parsed into located, checked plans (fx/model/dxsas_script.h).
#include "fx/model/dxsas_script.h"

#include <algorithm>

#include "fx/ascii_case.h"
#include "fx/model/effect_model.h"

namespace fx {
namespace {

enum class Where { technique, pass };

struct CommandSpec {
  std::string_view name;
  ScriptCommand command;
};

constexpr CommandSpec kCommands[] = {
    {"RenderColorTarget", ScriptCommand::render_color_target},
    {"RenderColorTarget0", ScriptCommand::render_color_target},
    {"RenderColorTarget1", ScriptCommand::render_color_target},
    {"RenderColorTarget2", ScriptCommand::render_color_target},
    {"RenderColorTarget3", ScriptCommand::render_color_target},
    {"RenderDepthStencilTarget", ScriptCommand::render_depth_stencil_target},
    {"ClearSetColor", ScriptCommand::clear_set_color},
    {"ClearSetDepth", ScriptCommand::clear_set_depth},
    {"ClearSetStencil", ScriptCommand::clear_set_stencil},
    {"Clear", ScriptCommand::clear},
    {"Pass", ScriptCommand::pass},
    {"Draw", ScriptCommand::draw},
    {"ScriptExternal", ScriptCommand::script_external},
    {"LoopByCount", ScriptCommand::loop_by_count},
    {"LoopByType", ScriptCommand::loop_by_type},
    {"LoopGetIndex", ScriptCommand::loop_get_index},
    {"LoopEnd", ScriptCommand::loop_end},
};

// DXSAS commands fxkit knows but does not run: a warning each, once per script.
constexpr std::string_view kUnsupported[] = {"Technique",  "RenderPort", "GeometryList", "Hint",    "LoopGetCount",
                                             "LoopGetMax", "LoopGetMin", "Scale",        "Callback"};

std::string trim(std::string_view s, size_t& at) {
  size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\n' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\n' || s[e - 1] == '\r')) --e;
  at += b;
  return std::string(s.substr(b, e - b));
}

class ScriptChecker {
 public:
  ScriptChecker(const EffectModel& model, DiagnosticSink& diags) : model_(model), diags_(diags) {}

  // The plan of one Script annotation of technique `technique` (or of its pass `pass`).
  ScriptPlan plan(const Annotation& a, const TechniqueInfo& technique, Where where) {
    annotation_ = &a;
    ScriptPlan plan;
    plan.range = a.range;
    const std::string& text = a.value.text;
    // Characters map to the source only when the literal is the text between two quotes.
    const SourceRange& v = a.value_range;
    exact_ = v.valid() && v.end.raw > v.begin.raw && v.end.raw - v.begin.raw == text.size() + 2;
    int loops = 0;
    size_t start = 0;
    while (start < text.size()) {
      size_t end = text.find(';', start);
      if (end == std::string::npos) end = text.size();
      size_t at = start;
      const std::string command = trim(std::string_view(text).substr(start, end - start), at);
      start = end + 1;
      if (command.empty()) continue;
      const SourceRange range = locate(at, command.size());
      const size_t eq = command.find('=');
      if (eq == std::string::npos) {
        diags_.warning("script-syntax", range,
                       "script command '" + command + "' has no '=' (DXSAS writes Name=Value;)");
        continue;
      }
      size_t name_at = at, value_at = at + eq + 1;
      const std::string name = trim(std::string_view(command).substr(0, eq), name_at);
      const std::string value = trim(std::string_view(command).substr(eq + 1), value_at);
      auto spec = std::find_if(std::begin(kCommands), std::end(kCommands),
                               [&](const CommandSpec& c) { return iequals(c.name, name); });
      if (spec == std::end(kCommands)) {
        unknown(name, locate(name_at, name.size()));
        continue;
      }
      ScriptStep step;
      step.command = spec->command;
      step.value = value;
      step.range = range;
      if (step.command == ScriptCommand::render_color_target && name.size() > 17) step.slot = uint32_t(name[17] - '0');
      if (!check(step, technique, where, locate(value_at, value.size()), loops)) continue;
      plan.steps.push_back(std::move(step));
    }
    if (loops > 0)
      diags_.warning("script-loop-unbalanced", a.range,
                     "script opens " + std::to_string(loops) + " loop(s) that no LoopEnd closes");
    return plan;
  }

 private:
  SourceRange locate(size_t at, size_t size) const {
    if (!exact_) return annotation_->range;
    const SourceLocation b = annotation_->value_range.begin.offset(uint32_t(1 + at));
    return {b, b.offset(uint32_t(std::max<size_t>(size, 1)))};
  }

  void unknown(const std::string& name, SourceRange range) {
    if (std::any_of(std::begin(kUnsupported), std::end(kUnsupported),
                    [&](std::string_view u) { return iequals(u, name); })) {
      diags_.warning("script-unknown-command", range,
                     "DXSAS command '" + name + "' is not supported by fxkit; it is skipped");
      return;
    }
    std::vector<std::string_view> names;
    for (const CommandSpec& c : kCommands) names.push_back(c.name);
    Diagnostic& d = diags_.warning("script-unknown-command", range, "unknown DXSAS script command '" + name + "'");
    const std::string guess = closest_match(name, names);
    if (!guess.empty()) d.message += "; did you mean '" + guess + "'?";
  }

  // The parameter `value` names (its index in `index`), or null with a warning.
  const Parameter* named(const std::string& value, SourceRange at, const char* command, uint32_t& index) {
    index = model_.find_parameter(value);
    if (index == kNoIndex) {
      diags_.warning("script-unknown-name", at, std::string(command) + " names '" + value + "', which is no parameter");
      return nullptr;
    }
    return &model_.parameters[index];
  }

  void wrong_type(SourceRange at, const std::string& value, const char* command, const std::string& want,
                  const Parameter& p) {
    diags_.warning("script-wrong-type", at,
                   std::string(command) + " wants " + want + "; '" + value + "' is " + p.type.to_string() +
                       (p.semantic.empty() ? "" : " : " + p.semantic));
  }

  bool check(ScriptStep& step, const TechniqueInfo& technique, Where where, SourceRange at, int& loops) {
    const std::string& v = step.value;
    auto misplaced = [&](const char* command, const char* where_ok) {
      diags_.warning("script-misplaced", step.range, std::string(command) + " belongs in a " + where_ok + "'s Script");
      return false;
    };
    switch (step.command) {
      case ScriptCommand::render_color_target:
      case ScriptCommand::render_depth_stencil_target: {
        if (v.empty()) return true;  // the frame's own target
        const bool colour = step.command == ScriptCommand::render_color_target;
        const char* command = colour ? "RenderColorTarget" : "RenderDepthStencilTarget";
        const Parameter* p = named(v, at, command, step.parameter);
        if (!p) return false;
        const char* semantic = colour ? "RENDERCOLORTARGET" : "RENDERDEPTHSTENCILTARGET";
        if (p->type.cls != TypeClass::texture || !iequals(p->semantic, semantic)) {
          wrong_type(at, v, command, std::string("a texture with the semantic ") + semantic, *p);
          return false;
        }
        return true;
      }
      case ScriptCommand::clear_set_color:
      case ScriptCommand::clear_set_depth:
      case ScriptCommand::clear_set_stencil:
      case ScriptCommand::loop_by_count:
      case ScriptCommand::loop_get_index: {
        const char* command = step.command == ScriptCommand::clear_set_color     ? "ClearSetColor"
                              : step.command == ScriptCommand::clear_set_depth   ? "ClearSetDepth"
                              : step.command == ScriptCommand::clear_set_stencil ? "ClearSetStencil"
                              : step.command == ScriptCommand::loop_by_count     ? "LoopByCount"
                                                                                 : "LoopGetIndex";
        if (step.command == ScriptCommand::loop_get_index && loops == 0) {
          diags_.warning("script-loop-unbalanced", step.range, "LoopGetIndex outside a loop");
          return false;
        }
        const Parameter* p = named(v, at, command, step.parameter);
        if (!p) return false;
        const bool colour = step.command == ScriptCommand::clear_set_color;
        const bool numeric = p->type.base == BaseType::float32 || p->type.base == BaseType::int32 ||
                             p->type.base == BaseType::uint32 || p->type.base == BaseType::half;
        const uint32_t components = p->type.component_count();
        if (!numeric || p->type.is_array() || (colour ? components < 3 || components > 4 : components != 1)) {
          wrong_type(at, v, command, colour ? "a float4 (or float3) parameter" : "a scalar parameter", *p);
          return false;
        }
        if (step.command == ScriptCommand::loop_by_count) ++loops;
        return true;
      }
      case ScriptCommand::loop_by_type: ++loops; return true;
      case ScriptCommand::loop_end:
        if (loops == 0) {
          diags_.warning("script-loop-unbalanced", step.range, "LoopEnd without an open loop");
          return false;
        }
        --loops;
        return true;
      case ScriptCommand::clear:
        if (iequals(v, "Color")) step.clear = ScriptClear::color;
        else if (iequals(v, "Depth")) step.clear = ScriptClear::depth;
        else if (iequals(v, "Stencil")) step.clear = ScriptClear::stencil;
        else {
          diags_.warning("script-unknown-name", at, "Clear wants Color, Depth or Stencil, not '" + v + "'");
          return false;
        }
        return true;
      case ScriptCommand::pass: {
        if (where == Where::pass) return misplaced("Pass=", "technique");
        for (uint32_t i = 0; i < technique.passes.size(); ++i)
          if (technique.passes[i].name == v) step.pass = i;
        if (step.pass == kNoIndex) {
          std::vector<std::string_view> names;
          for (const PassInfo& pass : technique.passes) names.push_back(pass.name);
          Diagnostic& d =
              diags_.warning("script-unknown-name", at, "technique '" + technique.name + "' has no pass '" + v + "'");
          const std::string guess = closest_match(v, names);
          if (!guess.empty()) d.message += "; did you mean '" + guess + "'?";
          return false;
        }
        return true;
      }
      case ScriptCommand::draw:
        if (where == Where::technique) return misplaced("Draw=", "pass");
        if (iequals(v, "Geometry")) step.draw = ScriptDraw::geometry;
        else if (iequals(v, "Buffer")) step.draw = ScriptDraw::buffer;
        else {
          diags_.warning("script-unknown-name", at, "Draw wants Geometry or Buffer, not '" + v + "'");
          return false;
        }
        return true;
      case ScriptCommand::script_external:
        if (where == Where::pass) return misplaced("ScriptExternal=", "technique");
        return true;
    }
    return true;
  }

  const EffectModel& model_;
  DiagnosticSink& diags_;
  const Annotation* annotation_ = nullptr;
  bool exact_ = false;
};

// The STANDARDSGLOBAL parameter's annotations, lower-cased and checked.
void plan_global(EffectModel& model, DiagnosticSink& diags) {
  for (uint32_t i = 0; i < model.parameters.size(); ++i) {
    const Parameter& p = model.parameters[i];
    if (!iequals(p.semantic, "STANDARDSGLOBAL")) continue;
    ScriptGlobal& g = model.script_global;
    g.parameter = i;
    struct Field {
      const char* name;
      std::string* value;
      std::vector<std::string_view> allowed;
    };
    for (const Field& f : {Field{"ScriptClass", &g.script_class, {"object", "scene", "sceneorobject"}},
                           Field{"ScriptOrder", &g.script_order, {"standard", "preprocess", "postprocess"}},
                           Field{"ScriptOutput", &g.script_output, {"color"}}}) {
      const Annotation* a = find_annotation(p.annotations, f.name);
      if (!a || !a->value.is_string()) continue;
      *f.value = ascii_lower(a->value.text);
      if (std::find(f.allowed.begin(), f.allowed.end(), *f.value) == f.allowed.end()) {
        std::string list;
        for (std::string_view s : f.allowed) list += (list.empty() ? "" : ", ") + std::string(s);
        diags.warning("script-unknown-name", a->range,
                      std::string(f.name) + " '" + a->value.text + "' is none of " + list);
      }
    }
    return;
  }
}

}  // namespace

void plan_scripts(EffectModel& model, DiagnosticSink& diags) {
  plan_global(model, diags);
  ScriptChecker checker(model, diags);
  for (TechniqueInfo& t : model.techniques) {
    if (const Annotation* a = find_annotation(t.annotations, "Script"); a && a->value.is_string())
      t.script = checker.plan(*a, t, Where::technique);
    for (PassInfo& pass : t.passes)
      if (const Annotation* a = find_annotation(pass.annotations, "Script"); a && a->value.is_string())
        pass.script = checker.plan(*a, t, Where::pass);
  }
}

}  // namespace fx
