// libFuzzer target: arbitrary bytes as an effect file through what `fxkit check` runs, glslang
// included: front end, then (only when it passed, as the CLI does) the translation units of
// every pass and their compilation to SPIR-V with validation. What reaches glslang has passed
// the front end's shader-code checks (fxkit issue #32), so a crash or hang inside glslang here
// is a hole in those checks. Inputs are capped at 16 KiB and at 8 compiled units so each run
// stays within libFuzzer's -timeout.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fx/compile/effect_programs.h"
#include "fx/compile/effect_units.h"
#include "fx/compile/shader_compiler.h"
#include "fx/diagnostic_render.h"
#include "fx/frontend.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > (16u << 10)) return 0;
  std::string text(reinterpret_cast<const char*>(data), size);
  fx::FrontEndOptions options;
  options.preprocessor.loader = [](const std::string& path) -> std::optional<std::string> {
    if (path.ends_with("common.fxh")) return std::string("#define SCALE(x) ((x) * 2)\nfloat g;\n");
    return std::nullopt;
  };
  options.preprocessor.lister = [](const std::string&) { return std::vector<std::string>{}; };
  options.preprocessor.limits.max_include_depth = 16;
  options.preprocessor.limits.max_tokens = 1u << 18;
  options.preprocessor.limits.max_macro_expansions = 1u << 14;
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  diags.set_error_limit(64);
  fx::ParsedEffect parsed = fx::parse_effect_text("fuzz.fx", std::move(text), sm, diags, options);
  fx::EffectUnits units(parsed.ast, sm, diags);
  static const fx::ShaderCompiler compiler;  // glslang's process set-up once, no cache
  fx::EffectPrograms programs(units, compiler, sm);
  size_t compiled = 0;
  for (const fx::EffectPass& pass : units.passes()) {
    if (compiled >= 8) break;
    const fx::PassProgram& program = programs.program(pass);
    compiled += program.stages.size();
    for (const fx::StageProgram& s : program.stages) (void)fx::render_text(s.diagnostics, sm);
  }
  (void)fx::render_text(diags.diagnostics(), sm);
  return 0;
}
