// `fxkit check --format sarif|junit|json -o FILE`: the reports CI systems and code-scanning
// dashboards read. The SARIF report is validated structurally against SARIF 2.1.0 (OASIS
// standard, https://docs.oasis-open.org/sarif/sarif/v2.1.0/sarif-v2.1.0.html, and its schema
// sarif-schema-2.1.0.json): every object fxkit writes, field by field, with the properties
// the schema allows for it, their types, enumerations and minimums.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "effect_folder.h"
#include "fxkit_cli.h"

namespace {

using fx::testing::run_fxkit;
using nlohmann::json;

// Errors in included files: a state error in a header, a macro-expanded one, a warning.
struct ReportFolder : fx::testing::EffectFolder {
  ReportFolder() : EffectFolder("report") {
    write("inc/states.fxh", "#define BAD_STATE ZEnable = Maybe;\ntechnique T { pass P { BAD_STATE } }\n");
    write("uses states.fx", "#include \"inc/states.fxh\"\n");  // a space: the URI must encode it
    write("clean.fx", "technique T { pass P { ZEnable = TRUE; } }\n");
    write("warns.fx", "technique T { pass P { ZEnable = TRUE; ZEnable = FALSE; } }\n");
  }
};

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The object has only properties SARIF 2.1.0 defines for it ("properties" is always allowed).
void expect_only(const json& object, const std::set<std::string>& allowed, const std::string& what) {
  ASSERT_TRUE(object.is_object()) << what;
  for (const auto& [key, value] : object.items())
    EXPECT_TRUE(allowed.count(key) || key == "properties") << what << " has no property '" << key << "' in SARIF 2.1.0";
}

void expect_message(const json& m, const std::string& what) {  // message: text or id required
  expect_only(m, {"text", "markdown", "id", "arguments"}, what);
  ASSERT_TRUE(m.contains("text") && m["text"].is_string()) << what;
}

void expect_uri(const json& uri, const std::string& what) {  // "format": "uri-reference"
  ASSERT_TRUE(uri.is_string()) << what;
  for (char c : uri.get<std::string>())
    EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || std::string("-._~/:%").find(c) != std::string::npos)
        << what << ": '" << uri << "' is not a URI reference";
}

void expect_physical_location(const json& p, const std::string& what) {
  expect_only(p, {"address", "artifactLocation", "region", "contextRegion"}, what);
  const json& a = p.at("artifactLocation");
  expect_only(a, {"uri", "uriBaseId", "index", "description"}, what + ".artifactLocation");
  expect_uri(a.at("uri"), what);
  if (a.contains("uriBaseId")) {
    EXPECT_TRUE(a["uriBaseId"].is_string());
  }
  if (!p.contains("region")) return;
  const json& r = p["region"];
  expect_only(r,
              {"startLine", "startColumn", "endLine", "endColumn", "charOffset", "charLength", "byteOffset",
               "byteLength", "snippet", "message", "sourceLanguage"},
              what + ".region");
  ASSERT_TRUE(r.at("startLine").is_number_integer());
  EXPECT_GE(r["startLine"].get<int>(), 1) << what;
  for (const char* k : {"startColumn", "endLine", "endColumn"})
    if (r.contains(k)) {
      EXPECT_TRUE(r[k].is_number_integer()) << what << "." << k;
      EXPECT_GE(r[k].get<int>(), 1) << what << "." << k;
    }
  if (r.contains("endLine")) {
    EXPECT_GE(r["endLine"].get<int>(), r["startLine"].get<int>()) << what;
  }
}

