#include "fx/compile/effect_programs.h"

#include <algorithm>
#include <chrono>
#include <unordered_set>

#include "fx/compile/spirv_cache.h"
#include "fx/compile/texture_fill_unit.h"
#include "fx/worker_pool.h"
#include "shader_diagnostics.h"

namespace fx {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

}  // namespace

const StageProgram* PassProgram::find(ShaderStage stage) const {
  for (const StageProgram& s : stages)
    if (s.stage == stage) return &s;
  return nullptr;
}

EffectPrograms::EffectPrograms(const EffectUnits& units, const ShaderCompiler& compiler, const SourceManager& sm)
    : units_(units), compiler_(compiler), sm_(sm) {
  programs_.resize(units_.passes().size());
}

EffectPrograms::~EffectPrograms() = default;

bool EffectPrograms::is_compiled(const EffectPass& pass) const {
  size_t i = static_cast<size_t>(&pass - units_.passes().data());
  return i < programs_.size() && programs_[i] != nullptr;
}

const PassProgram* EffectPrograms::program(std::string_view technique, std::string_view pass) {
  const EffectPass* p = units_.find(technique, pass);
  return p ? &program(*p) : nullptr;
}

StageProgram EffectPrograms::compile_stage(const StageUnit& stage, TranslationUnit unit) {
  StageProgram out;
  out.stage = stage.stage;
  Clock::time_point start = Clock::now();
  std::string key = spirv_cache_key(unit, compiler_.options()).hex();
  if (auto it = memo_.find(key); it != memo_.end()) {
    out.shader = it->second.shader;
    out.diagnostics = it->second.diagnostics;
    out.reused = true;
    ++stats_.stages_reused;
  } else {
    DiagnosticSink sink;
    if (auto ahead = compiled_ahead_.find(key); ahead != compiled_ahead_.end()) {
      out.shader = std::move(ahead->second);
      compiled_ahead_.erase(ahead);
    } else {
      out.shader = compiler_.compile(unit);
    }
    report_messages(out.shader.messages, resolver_for(sm_), sink);
    if (!out.shader.ok && out.shader.messages.empty())
      sink.error("shader-compile-error", stage.range, out.shader.info_log);
    out.diagnostics = sink.diagnostics();
    // What glslang reports with no place in the source (linking, SPIR-V validation) is the
    // stage's as a whole: it lands on the pass state that names the shader.
    for (Diagnostic& d : out.diagnostics)
      if (!d.range.valid()) d.range = stage.range;
    detail::refine_shader_diagnostics(out.diagnostics, sm_, units_.symbols());
    ++stats_.stages_compiled;
    stats_.compile_ms += out.shader.total_ms;
    if (!out.shader.from_cache) stats_.glslang_ms += out.shader.parse_ms + out.shader.link_ms;
    memo_.emplace(std::move(key), Memo{out.shader, out.diagnostics});
  }
  out.unit = std::move(unit);
  out.ms = ms_since(start);
  return out;
}

std::optional<StageProgram> EffectPrograms::compile_alone(const StageUnit& stage) {
  std::optional<TranslationUnit> unit = units_.unit(stage);
  if (!unit) return std::nullopt;
  return compile_stage(stage, std::move(*unit));
}

void EffectPrograms::compile_all(TaskExecutor& executor, bool shader_array_choices) {
  struct Job {
    std::string key;
    TranslationUnit unit;
    CompiledShader shader;
  };
  std::vector<Job> jobs;
  std::unordered_set<std::string> queued;
  auto add = [&](const StageUnit& stage) {
    std::optional<TranslationUnit> unit = units_.unit(stage);
    if (!unit) return;
    std::string key = spirv_cache_key(*unit, compiler_.options()).hex();
    if (memo_.count(key) || compiled_ahead_.count(key) || !queued.insert(key).second) return;
    jobs.push_back({std::move(key), std::move(*unit), {}});
  };
  if (const StageUnit* check = units_.uncalled_check(); check && !check_) add(*check);
  for (const EffectPass& pass : units_.passes()) {
    if (is_compiled(pass)) continue;
    for (const StageUnit& stage : pass.stages) {
      add(stage);
      if (!shader_array_choices) continue;
      for (size_t i = 0; i < stage.choices.size(); ++i)
        if (i != stage.choice) add(stage.choices[i]);
    }
  }
  // Only glslang runs on the executor: placing diagnostics reads the SourceManager, whose
  // line tables are built on first use and are not safe to build from several threads.
  executor.for_each(jobs.size(), [&](size_t i) { jobs[i].shader = compiler_.compile(jobs[i].unit); });
  for (Job& job : jobs) compiled_ahead_.emplace(std::move(job.key), std::move(job.shader));
  for (const EffectPass& pass : units_.passes()) program(pass);
}

