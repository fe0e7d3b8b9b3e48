// The compile worker pool: glslang in fxkit-compile-worker processes. A worker's answer is
// the in-process compiler's; a crash, hang or memory blow-up forced in a worker (its test
// flags --abort-on, --hang-on, --allocate-on) is a located `compiler-crashed` error and the
// worker is replaced, so the next compile works.
#include <gtest/gtest.h>

#include <thread>

#include "fx/compile/compile_workers.h"

namespace {

// A unit as the effect compiler writes them: #line directives into a .fx file.
fx::TranslationUnit pixel_unit(const std::string& body = "return c;") {
  fx::TranslationUnit u;
  u.source =
      "#line 10 \"effects/lit.fx\"\nfloat4 c;\n\nfloat4 PS(float2 uv : TEXCOORD0) : COLOR {\n  " + body + "\n}\n";
  u.stage = fx::ShaderStage::fragment;
  u.entry_point = "PS";
  u.profile = "ps_3_0";
  return u;
}

std::unique_ptr<fx::CompileWorkers> start(fx::CompileWorkerOptions options) {
  std::string error;
  std::unique_ptr<fx::CompileWorkers> pool = fx::CompileWorkers::start(options, error);
  EXPECT_TRUE(pool) << error;
  return pool;
}

void expect_crash_error(const fx::CompiledShader& s, const std::string& what) {
  EXPECT_FALSE(s.ok);
  EXPECT_TRUE(s.spirv.empty());
  ASSERT_EQ(s.messages.size(), 1u);
  const fx::ShaderMessage& m = s.messages[0];
  EXPECT_EQ(m.id, "compiler-crashed");
  EXPECT_EQ(m.file, "effects/lit.fx");  // the entry point's definition, through #line
  EXPECT_EQ(m.line, 12u);
  EXPECT_EQ(m.column, 8u);
  EXPECT_NE(m.text.find(what), std::string::npos) << m.text;
  EXPECT_NE(m.text.find("'PS'"), std::string::npos) << m.text;
}

TEST(CompileWorkers, AnswerAsTheInProcessCompilerDoes) {
  auto pool = start({.workers = 1});
  ASSERT_TRUE(pool);
  fx::ShaderCompiler here;
  fx::ShaderCompiler there({}, nullptr, pool.get());
  for (const fx::TranslationUnit& unit : {pixel_unit(), pixel_unit("return undefined_name;")}) {
    fx::CompiledShader a = here.compile(unit), b = there.compile(unit);
    EXPECT_EQ(a.ok, b.ok);
    EXPECT_EQ(a.spirv, b.spirv);
    EXPECT_EQ(a.info_log, b.info_log);
    ASSERT_EQ(a.messages.size(), b.messages.size());
    for (size_t i = 0; i < a.messages.size(); ++i) {
      EXPECT_EQ(a.messages[i].text, b.messages[i].text);
      EXPECT_EQ(a.messages[i].line, b.messages[i].line);
    }
    EXPECT_EQ(a.reflection.uniform_blocks.size(), b.reflection.uniform_blocks.size());
    EXPECT_EQ(a.reflection.outputs.size(), b.reflection.outputs.size());
  }
  EXPECT_EQ(pool->stats().compiles, 2u);
  EXPECT_EQ(there.glslang_runs(), 2u);
}

TEST(CompileWorkers, ACrashIsALocatedErrorAndTheWorkerIsReplaced) {
  auto pool = start({.workers = 1, .arguments = {"--abort-on", "FXKIT_TEST_CRASH"}});
  ASSERT_TRUE(pool);
  fx::ShaderCompiler compiler({}, nullptr, pool.get());
  expect_crash_error(compiler.compile(pixel_unit("return c; // FXKIT_TEST_CRASH")), "killed by signal 6");
  fx::CompiledShader next = compiler.compile(pixel_unit());
  EXPECT_TRUE(next.ok) << next.info_log;
  fx::CompileWorkerStats stats = pool->stats();
  EXPECT_EQ(stats.crashed, 1u);
  EXPECT_EQ(stats.started, 2u);
}

TEST(CompileWorkers, AHangIsStoppedAtTheTimeLimit) {
  // The limit counts from the unit's sending (a worker's start and warm-up come before):
  // a small shader compiles well inside it even on a loaded machine in a sanitizer build.
  auto pool = start({.workers = 1, .time_limit_ms = 3000, .arguments = {"--hang-on", "FXKIT_TEST_HANG"}});
  ASSERT_TRUE(pool);
  fx::ShaderCompiler compiler({}, nullptr, pool.get());
  expect_crash_error(compiler.compile(pixel_unit("return c; // FXKIT_TEST_HANG")), "did not finish within 3.0 s");
  EXPECT_EQ(pool->stats().timed_out, 1u);
  EXPECT_TRUE(compiler.compile(pixel_unit()).ok);
}

TEST(CompileWorkers, AMemoryBlowUpStopsAtTheLimit) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer builds run workers without an address-space limit";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "AddressSanitizer builds run workers without an address-space limit";
#endif
#endif
  auto pool = start({.workers = 1, .memory_limit_mb = 1024, .arguments = {"--allocate-on", "FXKIT_TEST_MEMORY"}});
  ASSERT_TRUE(pool);
  fx::ShaderCompiler compiler({}, nullptr, pool.get());
  expect_crash_error(compiler.compile(pixel_unit("return c; // FXKIT_TEST_MEMORY")),
                     "ran out of memory (limit 1024 MB)");
  EXPECT_TRUE(compiler.compile(pixel_unit()).ok);
}

