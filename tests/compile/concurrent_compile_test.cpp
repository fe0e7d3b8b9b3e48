// Many compiles at once, as `fxkit check --jobs N` and EffectLibrary's compile pool run
// them: one ShaderCompiler and SPIR-V cache shared by every thread, EffectPrograms per
// effect with its stages spread over the same pool (nested batches), and the library
// loading several effects in one call. Also built under ThreadSanitizer (scripts/tsan).
#include <gtest/gtest.h>

#include <filesystem>
#include <thread>

#include "fx/compile/effect_programs.h"
#include "fx/compile/spirv_cache.h"
#include "fx/frontend.h"
#include "fx/reload/effect_library.h"
#include "fx/worker_pool.h"

namespace {

const std::string kEffects = std::string(FXKIT_SOURCE_DIR) + "/effects/";

std::vector<std::string> seed_effects() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(kEffects))
    if (e.path().extension() == ".fx") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Every pass of `path` compiled with its stages on `pool`; the count of stages that compiled.
size_t compile_effect(const std::string& path, const fx::ShaderCompiler& compiler, fx::TaskExecutor& pool,
                      size_t* failed) {
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  fx::ParsedEffect parsed = fx::parse_effect_file(path, sm, diags, {});
  fx::EffectUnits units(parsed.ast, sm, diags);
  fx::EffectPrograms programs(units, compiler, sm);
  programs.compile_all(pool, true);
  size_t ok = 0;
  for (const fx::EffectPass& pass : units.passes())
    for (const fx::StageProgram& s : programs.program(pass).stages) {
      ok += s.shader.ok ? 1 : 0;
      *failed += s.shader.ok ? 0 : 1;
    }
  return ok;
}

TEST(ConcurrentCompile, EffectsAndStagesOnOnePoolMatchTheSerialCompile) {
  const std::vector<std::string> effects = seed_effects();
  ASSERT_GE(effects.size(), 5u);
  fx::WorkerPool serial(1);
  fx::ShaderCompiler alone;
  std::vector<size_t> expected(effects.size());
  size_t failed = 0;
  for (size_t i = 0; i < effects.size(); ++i) expected[i] = compile_effect(effects[i], alone, serial, &failed);
  EXPECT_EQ(failed, 0u);

  fx::SpirvCache cache;
  fx::ShaderCompiler shared({}, &cache);
  fx::WorkerPool pool(4);
  for (int round = 0; round < 3; ++round) {  // the later rounds are cache hits, read concurrently
    std::vector<size_t> got(effects.size() * 2);
    std::vector<size_t> fails(got.size(), 0);
    pool.for_each(got.size(),
                  [&](size_t i) { got[i] = compile_effect(effects[i % effects.size()], shared, pool, &fails[i]); });
    for (size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i], expected[i % effects.size()]) << effects[i % effects.size()];
      EXPECT_EQ(fails[i], 0u);
    }
  }
}

TEST(ConcurrentCompile, LibraryLoadsSeveralEffectsOnItsCompilePool) {
  const std::vector<std::string> effects = seed_effects();
  fx::EffectLibraryOptions options;
  options.watch = false;
  options.include_dirs = {kEffects};
  options.compile_threads = 3;
  fx::EffectLibrary library(std::move(options));
  std::vector<std::string> twice = effects;
  twice.insert(twice.end(), effects.begin(), effects.end());  // the same path twice: one effect
  std::vector<fx::EffectHandle> handles = library.load(twice);
  ASSERT_EQ(handles.size(), twice.size());
  for (size_t i = 0; i < effects.size(); ++i) {
    EXPECT_TRUE(handles[i].ok()) << effects[i];
    EXPECT_EQ(handles[i].version(), handles[i + effects.size()].version());
  }
  EXPECT_EQ(library.load(effects.front()).version(), handles.front().version());
}

TEST(ConcurrentCompile, LibraryTakesTheApplicationsExecutor) {
  struct CountingExecutor final : fx::TaskExecutor {
    fx::WorkerPool pool{2};
    std::atomic<size_t> batches{0};
    void for_each(size_t count, const std::function<void(size_t)>& task) override {
      batches.fetch_add(1);
      pool.for_each(count, task);
    }
    size_t concurrency() const override { return pool.concurrency(); }
  } executor;
  fx::EffectLibraryOptions options;
  options.watch = false;
  options.executor = &executor;
  fx::EffectLibrary library(std::move(options));
  std::vector<fx::EffectHandle> handles = library.load(seed_effects());
  for (const fx::EffectHandle& h : handles) EXPECT_TRUE(h.ok()) << h.path();
  EXPECT_GT(executor.batches.load(), handles.size());  // the load's batch and each effect's stages
}

}  // namespace
