#include "diagnostic_help.h"

#include <sstream>
#include <vector>

namespace fx::tools {

extern const char* const kDiagnosticsMarkdown;  // docs/diagnostics.md (generated diagnostics_md.cpp)

namespace {

// The cells of a Markdown table row ("| a | b \| c |" -> {"a", "b \| c"}).
std::vector<std::string> table_cells(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  for (size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      cell += "\\|";
      ++i;
    } else if (row[i] == '|') {
      size_t b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
      out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return out;
}

}  // namespace

std::string plain_text(const std::string& markdown) {
  std::string out;
  for (size_t i = 0; i < markdown.size(); ++i) {
    if (markdown[i] == '`') continue;
    if (markdown[i] == '\\' && i + 1 < markdown.size() && markdown[i + 1] == '|') continue;
    out += markdown[i];
  }
  return out;
}

const std::map<std::string, DiagnosticHelp>& diagnostic_help() {
  static const std::map<std::string, DiagnosticHelp> table = [] {
    std::map<std::string, DiagnosticHelp> out;
    std::istringstream doc(kDiagnosticsMarkdown);
    for (std::string line; std::getline(doc, line);) {
      if (line.rfind("| `", 0) != 0) continue;
      std::vector<std::string> c = table_cells(line);
      if (c.size() < 3 || c[0].size() < 3 || c[0].front() != '`' || c[0].back() != '`') continue;
      std::string id = c[0].substr(1, c[0].size() - 2);
      if (id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos) continue;
      out.emplace(id, DiagnosticHelp{c[1], c[2], c.size() > 3 ? c[3] : ""});
    }
    return out;
  }();
  return table;
}

}  // namespace fx::tools