TEST(CompileWorkers, ManyThreadsShareFewWorkers) {
  auto pool = start({.workers = 2, .arguments = {"--abort-on", "FXKIT_TEST_CRASH"}});
  ASSERT_TRUE(pool);
  fx::ShaderCompiler compiler({}, nullptr, pool.get());
  std::vector<std::thread> threads;
  std::atomic<int> ok{0}, crashed{0};
  for (int t = 0; t < 6; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 4; ++i) {
        bool crash = t == 0 && i == 1;
        fx::CompiledShader s = compiler.compile(
            pixel_unit(crash ? "return c; // FXKIT_TEST_CRASH" : "return c * " + std::to_string(i) + ";"));
        (s.ok ? ok : crashed) += 1;
      }
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(ok.load(), 23);
  EXPECT_EQ(crashed.load(), 1);
  EXPECT_EQ(pool->size(), 2u);
}

TEST(CompileWorkers, AMissingExecutableIsAnErrorNamingWhereItLooked) {
  std::string error;
  EXPECT_FALSE(fx::CompileWorkers::start({.executable = "/nonexistent/fxkit-compile-worker"}, error));
  EXPECT_NE(error.find("/nonexistent/fxkit-compile-worker"), std::string::npos) << error;
}

TEST(CompileWorkers, AProgramThatIsNoWorkerMakesEachCompileAnError) {
  auto pool = start({.executable = "/bin/true", .workers = 1});
  ASSERT_TRUE(pool);
  fx::CompiledShader s = fx::ShaderCompiler({}, nullptr, pool.get()).compile(pixel_unit());
  expect_crash_error(s, "could not be started ('/bin/true' did not start as a compile worker)");
}

TEST(CompileWorkers, WorkersStartWithTheFirstCompileThatNeedsThem) {
  auto pool = start({.workers = 2});
  ASSERT_TRUE(pool);
  EXPECT_EQ(pool->stats().started, 0u);
  fx::ShaderCompiler compiler({}, nullptr, pool.get());
  EXPECT_TRUE(compiler.compile(pixel_unit()).ok);
  EXPECT_EQ(pool->stats().started, 1u) << "one compile at a time needs one worker";
  EXPECT_GT(pool->stats().start_ms, 0.0);
  EXPECT_GT(pool->stats().warm_up_ms, 0.0);
}

TEST(CompileWorkers, TheBuildTreeWorkerIsFoundByDefault) {
  EXPECT_FALSE(fx::CompileWorkers::find_executable({}).empty());
}

}  // namespace
