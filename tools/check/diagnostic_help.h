// The help text of every diagnostic id, read from docs/diagnostics.md (compiled into the
// binary): each table row `| `id` | severity | meaning | example |` becomes one entry, so
// the document and the tool never disagree.
#pragma once
#include <map>
#include <string>

namespace fx::tools {

struct DiagnosticHelp {
  std::string severity;  // as the table says: "error", "warning", "error / warning"
  std::string meaning;   // the "reported when" column, Markdown
  std::string example;   // Markdown; may be empty
};

// Every documented id.
const std::map<std::string, DiagnosticHelp>& diagnostic_help();

// Markdown reduced to plain text: backticks dropped, `\|` unescaped.
std::string plain_text(const std::string& markdown);

}  // namespace fx::tools
