#include "check_report.h"

#include <cstdio>

namespace fx::tools {

size_t CheckRun::clean() const {
  size_t n = 0;
  for (const EffectCheck& c : checks) n += c.clean() ? 1 : 0;
  return n;
}
size_t CheckRun::errors() const {
  size_t n = 0;
  for (const EffectCheck& c : checks) n += c.errors;
  return n;
}
size_t CheckRun::warnings() const {
  size_t n = 0;
  for (const EffectCheck& c : checks) n += c.warnings;
  return n;
}
bool CheckRun::failed() const {
  for (const EffectCheck& c : checks)
    if (c.failed()) return true;
  return false;
}

std::string summary_line(const CheckRun& run) {
  char line[256];
  std::snprintf(line, sizeof line, "checked %zu file%s in %.2f s: %zu clean, %zu warning%s, %zu error%s",
                run.checks.size(), run.checks.size() == 1 ? "" : "s", run.seconds, run.clean(), run.warnings(),
                run.warnings() == 1 ? "" : "s", run.errors(), run.errors() == 1 ? "" : "s");
  std::string out = line;
  if (run.from_cache) out += " (" + std::to_string(run.from_cache) + " from the cache)";
  return out;
}

nlohmann::json json_report(const CheckRun& run) {
  nlohmann::json diagnostics = nlohmann::json::array(), effects = nlohmann::json::array();
  for (const EffectCheck& c : run.checks) {
    for (const auto& d : c.diagnostics) diagnostics.push_back(d);
    nlohmann::json e = c.effect;
    e["errors"] = c.errors;
    e["warnings"] = c.warnings;
    e["cached"] = c.from_cache;
    effects.push_back(std::move(e));
  }
  return {{"diagnostics", std::move(diagnostics)},
          {"effects", std::move(effects)},
          {"files", run.checks.size()},
          {"clean", run.clean()},
          {"errors", run.errors()},
          {"warnings", run.warnings()},
          {"seconds", run.seconds}};
}

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // XML 1.0 allows no control characters but tab, newline and carriage return.
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') out += "?";
        else out += static_cast<char>(c);
    }
  }
  return out;
}

std::string junit_report(const CheckRun& run) {
  size_t failures = 0;
  for (const EffectCheck& c : run.checks) failures += c.failed() ? 1 : 0;
  char head[256];
  std::snprintf(head, sizeof head, "tests=\"%zu\" failures=\"%zu\" errors=\"0\" time=\"%.3f\"", run.checks.size(),
                failures, run.seconds);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += std::string("<testsuites ") + head + ">\n";
  out += std::string("  <testsuite name=\"fxkit check\" ") + head + ">\n";
  for (const EffectCheck& c : run.checks) {
    char time[32];
    std::snprintf(time, sizeof time, "%.3f", c.ms / 1000);
    out += "    <testcase classname=\"fxkit.check\" name=\"" + xml_escaped(c.file) + "\" file=\"" +
           xml_escaped(c.file) + "\" time=\"" + time + "\"";
    if (c.clean()) {
      out += "/>\n";
      continue;
    }
    out += ">\n";
    if (c.failed()) {
      std::string message = std::to_string(c.errors) + " error" + (c.errors == 1 ? "" : "s");
      if (!c.runnable) message += ", no technique valid on the caps";
      out += "      <failure message=\"" + xml_escaped(message) + "\" type=\"fxkit.check\">" +
             xml_escaped(c.text + c.caps_text) + "</failure>\n";
    } else {
      out += "      <system-out>" + xml_escaped(c.text) + "</system-out>\n";
    }
    out += "    </testcase>\n";
  }
  out += "  </testsuite>\n</testsuites>\n";
  return out;
}

}  // namespace fx::tools
