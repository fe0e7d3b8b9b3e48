// `fxkit bench frontend`: front-end throughput (preprocess + parse + check) on a generated
// effect of at least 10 MB with macros and includes, against glslang parsing just the
// shader code of the same effect. Both measured in this run; the ratio is what counts.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <numeric>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <nlohmann/json.hpp>

#include "bench.h"
#include "effect_generator.h"
#include "fx/frontend.h"

namespace fx::tools {
namespace {

using Clock = std::chrono::steady_clock;

// Seconds `fn` takes.
double seconds(const std::function<void()>& fn) {
  auto start = Clock::now();
  fn();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct PhaseTimes {
  double preprocess = 0, parse = 0, check = 0, total = 0;
  size_t tokens = 0, errors = 0;
};

PhaseTimes run_front_end(const GeneratedEffect& g) {
  fx::PreprocessorOptions options;
  options.loader = [&g](const std::string& path) -> std::optional<std::string> {
    auto it = g.files.find(path.substr(path.find_last_of('/') + 1));
    if (it == g.files.end()) return std::nullopt;
    return it->second;
  };
  options.lister = [](const std::string&) { return std::vector<std::string>{}; };
  options.limits.max_input_bytes = 1u << 30;
  options.limits.max_tokens = 1u << 28;
  options.limits.max_macro_expansions = 1u << 28;
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  PhaseTimes t;
  auto t0 = Clock::now();
  std::vector<fx::Token> tokens;
  fx::Preprocessor pp(sm, diags, options);
  pp.run_file(g.main_name, tokens);
  auto t1 = Clock::now();
  t.tokens = tokens.size();
  fx::ast::Effect effect = fx::parse_effect(std::move(tokens), sm, diags);
  auto t2 = Clock::now();
  fx::check_effect(effect, sm, diags);
  auto t3 = Clock::now();
  t.preprocess = std::chrono::duration<double>(t1 - t0).count();
  t.parse = std::chrono::duration<double>(t2 - t1).count();
  t.check = std::chrono::duration<double>(t3 - t2).count();
  t.total = std::chrono::duration<double>(t3 - t0).count();
  t.errors = diags.error_count();
  return t;
}

bool glslang_parse(const std::string& code, const char* entry) {
  glslang::TShader shader(EShLangFragment);
  const char* text = code.c_str();
  int length = static_cast<int>(code.size());
  shader.setStringsWithLengths(&text, &length, 1);
  shader.setEntryPoint(entry);
  shader.setEnvInput(glslang::EShSourceHlsl, EShLangFragment, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgReadHlsl);
  return shader.parse(GetDefaultResources(), 100, false, messages);
}

}  // namespace

int bench_frontend(const BenchArgs& args) {
  size_t bytes = static_cast<size_t>(args.size_mb * 1024 * 1024);
  GeneratedEffect g = generate_effect(bytes);
  double mb = g.effect_bytes / 1e6, shader_mb = g.shader_code.size() / 1e6;

  PhaseTimes best = run_front_end(g);  // warm-up, and the error count to report
  glslang::InitializeProcess();
  glslang_parse("float4 PS0() : SV_Target { return 0; }", "PS0");  // built-in tables, once

  // Rounds: a block of front-end runs, one glslang run, the next block, and so on. A round's
  // ratio sets its glslang run against the blocks on either side of it, so both sides see
  // the same minute of a noisy machine; timing all of one side and then all of the other
  // let a slow spell land on one side only. The ratio is the median over rounds.
  constexpr int kFrontRunsPerBlock = 2;
  const int rounds = std::max(1, args.repeats / 2);
  std::vector<PhaseTimes> runs;
  std::vector<double> front_times, glslang_times, round_ratios;
  auto front_block = [&] {
    for (int i = 0; i < kFrontRunsPerBlock; ++i)
      front_times.push_back(seconds([&] { runs.push_back(run_front_end(g)); }));
  };
  bool glslang_ok = true;
  front_block();
  for (int r = 0; r < rounds; ++r) {
    glslang_times.push_back(seconds([&] { glslang_ok = glslang_parse(g.shader_code, "PS0") && glslang_ok; }));
    front_block();
    // The mean of the block before this glslang run and the block after it.
    auto around = front_times.end() - 2 * kFrontRunsPerBlock;
    double round_front = std::accumulate(around, front_times.end(), 0.0) / (2 * kFrontRunsPerBlock);
    round_ratios.push_back((mb / round_front) / (shader_mb / glslang_times.back()));
  }
  glslang::FinalizeProcess();
  std::sort(runs.begin(), runs.end(), [](auto& a, auto& b) { return a.total < b.total; });
  PhaseTimes median_run = runs[runs.size() / 2];
  const double front = median(front_times), glsl = median(glslang_times);
  const double ratio = median(round_ratios);

  double front_rate = mb / front, glsl_rate = shader_mb / glsl;
  nlohmann::json j = {
      {"benchmark", "frontend"},
      {"effect_mb", mb},
      {"modules", g.files.size() - 1},
      {"tokens", median_run.tokens},
      {"front_end",
       {{"seconds", front},
        {"mb_per_s", front_rate},
        {"preprocess_s", median_run.preprocess},
        {"parse_s", median_run.parse},
        {"check_s", median_run.check},
        {"errors", best.errors}}},
      {"glslang", {{"seconds", glsl}, {"shader_mb", shader_mb}, {"mb_per_s", glsl_rate}, {"ok", glslang_ok}}},
      {"ratio_mb_per_s", ratio},
      {"rounds", rounds},
      {"repeats", args.repeats}};
  if (args.json) {
    std::puts(json_text(j).c_str());
  } else {
    std::printf("fxkit bench frontend: %.1f MB effect, %zu included modules, %zu tokens\n", mb, g.files.size() - 1,
                median_run.tokens);
    std::printf("  medians of %zu front-end and %zu glslang runs, interleaved in %d rounds\n", front_times.size(),
                glslang_times.size(), rounds);
    std::printf("  front end (preprocess %.3f s + parse %.3f s + check %.3f s)  %7.3f s  %8.1f MB/s\n",
                median_run.preprocess, median_run.parse, median_run.check, front, front_rate);
    std::printf("  baseline: glslang parse of the %.1f MB of shader code   %7.3f s  %8.1f MB/s%s\n", shader_mb, glsl,
                glsl_rate, glslang_ok ? "" : "  (glslang reported errors)");
    std::printf("  ratio (front end MB/s / glslang MB/s), median of rounds  %7.1fx\n", ratio);
    if (best.errors) std::printf("  warning: the front end reported %zu errors on the generated effect\n", best.errors);
  }
  return best.errors || !glslang_ok ? kInputErrors : kSuccess;
}

}  // namespace fx::tools
