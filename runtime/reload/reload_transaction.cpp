// The reload transaction: every step of building an effect version, timed, all-or-nothing.
#include "fx/reload/reload_transaction.h"

#include <chrono>

#include "fx/compile/effect_file.h"

#include "version_steps.h"

namespace fx {

std::atomic<size_t> EffectVersion::live_{0};

EffectVersion::EffectVersion() { live_.fetch_add(1, std::memory_order_relaxed); }
EffectVersion::~EffectVersion() {
  // Destroy in reverse dependency order: GPU objects, then what points into the tree.
  gpu.reset();
  techniques.reset();
  params.reset();
  programs.reset();
  units.reset();
  model.reset();
  sources.reset();
  file.reset();
  live_.fetch_sub(1, std::memory_order_relaxed);
}
size_t EffectVersion::live_count() { return live_.load(std::memory_order_relaxed); }

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Attaches the compile side's rejections to the model side's techniques.
void merge(std::vector<TechniqueFacts>& facts, const ProgramOutcome& outcome) {
  for (const ProgramOutcome::Rejection& r : outcome.rejections) {
    uint32_t i = r.technique_index;
    if (i >= facts.size() || facts[i].name != r.technique) {
      i = kNoIndex;  // units name unnamed techniques "technique<i>": match by name
      for (uint32_t j = 0; j < facts.size(); ++j)
        if (facts[j].name == r.technique) i = j;
      if (i == kNoIndex) continue;
    }
    facts[i].valid = false;
    facts[i].reasons.push_back(r.reason);
  }
}

}  // namespace

ReloadTransactionResult run_reload_transaction(const ReloadTransactionInput& input) {
  ReloadTransactionResult result;
  auto version = std::make_unique<EffectVersion>();
  version->path = input.path;
  version->serial = input.serial;
  DiagnosticSink sink;
  static const FrontEndOptions kDefaults;
  const FrontEndOptions& fe = input.front_end ? *input.front_end : kDefaults;

  // Parse: front end, effect model, parameters.
  Clock::time_point start = Clock::now();
  version->file = EffectFile::parse(input.path, fe, sink);
  version->sources = std::shared_ptr<SourceManager>(version->file, &version->file->sources);
  result.sources = version->sources;
  result.files = version->file->parsed.files;
  if (result.files.empty()) result.files.push_back(input.path);
  std::vector<TechniqueFacts> facts;
  bool ok = !sink.has_errors() && build_version_model(*version, sink, facts);
  result.ms.parse = ms_since(start);

  // Compile: units and programs.
  if (ok && input.compiler) {
    start = Clock::now();
    ProgramOutcome outcome;
    ok = build_version_programs(*version, *input.compiler, input.executor, sink, outcome);
    result.ms.compile = ms_since(start);
    result.ms.glslang = outcome.glslang_ms;
    result.recompiled = std::move(outcome.recompiled);
    merge(facts, outcome);
  }

  // Select: candidates validated against the caps, and the plan.
  if (ok) {
    start = Clock::now();
    version->techniques = TechniqueChoice::build(std::move(facts), input.caps, sink);
    result.ms.parse += ms_since(start);
    ok = !sink.has_errors();
  }

  // GPU objects.
  if (ok && input.backend) {
    BackendTimings timings;
    DiagnosticSink gpu_sink;
    {
      std::unique_lock<std::mutex> lock;
      if (input.backend_mutex) lock = std::unique_lock(*input.backend_mutex);
      version->gpu = input.backend->prepare(*version, gpu_sink, timings);
    }
    for (const Diagnostic& d : gpu_sink.diagnostics()) forward(d, sink);
    if (!version->gpu && !sink.has_errors())
      sink.error("reload-backend-failed", {}, "the GPU backend could not prepare " + input.path);
    result.ms.pipeline = timings.pipeline_ms;
    result.ms.first_frame = timings.first_frame_ms;
    ok = !sink.has_errors();
  }

  result.diagnostics = sink.diagnostics();
  if (ok && !sink.has_errors()) {
    version->warnings = result.diagnostics;
    result.version = std::move(version);
  }
  return result;
}

}  // namespace fx