TEST(CheckReports, SarifOfAFolderWithErrorsInIncludedFilesIsSarif210) {
  ReportFolder f;
  std::string out = f.path("report.sarif");
  auto r = run_fxkit("check --syntax-only --format sarif -o " + out + " " + f.path(), true);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("checked 3 files"), std::string::npos) << r.err;  // the summary stays on the terminal
  json log = json::parse(read(out), nullptr, false);
  ASSERT_FALSE(log.is_discarded());

  expect_only(log, {"$schema", "version", "runs", "inlineExternalProperties"}, "sarifLog");
  EXPECT_EQ(log["version"], "2.1.0");
  EXPECT_TRUE(log["$schema"].is_string());
  ASSERT_TRUE(log["runs"].is_array());
  ASSERT_EQ(log["runs"].size(), 1u);
  const json& run = log["runs"][0];
  expect_only(run,
              {"tool",
               "invocations",
               "conversion",
               "language",
               "versionControlProvenance",
               "originalUriBaseIds",
               "artifacts",
               "logicalLocations",
               "graphs",
               "results",
               "automationDetails",
               "runAggregates",
               "baselineGuid",
               "redactionTokens",
               "defaultEncoding",
               "defaultSourceLanguage",
               "newlineSequences",
               "columnKind",
               "externalPropertyFileReferences",
               "threadFlowLocations",
               "taxonomies",
               "addresses",
               "translations",
               "policies",
               "webRequests",
               "webResponses",
               "specialLocations"},
              "run");
  const json& driver = run.at("tool").at("driver");
  expect_only(run["tool"], {"driver", "extensions"}, "tool");
  expect_only(driver,
              {"guid",
               "name",
               "organization",
               "product",
               "productSuite",
               "shortDescription",
               "fullDescription",
               "fullName",
               "version",
               "semanticVersion",
               "dottedQuadFileVersion",
               "releaseDateUtc",
               "downloadUri",
               "informationUri",
               "globalMessageStrings",
               "notifications",
               "rules",
               "taxa",
               "locations",
               "language",
               "contents",
               "isComprehensive",
               "localizedDataSemanticVersion",
               "minimumRequiredLocalizedDataSemanticVersion",
               "associatedComponent",
               "translationMetadata",
               "supportedTaxonomies"},
              "driver");
  EXPECT_EQ(driver.at("name"), "fxkit");
  EXPECT_TRUE(run["columnKind"] == "unicodeCodePoints" || run["columnKind"] == "utf16CodeUnits");
  for (const auto& [name, base] : run.at("originalUriBaseIds").items()) {
    expect_only(base, {"uri", "uriBaseId", "index", "description"}, "originalUriBaseIds." + name);
    std::string uri = base.at("uri");
    EXPECT_EQ(uri.rfind("file:///", 0), 0u) << uri;  // absolute, and a folder: ends with '/'
    EXPECT_EQ(uri.back(), '/') << uri;
  }
  for (const json& inv : run.at("invocations")) EXPECT_TRUE(inv.at("executionSuccessful").is_boolean());

  const json& rules = driver.at("rules");
  std::set<std::string> rule_ids;
  for (const json& rule : rules) {
    expect_only(rule,
                {"id", "deprecatedIds", "guid", "deprecatedGuids", "name", "deprecatedNames", "shortDescription",
                 "fullDescription", "messageStrings", "defaultConfiguration", "helpUri", "help", "relationships"},
                "rule");
    ASSERT_TRUE(rule.at("id").is_string());
    EXPECT_TRUE(rule_ids.insert(rule["id"]).second) << "duplicate rule " << rule["id"];
    for (const char* k : {"shortDescription", "fullDescription", "help"})
      if (rule.contains(k)) {
        expect_only(rule[k], {"text", "markdown"}, k);
        EXPECT_TRUE(rule[k].at("text").is_string());
      }
    if (rule.contains("defaultConfiguration")) {
      expect_only(rule["defaultConfiguration"], {"enabled", "level", "rank", "parameters"}, "defaultConfiguration");
      EXPECT_TRUE(
          std::set<std::string>({"none", "note", "warning", "error"}).count(rule["defaultConfiguration"]["level"]));
    }
  }
  // The documented ids carry their help text from docs/diagnostics.md.
  bool state_value_documented = false;
  for (const json& rule : rules)
    if (rule["id"] == "unknown-state-value") state_value_documented = rule.contains("help");
  EXPECT_TRUE(state_value_documented);

  const json& results = run.at("results");
  ASSERT_EQ(results.size(), 2u) << results.dump(2);  // the header's error, the duplicate-state warning
  bool header_error = false;
  for (const json& res : results) {
    expect_only(res,
                {"guid",
                 "correlationGuid",
                 "ruleId",
                 "ruleIndex",
                 "rule",
                 "taxa",
                 "kind",
                 "level",
                 "message",
                 "analysisTarget",
                 "locations",
                 "webRequest",
                 "webResponse",
                 "fingerprints",
                 "partialFingerprints",
                 "codeFlows",
                 "graphs",
                 "graphTraversals",
                 "stacks",
                 "relatedLocations",
                 "suppressions",
                 "baselineState",
                 "rank",
                 "attachments",
                 "workItemUris",
                 "hostedViewerUri",
                 "provenance",
                 "fixes",
                 "occurrenceCount"},
                "result");
    expect_message(res.at("message"), "result.message");
    EXPECT_TRUE(std::set<std::string>({"none", "note", "warning", "error"}).count(res.at("level")));
    ASSERT_TRUE(res.at("ruleIndex").is_number_integer());
    ASSERT_LT(res["ruleIndex"].get<size_t>(), rules.size());
    EXPECT_EQ(rules[res["ruleIndex"].get<size_t>()]["id"], res.at("ruleId"));
    ASSERT_EQ(res.at("locations").size(), 1u);
    expect_only(res["locations"][0],
                {"id", "physicalLocation", "logicalLocations", "message", "annotations", "relationships"}, "location");
    expect_physical_location(res["locations"][0].at("physicalLocation"), "result.location");
    std::set<int> related_ids;
    for (const json& rel : res.value("relatedLocations", json::array())) {
      expect_only(rel, {"id", "physicalLocation", "logicalLocations", "message", "annotations", "relationships"},
                  "relatedLocation");
      ASSERT_TRUE(rel.at("id").is_number_integer());
      EXPECT_TRUE(related_ids.insert(rel["id"].get<int>()).second);
      expect_physical_location(rel.at("physicalLocation"), "relatedLocation");
      expect_message(rel.at("message"), "relatedLocation.message");
    }
    if (res["ruleId"] != "unknown-state-value") continue;
    header_error = true;
    EXPECT_EQ(res["level"], "error");
    const json& where = res["locations"][0]["physicalLocation"];
    std::string uri = where["artifactLocation"]["uri"];
    EXPECT_NE(uri.find("inc/states.fxh"), std::string::npos) << uri;
    EXPECT_EQ(where["region"]["startLine"], 2);  // where the macro is expanded; its definition is a note
    // The macro expansion and the include are related locations, the include naming the
    // includer (whose name has a space, percent-encoded).
    std::string notes = res["relatedLocations"].dump();
    EXPECT_NE(notes.find("uses%20states.fx"), std::string::npos) << notes;
    EXPECT_NE(notes.find("included from"), std::string::npos) << notes;
    EXPECT_NE(notes.find("BAD_STATE"), std::string::npos) << notes;
  }
  EXPECT_TRUE(header_error) << results.dump(2);
}

