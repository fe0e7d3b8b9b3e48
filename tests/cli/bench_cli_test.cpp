// `fxkit bench MODE --processes N`: the benchmark run in N fresh processes of the built
// binary, each child's JSON kept, and the median of their ratios reported.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "fxkit_cli.h"

namespace {

using fx::testing::run_fxkit;

TEST(BenchCli, ProcessesReportTheMedianOfEachProcessRatio) {
#ifndef FXKIT_CLI_COMPILES
  GTEST_SKIP() << "a parser-only build has no benchmark: every baseline is glslang or Vulkan";
#endif
  auto r = run_fxkit("bench frontend --size-mb 0.1 --repeats 1 --processes 3 --json", true);
  ASSERT_EQ(r.status, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["benchmark"], "frontend");
  EXPECT_EQ(j["processes"], 3);
  ASSERT_EQ(j["runs"].size(), 3u);
  std::vector<double> ratios;
  for (const auto& run : j["runs"]) {
    EXPECT_EQ(run["benchmark"], "frontend");
    EXPECT_EQ(run["repeats"], 1);
    EXPECT_GT(run["tokens"].get<size_t>(), 1000u);  // each child generated and parsed the effect
    ratios.push_back(run["ratio_mb_per_s"].get<double>());
  }
  EXPECT_EQ(j["ratios"].get<std::vector<double>>(), ratios);
  std::sort(ratios.begin(), ratios.end());
  EXPECT_GT(ratios.front(), 0.0);
  EXPECT_EQ(j["ratio_mb_per_s"].get<double>(), ratios[1]);
  EXPECT_EQ(j["ratio_mb_per_s_min"].get<double>(), ratios.front());
  EXPECT_EQ(j["ratio_mb_per_s_max"].get<double>(), ratios.back());
}

TEST(BenchCli, ProcessesTextNamesEveryProcess) {
#ifndef FXKIT_CLI_COMPILES
  GTEST_SKIP() << "a parser-only build has no benchmark: every baseline is glslang or Vulkan";
#endif
  auto r = run_fxkit("bench frontend --size-mb 0.1 --repeats 1 --processes 2", true);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("in 2 fresh processes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ratio_mb_per_s: median "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("per process: "), std::string::npos) << r.out;
}

TEST(BenchCli, ProcessesRefuseOneAnnotationFileForManyProcesses) {
#ifndef FXKIT_CLI_COMPILES
  GTEST_SKIP() << "a parser-only build has no benchmark: every baseline is glslang or Vulkan";
#endif
  auto r = run_fxkit("bench accuracy --processes 2 --fxh /tmp/unused.fxh", true);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--processes and --fxh"), std::string::npos) << r.err;
}

}  // namespace
