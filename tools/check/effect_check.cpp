#include "effect_check.h"

#include <chrono>
#include <memory>

#include "effect_summary.h"
#include "fx/diagnostic_render.h"
#include "fx/shown_once.h"
#include "fx/worker_pool.h"
#ifdef FXKIT_HAS_RUNTIME
#include "check_cache.h"
#include "fx/compile/effect_file.h"
#include "fx/compile/effect_programs.h"
#include "fx/model/effect_model.h"
#include "fx/select/technique_validation.h"
#else
#include "fx/semantic_model.h"
#endif

namespace fx::tools {
namespace {

#ifdef FXKIT_HAS_RUNTIME
// Every technique valid or not on the caps, as text and in the summary; false when none is.
bool report_techniques(fx::EffectFile& effect, const EffectCheckSettings& settings, fx::DiagnosticSink& diags,
                       EffectCheck& out) {
  const fx::DeviceCaps& caps = *settings.caps;
  const fx::SourceManager& sm = effect.sources;
  auto techniques = fx::validate_effect(effect, caps, diags, settings.caps_compile, settings.compiler);
  size_t valid = 0;
  for (const auto& t : techniques) valid += t.valid ? 1 : 0;
  nlohmann::json list = nlohmann::json::array();
  out.caps_text += out.file + " on " + caps.name + ": " + std::to_string(valid) + " of " +
                   std::to_string(techniques.size()) + " techniques valid\n";
  for (const auto& t : techniques) {
    list.push_back({{"name", t.name}, {"valid", t.valid}, {"reasons", fx::render_json(t.reasons, sm)}});
    char line[256];
    std::snprintf(line, sizeof line, "  %-8s ", t.valid ? "valid" : "invalid");
    out.caps_text += line + t.name + "\n";
    for (const auto& r : t.reasons) out.caps_text += "    " + fx::located_reason(r, sm) + "\n";
  }
  out.effect["caps"] = caps.name;
  out.effect["techniques"] = std::move(list);
  out.effect["valid_techniques"] = valid;
  return valid > 0;
}

// The DXSAS Script warnings among the effect model's diagnostics (docs/dxsas.md); the
// model's other warnings repeat the front end's checks.
std::vector<fx::Diagnostic> script_diagnostics(const fx::DiagnosticSink& model) {
  std::vector<fx::Diagnostic> out;
  for (const fx::Diagnostic& d : model.diagnostics())
    if (d.id.rfind("script-", 0) == 0) out.push_back(d);
  return out;
}
#endif

}  // namespace

#ifdef FXKIT_HAS_RUNTIME
// Assembly and fixed-function stages are not reported: the legacy path runs them, so they
// are not a defect of the effect (`fxkit compile` lists them, as it is asked for SPIR-V). A
// stage fxkit cannot run at all is an error.
void check_shaders(const fx::EffectUnits& units, fx::EffectPrograms& programs, const EffectCheckSettings& settings,
                   fx::DiagnosticSink& diags, fx::ShownOnce& shown, const fx::EffectModel* model) {
  if (settings.executor) programs.compile_all(*settings.executor, true);
  shown.add(diags.diagnostics(), "");
  for (const fx::EffectPass& pass : units.passes()) {
    const std::string name = pass.technique + "." + pass.pass;
    const fx::PassProgram& program = programs.program(pass);
    for (const fx::StageProgram& s : program.stages) shown.add(s.diagnostics, name + " " + fx::to_string(s.stage));
    for (const fx::StageUnit& stage : pass.stages) {
      for (size_t i = 0; i < stage.choices.size(); ++i) {
        if (i == stage.choice) continue;
        if (std::optional<fx::StageProgram> s = programs.compile_alone(stage.choices[i]))
          shown.add(s->diagnostics, name + " " + fx::to_string(s->stage) + " choice " + std::to_string(i));
      }
      if (stage.kind != fx::StageSourceKind::invalid) continue;
      fx::DiagnosticSink located;
      located.error(
          "shader-not-compiled", stage.range,
          "pass '" + name + "' cannot be compiled: " + fx::to_string(stage.stage) + " stage: " + stage.unsupported);
      shown.add(located.diagnostics(), "");
    }
    shown.add(program.diagnostics, name);
  }
  if (!model) return;
  for (const fx::TextureInfo& t : model->textures) {
    if (!t.shader) continue;
    const fx::PassProgram& fill = programs.texture_fill(*t.shader);
    const std::string name = "texture shader of " + model->parameters[t.parameter].name;
    for (const fx::StageProgram& s : fill.stages) shown.add(s.diagnostics, name);
    shown.add(fill.diagnostics, name);
  }
}
#endif

EffectCheck check_effect(const std::string& file, const EffectCheckSettings& settings) {
  auto start = std::chrono::steady_clock::now();
  EffectCheck out;
  out.file = file;
  fx::DiagnosticSink diags;
#ifdef FXKIT_HAS_RUNTIME
  std::unique_ptr<fx::EffectFile> effect = fx::EffectFile::parse(file, settings.front_end, diags);
  const fx::SourceManager& sm = effect->sources;
  const fx::ParsedEffect& parsed = effect->parsed;
#else
  fx::SourceManager sm;
  const fx::ParsedEffect parsed = fx::parse_effect_file(file, sm, diags, settings.front_end);
  fx::semantic::SemanticModel(parsed.ast, sm).report(diags);  // as EffectFile::parse does
#endif
  out.files = parsed.files;
  if (out.files.empty()) out.files.push_back(file);
  out.effect = summarize_effect(parsed.ast, sm);
  out.effect["file"] = file;
  out.effect["ok"] = parsed.ok;
  out.effect["includes"] = parsed.files;
  fx::ShownOnce shown;
#ifdef FXKIT_HAS_RUNTIME
  // What select and render refuse, check refuses: the effect model's errors (types,
  // array sizes, defaults) beside the front end's. Its warnings repeat the front end's.
  fx::DiagnosticSink model_diags;
  if (parsed.ok) {
    effect->build_model(model_diags);
    for (const fx::Diagnostic& d : model_diags.diagnostics())
      if (d.severity >= fx::Severity::error) {
        fx::Diagnostic& copy = diags.report(d.severity, d.id, d.range, d.message);
        copy.notes = d.notes;
        copy.fixits = d.fixits;
      }
  }
  // The shaders of an effect whose front end failed would only repeat its errors.
  if (settings.compile && settings.compiler && !diags.has_errors()) {
    effect->build_programs(diags, settings.compiler);
    check_shaders(*effect->units, *effect->programs, settings, diags, shown, effect->model.get());
  } else shown.add(diags.diagnostics(), "");
  if (parsed.ok) shown.add(script_diagnostics(model_diags), "");
  if (settings.caps && parsed.ok) {
    fx::DiagnosticSink caps_diags;
    out.runnable = report_techniques(*effect, settings, caps_diags, out);
    shown.add(model_diags.diagnostics(), "");
    shown.add(caps_diags.diagnostics(), "");
  }
#else
  shown.add(diags.diagnostics(), "");
#endif
  fx::DiagnosticSink final_sink;  // counts, with --werror applied
  final_sink.set_warnings_as_errors(settings.werror);
  for (const fx::Diagnostic& d : shown.diagnostics()) {
    fx::Diagnostic& copy = final_sink.report(d.severity, d.id, d.range, d.message);
    copy.notes = d.notes;
    copy.fixits = d.fixits;
  }
  out.errors = final_sink.error_count();
  out.warnings = final_sink.warning_count();
  out.text = fx::render_text(final_sink.diagnostics(), sm);
  out.diagnostics = fx::render_json(final_sink.diagnostics(), sm);
  out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void check_effects(const std::vector<std::string>& files, const EffectCheckSettings& settings, CheckCache* cache,
                   std::vector<EffectCheck>& results, const std::function<void(size_t)>& finished) {
  results.assign(files.size(), {});
  auto one = [&](size_t i) {
#ifdef FXKIT_HAS_RUNTIME
    std::optional<EffectCheck> hit = cache ? cache->find(files[i]) : std::nullopt;
    if (hit) results[i] = std::move(*hit);
    else results[i] = check_effect(files[i], settings);
    if (cache && !hit) cache->store(results[i]);
#else
    (void)cache;
    results[i] = check_effect(files[i], settings);
#endif
    if (finished) finished(i);
  };
  if (settings.executor) settings.executor->for_each(files.size(), one);
  else
    for (size_t i = 0; i < files.size(); ++i) one(i);
}

nlohmann::json to_json(const EffectCheck& c) {
  return {{"file", c.file},         {"files", c.files}, {"errors", c.errors},       {"warnings", c.warnings},
          {"runnable", c.runnable}, {"text", c.text},   {"caps_text", c.caps_text}, {"diagnostics", c.diagnostics},
          {"effect", c.effect},     {"ms", c.ms}};
}

bool from_json(const nlohmann::json& j, EffectCheck& c) {
  if (!j.is_object()) return false;
  try {
    c.file = j.at("file").get<std::string>();
    c.files = j.at("files").get<std::vector<std::string>>();
    c.errors = j.at("errors").get<size_t>();
    c.warnings = j.at("warnings").get<size_t>();
    c.runnable = j.at("runnable").get<bool>();
    c.text = j.at("text").get<std::string>();
    c.caps_text = j.at("caps_text").get<std::string>();
    c.diagnostics = j.at("diagnostics");
    c.effect = j.at("effect");
    c.ms = j.at("ms").get<double>();
  } catch (const nlohmann::json::exception&) {
    return false;
  }
  return true;
}

}  // namespace fx::tools
