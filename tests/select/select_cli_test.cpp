// `fxkit check --caps` and `fxkit select` as a user runs them: the built binary, its exit
// codes, its text and its JSON.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "fxkit_cli.h"

namespace {

using fx::testing::CliRun;
CliRun fxkit(const std::string& args) { return fx::testing::run_fxkit(args); }

const std::string kEffects = std::string(FXKIT_SOURCE_DIR) + "/effects/";

TEST(SelectCli, SelectPrintsTheChoiceAndEveryRejection) {
  CliRun r = fxkit("select " + kEffects + "per_pixel_lighting.fx --caps dx7");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(r.out.rfind("per_pixel_lighting.fx on dx7: dot3_multitexture (direct)\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("  diffuse_ps20: invalid: per_pixel_lighting.fx:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ps_2_0 not supported on dx7"), std::string::npos) << r.out;
}

TEST(SelectCli, SelectJsonHasTheChoiceRouteAndLocatedRejections) {
  CliRun r = fxkit("select " + kEffects + "strand_aniso.fx --caps dx8 --distance 100 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << r.out;
  EXPECT_EQ(j["caps"], "dx8");
  EXPECT_EQ(j["chosen"], "strand_lut_ps11");
  EXPECT_EQ(j["route"], "direct");  // strand_lut_ps11 has no distance band
  EXPECT_EQ(j["criteria"]["distance"], 100.0);
  EXPECT_TRUE(j["criteria"]["budget_ms"].is_null());
  ASSERT_TRUE(j["fallback_path"].is_array());
  EXPECT_TRUE(j["fallback_path"].empty());
  ASSERT_TRUE(j["techniques"].is_array());
  int chosen = 0;
  for (const auto& t : j["techniques"]) {
    ASSERT_TRUE(t.contains("name") && t.contains("valid") && t.contains("reason") && t.contains("rejections"));
    chosen += t["chosen"].get<bool>() ? 1 : 0;
    if (t["chosen"].get<bool>()) EXPECT_EQ(t["reason"], "");
    else EXPECT_NE(t["reason"], "") << t["name"];
    if (!t["valid"].get<bool>()) {
      ASSERT_FALSE(t["rejections"].empty()) << t["name"];
      const auto& first = t["rejections"][0];
      EXPECT_NE(first["file"].get<std::string>().find("strand_aniso.fx"), std::string::npos);
      EXPECT_GT(first["line"].get<int>(), 0);
      EXPECT_EQ(first["severity"], "note");
    }
  }
  EXPECT_EQ(chosen, 1);
}

TEST(SelectCli, SelectWithNothingValidExitsOne) {
  CliRun r = fxkit("select " + kEffects + "aniso_highlights_glsl.fx --caps dx9c --json");
  EXPECT_EQ(r.status, 1) << r.out;
  nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_TRUE(j["chosen"].is_null());
  EXPECT_EQ(j["route"], "none");
}

// An effect with errors does not load, so `render` draws none of its techniques: `select`
// calls none valid either, however well the technique itself would run.
TEST(SelectCli, SelectCallsNoTechniqueOfAnEffectWithErrorsValid) {
  const std::string path = ::testing::TempDir() + "fxkit_select_errors.fx";
  std::ofstream(path) << "undeclared_type Broken;\n"
                         "float4 VS(float4 p : POSITION) : SV_Position { return p; }\n"
                         "float4 PS() : SV_Target { return 1; }\n"
                         "technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); "
                         "SetPixelShader(CompileShader(ps_4_0, PS())); } }\n";
  CliRun r = fxkit("select " + path + " --caps modern --json");
  EXPECT_EQ(r.status, 1) << r.out;
  nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << r.out;
  EXPECT_TRUE(j["chosen"].is_null());
  ASSERT_EQ(j["techniques"].size(), 1u);
  EXPECT_FALSE(j["techniques"][0]["valid"].get<bool>());
  EXPECT_EQ(j["techniques"][0]["reason"], "the effect has errors, so it does not load");
  std::remove(path.c_str());
}

TEST(SelectCli, CheckCapsListsEveryTechniqueWithReasons) {
  CliRun r = fxkit("check " + kEffects + "per_pixel_lighting.fx --caps modern");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("on modern: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  valid    diffuse_ps20\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  invalid  emboss\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("has no Vulkan equivalent (modern has no fixed-function texture stages)"), std::string::npos)
      << r.out;

  CliRun j = fxkit("check --json --caps dx6 " + kEffects + "per_pixel_lighting.fx");
  EXPECT_EQ(j.status, 0) << j.out;
  nlohmann::json doc = nlohmann::json::parse(j.out, nullptr, false);
  ASSERT_FALSE(doc.is_discarded()) << j.out;
  const auto& e = doc["effects"][0];
  EXPECT_EQ(e["caps"], "dx6");
  ASSERT_TRUE(e["techniques"].is_array());
  size_t valid = 0;
  for (const auto& t : e["techniques"]) valid += t["valid"].get<bool>() ? 1 : 0;
  EXPECT_EQ(e["valid_techniques"], valid);
  EXPECT_GE(valid, 2u);  // emboss, specular_emboss
}

TEST(SelectCli, LiveDeviceCapsRunTheShaderModel2Technique) {
  // Only queries the physical device (no rendering, so no validation messenger to attach).
  CliRun r = fxkit("select " + kEffects + "per_pixel_lighting.fx --caps device --json");
  ASSERT_EQ(r.status, 0) << r.out;
  nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["chosen"], "diffuse_ps20");
  EXPECT_NE(j["caps"], "modern");  // the device's own name
}

TEST(SelectCli, CheckCapsFailsWhenNothingRunsAndOnBadCaps) {
  EXPECT_EQ(fxkit("check " + kEffects + "strand_aniso.fx --caps dx7").status, 1);
  EXPECT_EQ(fxkit("check " + kEffects + "strand_aniso.fx --caps dx77").status, 2);
  EXPECT_EQ(fxkit("select " + kEffects + "strand_aniso.fx --caps /no/such/caps.json").status, 2);
  // A saved caps file is accepted.
  CliRun saved = fxkit("select " + std::string(FXKIT_SOURCE_DIR) + "/effects/hemisphere.fx --caps " +
                       std::string(FXKIT_SOURCE_DIR) + "/runtime/select/profiles/dx8.json");
  EXPECT_EQ(saved.status, 0);
  EXPECT_EQ(saved.out.rfind("hemisphere.fx on dx8: hemisphere_ps11", 0), 0u) << saved.out;
}

// The acceptance test of the technique table (docs/accuracy.json, `techniques`, written with
// effects/generated/costs.fxh by scripts/accuracy-report): for every effect and error limit,
// `fxkit select --caps device --max-error E` picks the cheapest technique whose measured
// error is within E (ns per pixel, then ns per vertex, as costs.fxh rounds them), among the
// techniques the device runs and the default distance admits; a technique without a
// measured error is never picked (not even down a fallback chain) and says "error not measured".
TEST(SelectCli, ErrorLimitPicksTheCheapestTechniqueOfTheMeasuredTable) {
  std::ifstream in(std::string(FXKIT_SOURCE_DIR) + "/docs/accuracy.json");
  nlohmann::json table = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(table.is_discarded());
  ASSERT_TRUE(table["techniques"].is_array());
  struct Row {
    double error, ns_pixel, ns_vertex;
    bool measured;
  };
  std::map<std::string, std::map<std::string, Row>> effects;
  auto rounded = [](double v, double scale) { return std::round(std::max(0.0, v) * scale) / scale; };
  for (const auto& t : table["techniques"]) {
    // A precision-model row is the technique compiled with FXKIT_PS1X_PRECISION, not a
    // technique selection can pick: selection ranks the default compile's row.
    if (t.value("precision_model", false)) continue;
    const bool measured = t["measured"].get<bool>() && t.contains("ns_per_pixel");
    Row r{0, 0, 0, measured};
    if (measured)
      r = {rounded(t["max_error_lsb"].get<double>(), 100), rounded(t["ns_per_pixel"].get<double>(), 1000),
           rounded(t["ns_per_vertex"].get<double>(), 1000), true};
    effects[t["effect"].get<std::string>()][t["technique"].get<std::string>()] = r;
  }
  ASSERT_GE(effects.size(), 7u);
  int picked = 0;
  for (const auto& [effect, rows] : effects) {
    for (double limit : {0.5, 2.0, 8.0, 32.0}) {
      SCOPED_TRACE(effect + " --max-error " + std::to_string(limit));
      char arg[32];
      std::snprintf(arg, sizeof arg, "%g", limit);
      CliRun r = fxkit("select " + kEffects + effect + " --caps device --max-error " + arg + " --json");
      nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
      ASSERT_FALSE(j.is_discarded()) << r.out << r.err;
      ASSERT_EQ(j["techniques"].size(), rows.size()) << "the table lists every technique";
      std::string expected;
      const Row* best = nullptr;
      for (const auto& t : j["techniques"]) {
        const std::string name = t["name"].get<std::string>();
        ASSERT_TRUE(rows.count(name)) << name;
        const Row& row = rows.at(name);
        const std::string reason = t["reason"].get<std::string>();
        if (!row.measured && t["valid"].get<bool>() && reason.rfind("outside ", 0) != 0) {
          EXPECT_NE(reason.find("error not measured"), std::string::npos) << name << ": " << reason;
        }
        EXPECT_FALSE(!row.measured && t["chosen"].get<bool>()) << "picked " << name << ", whose error is unknown";
        const bool eligible = t["valid"].get<bool>() && reason.rfind("outside ", 0) != 0;
        if (!row.measured || !eligible || row.error > limit) continue;
        if (!best || row.ns_pixel < best->ns_pixel ||
            (row.ns_pixel == best->ns_pixel && row.ns_vertex < best->ns_vertex))
          best = &row, expected = name;
      }
      if (!best) continue;
      ++picked;
      EXPECT_EQ(j["route"], "direct");
      ASSERT_TRUE(j["chosen"].is_string());
      const Row& chosen = rows.at(j["chosen"].get<std::string>());
      EXPECT_TRUE(chosen.measured && chosen.ns_pixel == best->ns_pixel && chosen.ns_vertex == best->ns_vertex)
          << "chose " << j["chosen"] << ", the cheapest within the limit is " << expected;
    }
  }
  EXPECT_GE(picked, 6);  // at least two effects with measured techniques, several limits
}

// Every drawable technique of every effect in effects/ has a measured row in the technique
// table (docs/accuracy.json), so `select --max-error` meets no unknown error among them and
// docs/accuracy.md plots each of them: the table has rows for every effect file of the
// folder, one per technique `select` lists, and each drawable one is measured. A new effect
// or technique without a reference model fails here until scripts/accuracy-report measures it.
TEST(SelectCli, EveryDrawableTechniqueOfTheEffectsHasAMeasuredRow) {
  std::ifstream in(std::string(FXKIT_SOURCE_DIR) + "/docs/accuracy.json");
  nlohmann::json table = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(table.is_discarded());
  std::map<std::string, std::map<std::string, nlohmann::json>> rows;  // effect -> technique -> row
  for (const auto& t : table["techniques"])
    if (!t.value("precision_model", false)) rows[t["effect"].get<std::string>()][t["technique"].get<std::string>()] = t;
  int drawable = 0, measured = 0;
  for (const auto& file : std::filesystem::directory_iterator(kEffects)) {
    if (file.path().extension() != ".fx") continue;
    const std::string effect = file.path().filename().string();
    SCOPED_TRACE(effect);
    ASSERT_TRUE(rows.count(effect)) << "no rows in docs/accuracy.json (scripts/accuracy-report --effect " << effect
                                    << ")";
    CliRun r = fxkit("select " + kEffects + effect + " --caps device --json");
    nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << r.out << r.err;
    EXPECT_EQ(j["techniques"].size(), rows[effect].size());
    for (const auto& t : j["techniques"]) EXPECT_TRUE(rows[effect].count(t["name"].get<std::string>())) << t["name"];
    for (const auto& [name, row] : rows[effect]) {
      if (!row["drawable"].get<bool>()) continue;
      ++drawable;
      const bool ok = row["measured"].get<bool>() && row.contains("max_error_lsb");
      measured += ok;
      EXPECT_TRUE(ok) << name << " is drawable and not measured: " << row.value("reason", std::string());
    }
  }
  std::printf("measured rows: %d/%d drawable techniques\n", measured, drawable);
  EXPECT_GE(drawable, 40);
}

}  // namespace
