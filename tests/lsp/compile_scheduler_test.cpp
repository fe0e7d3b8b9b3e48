// The compile scheduler of the language server: results come back through the ready
// callback, a snapshot replaced before it runs is never compiled, and the result of one
// replaced while it runs is thrown away (driven by events, not by the clock).
#include "compile_scheduler.h"

#include <gtest/gtest.h>

#include "compile_events.h"

namespace {

using fx::testing::CompileEvents;
using fx::tools::lsp::CompileScheduler;
using fx::tools::lsp::CompileSnapshot;
using nlohmann::json;

CompileSnapshot snapshot(const std::string& uri, uint64_t generation) {
  CompileSnapshot s;
  s.uri = uri;
  s.generation = generation;
  s.document.text = "text of " + std::to_string(generation);
  return s;
}

// A compile that reports which snapshot it saw.
fx::tools::lsp::CompileFindings compiled(CompileEvents& events, const CompileSnapshot& s) {
  events.started(s.generation);
  return {json::array({{{"message", s.document.text}}})};
}

TEST(CompileScheduler, ResultArrivesThroughTheReadyCallback) {
  CompileEvents events;
  CompileScheduler scheduler([&](const CompileSnapshot& s) { return compiled(events, s); },
                             std::chrono::milliseconds(0), [&] { events.ready(); });
  scheduler.schedule(snapshot("file:///a.fx", 1));
  events.wait_ready(1);
  auto results = scheduler.take_results();
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].uri, "file:///a.fx");
  EXPECT_EQ(results[0].generation, 1u);
  EXPECT_EQ(results[0].findings.diagnostics[0]["message"], "text of 1");
  EXPECT_TRUE(scheduler.take_results().empty());  // each once
}

TEST(CompileScheduler, OutdatedResultIsThrownAwayAndWaitingSnapshotReplaced) {
  CompileEvents events;
  events.hold(1);
  CompileScheduler scheduler([&](const CompileSnapshot& s) { return compiled(events, s); },
                             std::chrono::milliseconds(0), [&] { events.ready(); });
  scheduler.schedule(snapshot("file:///a.fx", 1));
  events.wait_started(1);  // generation 1 is compiling (held)
  scheduler.schedule(snapshot("file:///a.fx", 2));
  scheduler.schedule(snapshot("file:///a.fx", 3));  // replaces 2, which never runs
  events.release(1);
  events.wait_ready(1);
  auto results = scheduler.take_results();
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].generation, 3u);
  EXPECT_EQ(results[0].findings.diagnostics[0]["message"], "text of 3");
  EXPECT_EQ(events.started_generations(), (std::vector<uint64_t>{1, 3}));
  const CompileScheduler::Stats stats = scheduler.stats();
  EXPECT_EQ(stats.replaced, 1u);
  EXPECT_EQ(stats.discarded, 1u);
}

TEST(CompileScheduler, CancelledDocumentGetsNoResult) {
  CompileEvents events;
  events.hold(1);
  CompileScheduler scheduler([&](const CompileSnapshot& s) { return compiled(events, s); },
                             std::chrono::milliseconds(0), [&] { events.ready(); });
  scheduler.schedule(snapshot("file:///a.fx", 1));
  events.wait_started(1);
  scheduler.cancel("file:///a.fx");  // closed while compiling
  scheduler.schedule(snapshot("file:///b.fx", 2));
  events.release(1);
  events.wait_ready(1);  // b's result: a's was thrown away before it
  auto results = scheduler.take_results();
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].uri, "file:///b.fx");
  EXPECT_EQ(scheduler.stats().discarded, 1u);
}

TEST(CompileScheduler, CompileThatThrowsBecomesADiagnostic) {
  CompileEvents events;
  CompileScheduler scheduler(
      [](const CompileSnapshot&) -> fx::tools::lsp::CompileFindings { throw std::runtime_error("out of luck"); },
      std::chrono::milliseconds(0), [&] { events.ready(); });
  scheduler.schedule(snapshot("file:///a.fx", 1));
  events.wait_ready(1);
  auto results = scheduler.take_results();
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].findings.diagnostics[0]["message"], "compiling the shaders failed: out of luck");
}

}  // namespace
