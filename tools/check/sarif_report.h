// A `fxkit check` run as SARIF 2.1.0 (OASIS Static Analysis Results Interchange Format), the
// form code-scanning dashboards and editors read: one run, fxkit as the tool with a rule
// per diagnostic id it reported (help text from docs/diagnostics.md), a result per
// diagnostic with its physical location, and the include/macro/repeat notes as related
// locations.
#pragma once
#include <nlohmann/json.hpp>

#include "check_report.h"

namespace fx::tools {

// `base` is the folder relative paths are relative to (the working directory): it becomes
// the run's SRCROOT.
nlohmann::json sarif_report(const CheckRun& run, const std::string& base);

// A path as a URI reference: relative paths stay relative (forward slashes), absolute ones
// become file:// URIs; bytes outside the unreserved set are percent-encoded.
std::string path_uri(const std::string& path);

}  // namespace fx::tools
