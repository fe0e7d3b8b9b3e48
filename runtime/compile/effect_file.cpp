// EffectFile: front end -> model -> units -> lazily compiled programs -> parameter store.
#include "fx/compile/effect_file.h"

#include "fx/diagnostic_render.h"
#include "fx/semantic_model.h"

namespace fx {

EffectUnitOptions effect_unit_options(const FrontEndOptions& options) {
  EffectUnitOptions unit_options;
  for (const auto& [name, value] : options.preprocessor.defines)
    if (name == kPs1xPrecisionMacro && value != "0") unit_options.ps1x_precision = true;
  return unit_options;
}

namespace {

// The semantic model of the front end's result: its unknown-identifier and unknown-member
// findings beside the front end's, so check, loads, reloads and the editor report alike.
void model_shader_code(const EffectFile& e, DiagnosticSink& sink) {
  semantic::SemanticModel(e.parsed.ast, e.sources).report(sink);
}

}  // namespace

std::unique_ptr<EffectFile> EffectFile::parse(const std::string& path, const FrontEndOptions& options,
                                              DiagnosticSink& sink) {
  auto e = std::make_unique<EffectFile>();
  e->path = path;
  e->options = options;
  e->parsed = parse_effect_file(path, e->sources, sink, options);
  model_shader_code(*e, sink);
  return e;
}

std::unique_ptr<EffectFile> EffectFile::parse_text(const std::string& path, std::string text,
                                                   const FrontEndOptions& options, DiagnosticSink& sink) {
  auto e = std::make_unique<EffectFile>();
  e->path = path;
  e->options = options;
  e->parsed = parse_effect_text(path, std::move(text), e->sources, sink, options);
  model_shader_code(*e, sink);
  return e;
}

bool EffectFile::build_model(DiagnosticSink& sink) {
  const size_t errors = sink.error_count();
  model = std::make_unique<EffectModel>(build_effect_model(parsed, sources, sink));
  if (sink.error_count() != errors) return false;
  params = std::make_unique<ParameterStore>(*model, nullptr, &sink);
  return sink.error_count() == errors;
}

void EffectFile::build_programs(DiagnosticSink& sink, const ShaderCompiler* shared) {
  programs.reset();  // before the units and the compiler it points into
  units = std::make_unique<EffectUnits>(parsed.ast, sources, sink, effect_unit_options(options));
  if (!shared && !compiler) compiler = std::make_unique<ShaderCompiler>();
  programs = std::make_unique<EffectPrograms>(*units, shared ? *shared : *compiler, sources);
}

namespace {

// The steps after the front end of a load: null, with the errors as text in `located` when
// given, once the front end or the model reported errors.
std::unique_ptr<EffectFile> built(std::unique_ptr<EffectFile> e, DiagnosticSink& sink, std::string* located) {
  if (sink.has_errors() || !e->build_model(sink)) {
    if (located) *located = render_text(sink.diagnostics(), e->sources);
    return nullptr;
  }
  e->build_programs(sink);
  return e;
}

}  // namespace

std::unique_ptr<EffectFile> EffectFile::load(const std::string& path, const FrontEndOptions& options,
                                             DiagnosticSink& sink, std::string* located) {
  return built(parse(path, options, sink), sink, located);
}

std::unique_ptr<EffectFile> EffectFile::load_text(const std::string& name, std::string text,
                                                  const FrontEndOptions& options, DiagnosticSink& sink) {
  return built(parse_text(name, std::move(text), options, sink), sink, nullptr);
}

uint32_t EffectFile::find_technique(std::string_view name) const {
  const TechniqueInfo* t = model ? model->find_technique(name) : nullptr;
  return t ? static_cast<uint32_t>(t - model->techniques.data()) : kNoIndex;
}

}  // namespace fx
