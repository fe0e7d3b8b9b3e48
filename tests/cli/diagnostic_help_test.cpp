// Every diagnostic id fxkit reports has help text (docs/diagnostics.md, compiled into the
// check library), so a SARIF run that reports each of them describes each rule, not just
// names it. The ids are the ones the sources report through a DiagnosticSink or a public
// Message with a literal id.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "check_report.h"
#include "diagnostic_help.h"
#include "sarif_report.h"

namespace {

namespace fs = std::filesystem;

// Each id reported as `sink.error("id", ...)`, `report(Severity::x, "id", ...)`,
// `to_message(Severity::x, "id", ...)` and the like, with the file that reports it first.
std::map<std::string, std::string> reported_ids() {
  static const std::regex reported(
      R"re(\b(?:error|warning|note|report|to_message)\(\s*(?:(?:fx::)?Severity::\w+\s*,\s*|[^,()]*\?[^,()]*:\s*[^,()]*,\s*)?"([a-z0-9]+(?:-[a-z0-9]+)+)")re");
  std::map<std::string, std::string> out;
  for (const char* root : {"lib", "parser", "runtime", "tools", "samples", "bench"})
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(fs::path(FXKIT_SOURCE_DIR) / root)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
      std::ifstream in(e.path());
      std::ostringstream text;
      text << in.rdbuf();
      const std::string source = text.str();
      for (auto it = std::sregex_iterator(source.begin(), source.end(), reported); it != std::sregex_iterator(); ++it)
        out.emplace((*it)[1], fs::relative(e.path(), FXKIT_SOURCE_DIR).string());
    }
  return out;
}

TEST(DiagnosticHelp, EveryReportedIdHasHelpText) {
  const std::map<std::string, std::string> ids = reported_ids();
  ASSERT_GT(ids.size(), 100u) << "the scan found too few ids: has the reporting style changed?";
  for (const auto& [id, file] : ids) {
    auto help = fx::tools::diagnostic_help().find(id);
    if (help == fx::tools::diagnostic_help().end()) {
      ADD_FAILURE() << "'" << id << "' (" << file << ") has no row in docs/diagnostics.md";
      continue;
    }
    EXPECT_FALSE(help->second.meaning.empty()) << id;
    EXPECT_FALSE(help->second.severity.empty()) << id;
  }
}

TEST(DiagnosticHelp, ASarifRunReportingEveryIdDescribesEveryRule) {
  fx::tools::EffectCheck check;
  check.file = "every.fx";
  for (const auto& [id, file] : reported_ids())
    check.diagnostics.push_back(
        {{"file", "every.fx"}, {"line", 1}, {"column", 1}, {"severity", "error"}, {"id", id}, {"message", "a " + id}});
  fx::tools::CheckRun run;
  run.checks.push_back(check);
  const nlohmann::json sarif = fx::tools::sarif_report(run, "/work");
  EXPECT_EQ(sarif["version"], "2.1.0");
  ASSERT_EQ(sarif["runs"].size(), 1u);
  const nlohmann::json& rules = sarif["runs"][0]["tool"]["driver"]["rules"];
  const nlohmann::json& results = sarif["runs"][0]["results"];
  ASSERT_EQ(rules.size(), check.diagnostics.size());
  ASSERT_EQ(results.size(), check.diagnostics.size());
  std::set<std::string> rule_ids;
  for (const nlohmann::json& rule : rules) {
    const std::string id = rule["id"];
    rule_ids.insert(id);
    ASSERT_TRUE(rule.contains("help")) << id << " has no help";
    EXPECT_NE(rule["shortDescription"]["text"], id) << "the description of " << id << " is its id";
    EXPECT_FALSE(rule["help"]["text"].get<std::string>().empty()) << id;
    EXPECT_FALSE(rule["fullDescription"]["text"].get<std::string>().empty()) << id;
    EXPECT_TRUE(rule["defaultConfiguration"]["level"] == "error" ||
                rule["defaultConfiguration"]["level"] == "warning" || rule["defaultConfiguration"]["level"] == "note")
        << id;
  }
  EXPECT_EQ(rule_ids.size(), rules.size()) << "one rule per id";
  for (const nlohmann::json& result : results) {
    const size_t index = result["ruleIndex"];
    ASSERT_LT(index, rules.size());
    EXPECT_EQ(rules[index]["id"], result["ruleId"]);
    EXPECT_EQ(result["locations"][0]["physicalLocation"]["region"]["startLine"], 1);
  }
}

}  // namespace
