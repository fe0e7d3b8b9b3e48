// EffectFile: front end -> model -> units -> lazily compiled programs -> parameter store.
#include "fx/compile/effect_file.h"

#include "fx/diagnostic_render.h"

namespace fx {

EffectUnitOptions effect_unit_options(const FrontEndOptions& options) {
  EffectUnitOptions unit_options;
  for (const auto& [name, value] : options.preprocessor.defines)
    if (name == kPs1xPrecisionMacro && value != "0") unit_options.ps1x_precision = true;
  return unit_options;
}

namespace {

// The pieces after the front end, for an effect `e` whose parse is in e->parsed.
std::unique_ptr<EffectFile> build(std::unique_ptr<EffectFile> e, const FrontEndOptions& options, DiagnosticSink& sink,
                                  std::string* located) {
  auto failed = [&] {
    if (located) *located = render_text(sink.diagnostics(), e->sources);
    return nullptr;
  };
  if (sink.has_errors()) return failed();
  e->model = std::make_unique<EffectModel>(build_effect_model(e->parsed, e->sources, sink));
  if (sink.has_errors()) return failed();
  e->units = std::make_unique<EffectUnits>(e->parsed.ast, e->sources, sink, effect_unit_options(options));
  e->compiler = std::make_unique<ShaderCompiler>();
  e->programs = std::make_unique<EffectPrograms>(*e->units, *e->compiler, e->sources);
  e->params = std::make_unique<ParameterStore>(*e->model, nullptr, &sink);
  return e;
}

}  // namespace

std::unique_ptr<EffectFile> EffectFile::load(const std::string& path, const FrontEndOptions& options,
                                             DiagnosticSink& sink, std::string* located) {
  auto e = std::make_unique<EffectFile>();
  e->path = path;
  e->parsed = parse_effect_file(path, e->sources, sink, options);
  return build(std::move(e), options, sink, located);
}

std::unique_ptr<EffectFile> EffectFile::load_text(const std::string& name, std::string text,
                                                  const FrontEndOptions& options, DiagnosticSink& sink) {
  auto e = std::make_unique<EffectFile>();
  e->path = name;
  e->parsed = parse_effect_text(name, std::move(text), e->sources, sink, options);
  return build(std::move(e), options, sink, nullptr);
}

uint32_t EffectFile::find_technique(std::string_view name) const {
  const TechniqueInfo* t = model->find_technique(name);
  return t ? static_cast<uint32_t>(t - model->techniques.data()) : kNoIndex;
}

}  // namespace fx
