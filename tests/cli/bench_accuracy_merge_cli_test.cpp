// `fxkit bench accuracy --effect F --merge JSON`: one effect's techniques measured again and
// merged into an earlier table (scripts/accuracy-report --effect), every other row kept as
// it was; --merge without --effect and an unknown effect are usage or input errors.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fxkit_cli.h"

namespace {

using fx::testing::run_fxkit;

const std::string kSource = FXKIT_SOURCE_DIR;

TEST(BenchAccuracyMergeCli, OneEffectIsMeasuredAgainAndTheRestKept) {
  std::ifstream in(kSource + "/docs/accuracy.json");
  const nlohmann::json earlier = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(earlier.is_discarded());
  const std::string fxh = testing::TempDir() + "merge_costs.fxh";
  auto r = run_fxkit("bench accuracy --repeats 1 --effects " + kSource + "/effects --effect hemisphere.fx --merge " +
                         kSource + "/docs/accuracy.json --json --fxh " + fxh,
                     true);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json merged = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(merged.is_discarded()) << r.out;
  EXPECT_EQ(merged["approximations"], earlier["approximations"]);
  // Rows by effect, technique and precision model, in the order each table lists them.
  auto key = [](const nlohmann::json& r) {
    return r["effect"].get<std::string>() + " " + r["technique"].get<std::string>() +
           (r.value("precision_model", false) ? " (ps.1.x precision)" : "");
  };
  std::vector<std::string> kept_before, kept_after;
  std::map<std::string, nlohmann::json> before;
  for (const auto& r : earlier["techniques"]) {
    before[key(r)] = r;
    if (r["effect"] != "hemisphere.fx") kept_before.push_back(key(r));
  }
  size_t remeasured = 0;
  for (const auto& b : merged["techniques"]) {
    if (b["effect"] != "hemisphere.fx") {
      kept_after.push_back(key(b));
      for (const auto& [k, value] : before[key(b)].items()) EXPECT_EQ(b[k], value) << key(b) << " " << k << ": kept";
      continue;
    }
    ++remeasured;
    // Errors are deterministic; costs are timed again (not compared).
    const auto it = before.find(key(b));
    if (it == before.end() || !it->second["measured"].get<bool>()) continue;
    EXPECT_TRUE(b["measured"].get<bool>()) << key(b);
    EXPECT_NEAR(it->second["max_error_lsb"].get<double>(), b["max_error_lsb"].get<double>(), 0.5) << key(b);
  }
  EXPECT_EQ(kept_after, kept_before);
  EXPECT_GE(remeasured, 8u);
  const auto& runs = merged["technique_runs"];
  ASSERT_EQ(runs.size(), earlier.value("technique_runs", nlohmann::json::array()).size() + 1);
  EXPECT_EQ(runs.back()["effects"], nlohmann::json::array({"hemisphere.fx"}));
  std::ifstream annotations(fxh);
  const std::string text((std::istreambuf_iterator<char>(annotations)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("#define COST_wood "), std::string::npos) << "kept rows are annotated too";
  EXPECT_NE(text.find("Ps1xPrecisionMaxError"), std::string::npos);
}

TEST(BenchAccuracyMergeCli, MergeNeedsAnEffectAndTheEffectMustExist) {
  auto no_effect = run_fxkit("bench accuracy --merge " + kSource + "/docs/accuracy.json --json", true);
  EXPECT_EQ(no_effect.status, 2);
  EXPECT_NE(no_effect.err.find("--merge needs --effect"), std::string::npos) << no_effect.err;
  auto unknown = run_fxkit("bench accuracy --repeats 1 --effects " + kSource + "/effects --effect nosuch.fx --merge " +
                               kSource + "/docs/accuracy.json --json",
                           true);
  EXPECT_NE(unknown.status, 0);
  EXPECT_NE(unknown.err.find("no effect 'nosuch.fx'"), std::string::npos) << unknown.err;
}

}  // namespace
