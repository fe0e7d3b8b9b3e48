// `fxkit compile FILE [-I DIR]... [-D NAME[=VALUE]]... [--profile P] [--technique T]
//  [-o DIR] [--cache DIR] [--json]`: SPIR-V for every pass stage.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "command.h"
#include "compile_workers_option.h"
#include "fx/compile/effect_file.h"
#include "fx/compile/effect_programs.h"
#include "fx/compile/spirv_cache.h"
#include "fx/diagnostic_render.h"
#include "fx/shown_once.h"

namespace fx::tools {
namespace {

// One compiled stage as `fxkit compile --json` lists it. A stage of a shader array also
// names the index expression that chooses among its elements.
nlohmann::json shader_json(const fx::EffectPass& pass, const fx::StageProgram& s, const fx::StageUnit* stage,
                           const fx::SourceManager& sm) {
  nlohmann::json j = {{"technique", pass.technique},
                      {"pass", pass.pass},
                      {"stage", fx::to_string(s.stage)},
                      {"entry", s.unit.entry_point},
                      {"function", stage ? stage->function : ""},
                      {"profile", stage ? stage->profile : s.unit.profile},
                      {"language", fx::to_string(s.unit.language)},
                      {"ok", s.shader.ok},
                      {"ms", s.ms},
                      {"cached", s.shader.from_cache || s.reused},
                      {"words", s.shader.spirv.size()},
                      {"diagnostics", fx::render_json(s.diagnostics, sm)}};
  for (const fx::StageUnit& p : pass.stages)
    if (p.stage == s.stage && !p.choices.empty()) j["selector"] = p.selector;
  // A generated fixed-function stage has no profile of its own: the pass sets no shader.
  if (stage && stage->kind == fx::StageSourceKind::fixed_function) {
    j["profile"] = nullptr;
    j["generated"] = stage->emulation;
  }
  return j;
}

struct CompileArgs {
  FrontEndFlags front_end;
  std::string file;
  std::string technique;
  std::string output_dir;
  std::string cache_dir;
  bool json = false;
  CompileWorkersFlag workers;
};

bool write_spirv(const std::filesystem::path& path, const std::vector<uint32_t>& words) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
  return static_cast<bool>(out);
}

int run_compile(const CompileArgs& args) {
  fx::FrontEndOptions options;
  std::string error;
  if (!args.front_end.to_options(options, error)) {
    std::fprintf(stderr, "fxkit compile: %s\n", error.c_str());
    return kUsageError;
  }
  if (!std::filesystem::is_regular_file(args.file)) {
    std::fprintf(stderr, "fxkit compile: cannot read '%s'\n", args.file.c_str());
    return kUsageError;
  }
  if (!args.output_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.output_dir, ec);
    if (ec) {
      std::fprintf(stderr, "fxkit compile: cannot create '%s': %s\n", args.output_dir.c_str(), ec.message().c_str());
      return kUsageError;
    }
  }
  fx::SpirvCache cache(args.cache_dir);
  // One worker: the passes below compile one after another.
  std::unique_ptr<fx::CompileWorkers> workers = args.workers.start("compile", 1);
  fx::ShaderCompiler compiler({}, &cache, workers.get());
  fx::DiagnosticSink diags;
  std::unique_ptr<fx::EffectFile> effect = fx::EffectFile::parse(args.file, options, diags);
  const fx::SourceManager& sm = effect->sources;
  effect->build_programs(diags, &compiler);
  const fx::EffectUnits& units = *effect->units;
  fx::EffectPrograms& programs = *effect->programs;

