// What a `fxkit check` run found, and its forms for people and machines: the summary line,
// the JSON document, JUnit XML (a test case per effect) and SARIF 2.1.0 (sarif_report.h).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "effect_check.h"

namespace fx::tools {

struct CheckRun {
  std::vector<EffectCheck> checks;  // in file order
  double seconds = 0;               // wall time of the whole run
  size_t included_only = 0;         // folder files checked through their includers
  size_t from_cache = 0;

  size_t clean() const;
  size_t errors() const;
  size_t warnings() const;
  bool failed() const;
};

// "checked 12 files in 0.84 s: 10 clean, 3 warnings, 2 errors" (and what came from the cache).
std::string summary_line(const CheckRun& run);

// {"diagnostics": [...every file's...], "effects": [...], "files", "clean", "errors",
//  "warnings", "seconds"}: the --json document of one file, extended to many.
nlohmann::json json_report(const CheckRun& run);

// <testsuites><testsuite name="fxkit check"><testcase name=FILE> with a <failure> carrying
// the diagnostics when the effect has errors; warnings go to the case's <system-out>.
std::string junit_report(const CheckRun& run);

// Text escaped for an XML attribute or element.
std::string xml_escaped(const std::string& text);

}  // namespace fx::tools
