#include "fx/diagnostic.h"

#include <algorithm>

#include "fx/ascii_case.h"

namespace fx {

const char* to_string(Severity s) {
  switch (s) {
    case Severity::note: return "note";
    case Severity::warning: return "warning";
    case Severity::error: return "error";
    case Severity::fatal: return "fatal error";
  }
  return "error";
}

Diagnostic& DiagnosticSink::report(Severity severity, std::string id, SourceRange range, std::string message) {
  if (severity == Severity::warning && werror_) severity = Severity::error;
  if (severity >= Severity::error) {
    if (error_limit_reached()) {
      ++errors_;
      overflow_ = {};
      return overflow_;
    }
    ++errors_;
  } else if (severity == Severity::warning) {
    ++warnings_;
  }
  diagnostics_.push_back({std::move(id), severity, range, std::move(message), {}, {}});
  return diagnostics_.back();
}

void DiagnosticSink::clear() {
  diagnostics_.clear();
  errors_ = warnings_ = 0;
}

namespace {
// Optimal string alignment distance (Damerau-Levenshtein without editing a substring
// twice), ASCII case-insensitive: insertions, deletions, substitutions and swaps of two
// neighbours count one edit each, so "Clmap" is one edit from "Clamp", as "Clmp" is.
size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  auto same = [](char x, char y) { return ascii_lower(x) == ascii_lower(y); };
  for (size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
        row[j] = std::min(row[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, row);
  }
  return previous[b.size()];
}
}  // namespace

std::string closest_match(std::string_view word, const std::vector<std::string_view>& candidates) {
  size_t best = std::max<size_t>(1, word.size() / 3) + 1;
  std::string_view found;
  for (std::string_view c : candidates) {
    size_t d = edit_distance(word, c);
    if (d < best) best = d, found = c;
  }
  return std::string(found);
}

}  // namespace fx