  bool failed = diags.has_errors();
  bool matched = args.technique.empty();
  nlohmann::json shaders = nlohmann::json::array();
  fx::ShownOnce all;
  all.add(diags.diagnostics(), "");
  std::vector<fx::Diagnostic> effect_level = diags.diagnostics();  // the front end's and linking's
  for (const fx::EffectPass& pass : units.passes()) {
    if (!args.technique.empty() && pass.technique != args.technique) continue;
    matched = true;
    const fx::PassProgram& program = programs.program(pass);
    for (const fx::StageProgram& s : program.stages) {
      const fx::StageUnit* stage = pass.find(s.stage);
      // A stage that compiled is not blamed for another stage's failure (the pass as a
      // whole still fails, and the exit status says so).
      bool ok = s.shader.ok;
      failed = failed || !ok;
      all.add(s.diagnostics, pass.technique + "." + pass.pass + " " + fx::to_string(s.stage));
      std::string spv;
      if (ok && !args.output_dir.empty()) {
        std::filesystem::path path = std::filesystem::path(args.output_dir) /
                                     (pass.technique + "." + pass.pass + "." + fx::to_string(s.stage) + ".spv");
        if (!write_spirv(path, s.shader.spirv)) {
          std::fprintf(stderr, "fxkit compile: cannot write '%s'\n", path.string().c_str());
          return kUsageError;
        }
        spv = path.string();
      }
      if (args.json) {
        nlohmann::json j = shader_json(pass, s, stage, sm);
        if (stage && !stage->choices.empty()) j["choice"] = stage->choice;
        if (!spv.empty()) j["spirv"] = spv;
        shaders.push_back(std::move(j));
      } else {
        std::fprintf(stderr, "%s.%s %s (%s %s): %s%s\n", pass.technique.c_str(), pass.pass.c_str(),
                     fx::to_string(s.stage), s.unit.profile.c_str(), s.unit.entry_point.c_str(), ok ? "ok" : "FAILED",
                     spv.empty() ? "" : (" -> " + spv).c_str());
      }
    }
    // The other elements of a shader array the pass indexes: each is a shader of the effect.
    for (const fx::StageUnit& stage : pass.stages)
      for (size_t i = 0; i < stage.choices.size(); ++i) {
        if (i == stage.choice) continue;
        std::optional<fx::StageProgram> s = programs.compile_alone(stage.choices[i]);
        if (!s) continue;
        failed = failed || !s->shader.ok;
        all.add(s->diagnostics,
                pass.technique + "." + pass.pass + " " + fx::to_string(s->stage) + " choice " + std::to_string(i));
        if (args.json) {
          nlohmann::json j = shader_json(pass, *s, &stage.choices[i], sm);
          j["choice"] = i;
          shaders.push_back(std::move(j));
        } else {
          std::fprintf(stderr, "%s.%s %s, choice %zu of [%s] (%s %s): %s\n", pass.technique.c_str(), pass.pass.c_str(),
                       fx::to_string(s->stage), i, stage.selector.c_str(), s->unit.profile.c_str(),
                       s->unit.entry_point.c_str(), s->shader.ok ? "ok" : "FAILED");
        }
      }
    all.add(program.diagnostics, pass.technique + "." + pass.pass);
    effect_level.insert(effect_level.end(), program.diagnostics.begin(), program.diagnostics.end());
    if (!program.compiled && !program.stages.empty()) failed = true;
    // What is not compiled, located so an editor or CI log points at it: fixed-function
    // processing at the pass; a stage's own reason (assembly, for the legacy path; a shader
    // fxkit cannot compile, an error) at the state that names it, with its profile.
    auto not_compiled = [&](const fx::StageUnit* stage, const std::string& reason, fx::SourceRange range) {
      const bool error = stage && stage->kind == fx::StageSourceKind::invalid;
      failed = failed || error;
      fx::DiagnosticSink located;
      located.report(error ? fx::Severity::error : fx::Severity::warning, "shader-not-compiled", range,
                     "pass '" + pass.technique + "." + pass.pass + "' is not compiled to SPIR-V: " + reason);
      if (args.json) {
        shaders.push_back(
            {{"technique", pass.technique},
             {"pass", pass.pass},
             {"stage", stage ? nlohmann::json(fx::to_string(stage->stage)) : nlohmann::json()},
             {"entry", nullptr},
             {"function", stage ? stage->function : ""},
             {"profile", stage && !stage->profile.empty() ? nlohmann::json(stage->profile) : nlohmann::json()},
             {"ok", false},
             {"ms", 0},
             {"unsupported", reason},
             {"diagnostics", fx::render_json(located.diagnostics(), sm)}});
      } else {
        std::fprintf(stderr, "%s.%s: not compiled: %s\n", pass.technique.c_str(), pass.pass.c_str(), reason.c_str());
        all.add(located.diagnostics(), "");
      }
    };
    for (const std::string& reason : pass.unsupported) not_compiled(nullptr, reason, pass.range);
    for (const fx::StageUnit& stage : pass.stages)
      if (stage.kind == fx::StageSourceKind::invalid ||
          (stage.kind == fx::StageSourceKind::assembly && stage.translated.empty()))
        not_compiled(&stage, std::string(fx::to_string(stage.stage)) + " stage: " + stage.unsupported, stage.range);
  }
  if (!matched) {
    std::fprintf(stderr, "fxkit compile: no technique named '%s'\n", args.technique.c_str());
    return kUsageError;
  }
  if (args.json) {
    nlohmann::json out = {
        {"file", args.file},
        {"shaders", std::move(shaders)},
        {"diagnostics", fx::render_json(effect_level, sm)},
        {"ok", !failed},
        {"glslang_started", fx::ShaderCompiler::glslang_started() || (workers && workers->stats().started > 0)}};
    std::puts(json_text(out).c_str());
  } else {
    std::fputs(fx::render_text(all.diagnostics(), sm).c_str(), stderr);
  }
  return failed ? kInputErrors : kSuccess;
}

}  // namespace

void register_compile(CLI::App& app, Runner& run) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("compile", "Compile every pass stage of an effect to SPIR-V");
  args->front_end.add_to(*cmd);
  cmd->add_option("--technique", args->technique, "Only this technique");
  cmd->add_option("-o", args->output_dir, "Write DIR/<technique>.<pass>.<stage>.spv");
  cmd->add_option("--cache", args->cache_dir, "SPIR-V cache directory (default: memory only)");
  cmd->add_flag("--json", args->json, "Print one JSON document: shaders with their diagnostics");
  args->workers.add_to(*cmd);
  cmd->add_option("FILE", args->file, "Effect file")->required();
  cmd->callback([args, &run] { run = [args] { return run_compile(*args); }; });
}

}  // namespace fx::tools
