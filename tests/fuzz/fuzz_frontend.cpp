// libFuzzer target: arbitrary bytes as an effect file through preprocessor, parser,
// checker and (when the runtime is built) the semantic model (types, constant folding,
// resolved states) and the translation unit of every pass stage (filtered declarations,
// each entry's reachable functions). One virtual include; rendered diagnostics included.
// Any crash, hang, sanitizer report or out-of-memory is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "fx/diagnostic_render.h"
#include "fx/frontend.h"
#ifdef FXKIT_FUZZ_MODEL
#include "fx/compile/effect_units.h"
#include "fx/model/effect_model.h"
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  fx::FrontEndOptions options;
  // Includes resolve to a small header, or to the input itself (recursion is bounded by
  // the include-depth limit).
  options.preprocessor.loader = [&text](const std::string& path) -> std::optional<std::string> {
    if (path.ends_with("common.fxh")) return std::string("#define SCALE(x) ((x) * 2)\nfloat g;\n");
    if (path.ends_with("self.fx")) return text;
    return std::nullopt;
  };
  options.preprocessor.lister = [](const std::string&) { return std::vector<std::string>{}; };
  options.preprocessor.limits.max_include_depth = 16;
  options.preprocessor.limits.max_input_bytes = 4u << 20;
  options.preprocessor.limits.max_tokens = 1u << 20;
  options.preprocessor.limits.max_macro_expansions = 1u << 16;
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  diags.set_error_limit(64);
  fx::ParsedEffect parsed = fx::parse_effect_text("fuzz.fx", std::move(text), sm, diags, options);
#ifdef FXKIT_FUZZ_MODEL
  // The model must cope with partial trees from inputs that failed to parse, too.
  fx::EffectModel model = fx::build_effect_model(parsed, sm, diags);
  (void)model;
  fx::EffectUnits units(parsed.ast, sm, diags);
  for (const fx::EffectPass& pass : units.passes())
    for (const fx::StageUnit& stage : pass.stages) (void)units.unit(stage);
#endif
  std::string rendered = fx::render_text(diags.diagnostics(), sm);
  // As the CLI prints it: invalid UTF-8 from the input is replaced, never thrown.
  (void)fx::render_json(diags.diagnostics(), sm).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  (void)parsed;
  (void)rendered;
  return 0;
}