const StageProgram* EffectPrograms::uncalled_check() {
  const StageUnit* check = units_.uncalled_check();
  if (!check) return nullptr;
  if (!check_) check_ = std::make_unique<StageProgram>(compile_stage(*check, *units_.unit(*check)));
  return check_.get();
}

const PassProgram& EffectPrograms::texture_fill(const TextureShader& shader) {
  std::optional<TranslationUnit> unit = texture_fill_unit(units_, shader, sm_);
  std::string key = unit ? spirv_cache_key(*unit, compiler_.options()).hex() : "no function:" + shader.function;
  std::unique_ptr<PassProgram>& slot = fills_[key];
  if (slot) return *slot;
  slot = std::make_unique<PassProgram>();
  PassProgram& p = *slot;
  if (!unit) return p;
  StageUnit stage;
  stage.stage = ShaderStage::compute;
  stage.profile = unit->profile;
  stage.function = shader.function;
  stage.entry_point = unit->entry_point;
  stage.range = shader.range;
  p.stages.push_back(compile_stage(stage, std::move(*unit)));
  if (!p.stages.back().shader.ok) return p;
  Clock::time_point start = Clock::now();
  DiagnosticSink sink;
  p.layout = link_program({&p.stages.back().shader}, sink, {});
  p.diagnostics = sink.diagnostics();
  p.compiled = !sink.has_errors();
  p.link_ms = ms_since(start);
  stats_.link_ms += p.link_ms;
  return p;
}

const PassProgram& EffectPrograms::program(const EffectPass& pass) {
  size_t index = static_cast<size_t>(&pass - units_.passes().data());
  std::unique_ptr<PassProgram>& slot = programs_.at(index);
  if (slot) return *slot;
  slot = std::make_unique<PassProgram>();
  PassProgram& p = *slot;
  p.pass = &pass;
  p.unsupported = pass.unsupported;
  bool all_ok = true;
  for (const StageUnit& stage : pass.stages) {
    std::optional<TranslationUnit> unit = units_.unit(stage);
    if (!unit) {
      p.unsupported.push_back(std::string(to_string(stage.stage)) + " stage: " + stage.unsupported);
      continue;
    }
    p.stages.push_back(compile_stage(stage, std::move(*unit)));
    all_ok = all_ok && p.stages.back().shader.ok;
  }
  // An error in a function no stage calls fails the pass too (fxc rejects the whole effect).
  const bool any_hlsl = std::any_of(p.stages.begin(), p.stages.end(),
                                    [](const StageProgram& s) { return s.unit.language == ShaderLanguage::hlsl; });
  if (const StageProgram* check = any_hlsl ? uncalled_check() : nullptr; check && !check->shader.ok) {
    p.diagnostics = check->diagnostics;
    all_ok = false;
  }
  if (all_ok && !p.stages.empty()) {
    Clock::time_point start = Clock::now();
    std::vector<CompiledShader*> shaders;
    for (StageProgram& s : p.stages) shaders.push_back(&s.shader);
    DiagnosticSink sink;
    // ConstructGSWithSO: the outputs it captures stay linked, read by the pixel shader or not.
    auto so = std::find_if(pass.stages.begin(), pass.stages.end(),
                           [](const StageUnit& s) { return s.stream_output.has_value(); });
    std::vector<std::string> captured;
    if (so != pass.stages.end())
      for (const StreamOutputEntry& e : so->stream_output->entries)
        if (!e.entry.semantic.empty())
          captured.push_back(canonical_semantic(e.entry.semantic + std::to_string(e.entry.semantic_index)));
    p.layout = link_program(shaders, sink, captured);
    if (so != pass.stages.end())
      for (StageProgram& s : p.stages)
        if (s.stage == so->stage) p.stream_output = capture_stream_output(s.shader, *so->stream_output, sink);
    p.diagnostics = sink.diagnostics();
    p.compiled = !sink.has_errors();
    p.link_ms = ms_since(start);
    stats_.link_ms += p.link_ms;
  }
  return p;
}

}  // namespace fx