TEST(CheckReports, JunitHasATestCasePerEffectWithFailures) {
  ReportFolder f;
  auto r = run_fxkit("check --syntax-only --format junit " + f.path(), true);
  EXPECT_EQ(r.status, 1);
  const std::string& xml = r.out;
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites tests=\"3\" failures=\"1\"", 0), 0u)
      << xml;
  size_t cases = 0;
  for (size_t at = xml.find("<testcase "); at != std::string::npos; at = xml.find("<testcase ", at + 1)) ++cases;
  EXPECT_EQ(cases, 3u) << xml;
  size_t failure = xml.find("<failure message=\"1 error\" type=\"fxkit.check\">");
  ASSERT_NE(failure, std::string::npos) << xml;
  EXPECT_NE(xml.find("unknown-state-value", failure), std::string::npos) << xml;  // the diagnostics, escaped
  EXPECT_NE(xml.find("&apos;Maybe&apos;", failure), std::string::npos) << xml;
  EXPECT_NE(xml.find("<system-out>"), std::string::npos) << xml;  // the warning of warns.fx
  EXPECT_NE(xml.find("</testsuites>"), std::string::npos);
}

TEST(CheckReports, JsonToAFileAndTheSummaryOnTheTerminal) {
  ReportFolder f;
  std::string out = f.path("report.json");
  auto r = run_fxkit("check --syntax-only --json -o " + out + " " + f.path(), true);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("checked 3 files in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": 1 clean, 1 warning, 1 error"), std::string::npos) << r.err;
  json j = json::parse(read(out));
  EXPECT_EQ(j["files"], 3);
  EXPECT_EQ(j["clean"], 1);
  EXPECT_EQ(j["errors"], 1);
  EXPECT_EQ(j["warnings"], 1);
  EXPECT_EQ(j["effects"].size(), 3u);
  EXPECT_EQ(run_fxkit("check -o /nonexistent/dir/report.json " + f.path()).status, 2);
}

TEST(CheckReports, NoProgressWhenPiped) {
  ReportFolder f;
  auto r = run_fxkit("check --syntax-only " + f.path(), true);
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("files, "), std::string::npos) << r.err;
}

}  // namespace
