#include "sarif_report.h"

#include <cctype>
#include <map>

#include "diagnostic_help.h"

namespace fx::tools {
namespace {

// SARIF's levels: error, warning, note (our notes are never results of their own).
std::string sarif_level(const nlohmann::json& severity) {
  std::string s = severity.is_string() ? severity.get<std::string>() : "";
  return s == "error" || s == "fatal" ? "error" : s == "warning" ? "warning" : "note";
}

// A physicalLocation, or null for a diagnostic with no place.
nlohmann::json physical_location(const nlohmann::json& place) {
  if (!place.contains("file") || !place["file"].is_string() || place.value("line", 0) <= 0) return nullptr;
  const std::string file = place["file"].get<std::string>();
  nlohmann::json artifact = {{"uri", path_uri(file)}};
  if (!file.empty() && file[0] != '/') artifact["uriBaseId"] = "SRCROOT";
  nlohmann::json region = {{"startLine", place["line"]}};
  if (place.value("column", 0) > 0) region["startColumn"] = place["column"];
  if (place.contains("end") && place["end"].value("line", 0) > 0) {
    const auto& end = place["end"];
    bool empty = end["line"] == place["line"] && end["column"] == place["column"];
    if (!empty) {
      region["endLine"] = end["line"];
      if (end.value("column", 0) > 0) region["endColumn"] = end["column"];
    }
  }
  return {{"artifactLocation", std::move(artifact)}, {"region", std::move(region)}};
}

nlohmann::json sarif_rule(const std::string& id) {
  nlohmann::json r = {{"id", id}, {"name", id}};
  auto it = diagnostic_help().find(id);
  if (it == diagnostic_help().end()) {
    r["shortDescription"] = {{"text", id}};
    return r;
  }
  const DiagnosticHelp& h = it->second;
  std::string text = plain_text(h.meaning);
  r["shortDescription"] = {{"text", text}};
  r["fullDescription"] = {{"text", text}};
  std::string help = text, markdown = h.meaning;
  if (!h.example.empty()) {
    help += ". Example: " + plain_text(h.example);
    markdown += ". Example: " + h.example;
  }
  r["help"] = {{"text", help}, {"markdown", markdown}};
  const std::string first = h.severity.substr(0, h.severity.find(' '));
  r["defaultConfiguration"] = {{"level", sarif_level(first)}};
  return r;
}

}  // namespace

std::string path_uri(const std::string& path) {
  std::string out = !path.empty() && path[0] == '/' ? "file://" : "";
  static const char* kHex = "0123456789ABCDEF";
  for (unsigned char c : path) {
    char ch = c == '\\' ? '/' : static_cast<char>(c);
    if (std::isalnum(c) || std::string_view("-._~/").find(ch) != std::string_view::npos) {
      out += ch;
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

nlohmann::json sarif_report(const CheckRun& run, const std::string& base) {
  std::map<std::string, size_t> rule_index;
  nlohmann::json rules = nlohmann::json::array(), results = nlohmann::json::array();
  for (const EffectCheck& c : run.checks) {
    for (const auto& d : c.diagnostics) {
      const std::string id = d.value("id", "fxkit");
      auto [it, added] = rule_index.emplace(id, rules.size());
      if (added) rules.push_back(sarif_rule(id));
      nlohmann::json result = {{"ruleId", id},
                               {"ruleIndex", it->second},
                               {"level", sarif_level(d["severity"])},
                               {"message", {{"text", d.value("message", "")}}}};
      nlohmann::json where = physical_location(d);
      // A diagnostic without a place (a file that cannot be read) is the effect's.
      if (where.is_null()) where = {{"artifactLocation", {{"uri", path_uri(c.file)}}}};
      result["locations"] = nlohmann::json::array({{{"physicalLocation", std::move(where)}}});
      nlohmann::json related = nlohmann::json::array();
      for (const auto& note : d.value("notes", nlohmann::json::array())) {
        nlohmann::json loc = physical_location(note);
        if (loc.is_null()) continue;
        related.push_back({{"id", related.size() + 1},
                           {"physicalLocation", std::move(loc)},
                           {"message", {{"text", note.value("message", "")}}}});
      }
      if (!related.empty()) result["relatedLocations"] = std::move(related);
      results.push_back(std::move(result));
    }
  }
  std::string root = path_uri(base);
  if (root.empty() || root.back() != '/') root += '/';
  nlohmann::json driver = {{"name", "fxkit"}, {"rules", std::move(rules)}};
  nlohmann::json sarif_run = {{"tool", {{"driver", std::move(driver)}}},
                              {"originalUriBaseIds", {{"SRCROOT", {{"uri", root}}}}},
                              {"invocations", nlohmann::json::array({{{"executionSuccessful", true}}})},
                              {"columnKind", "unicodeCodePoints"},
                              {"results", std::move(results)}};
  return {{"$schema", "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"},
          {"version", "2.1.0"},
          {"runs", nlohmann::json::array({std::move(sarif_run)})}};
}

}  // namespace fx::tools
