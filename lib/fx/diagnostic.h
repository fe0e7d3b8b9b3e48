// Diagnostics are values: a stable id, a severity, a primary range, notes and fix-its.
// Library code reports them into a DiagnosticSink; it never prints or aborts.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fx/source_location.h"

namespace fx {

enum class Severity { note, warning, error, fatal };
const char* to_string(Severity s);

// A suggested edit: replace `range` with `replacement` (an insertion when range is empty).
struct FixIt {
  SourceRange range;
  std::string replacement;
};

// An extra location attached to a diagnostic ("previous definition is here").
struct DiagnosticNote {
  SourceLocation location;
  std::string message;
};

struct Diagnostic {
  std::string id;  // stable, kebab-case, e.g. "unknown-state"; documented in docs/diagnostics.md
  Severity severity = Severity::error;
  SourceRange range;
  std::string message;
  std::vector<DiagnosticNote> notes;
  std::vector<FixIt> fixits;
};

// Collects diagnostics in the order they are reported.
class DiagnosticSink {
 public:
  Diagnostic& report(Severity severity, std::string id, SourceRange range, std::string message);
  Diagnostic& error(std::string id, SourceRange range, std::string message) {
    return report(Severity::error, std::move(id), range, std::move(message));
  }
  Diagnostic& warning(std::string id, SourceRange range, std::string message) {
    return report(Severity::warning, std::move(id), range, std::move(message));
  }

  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  size_t error_count() const { return errors_; }
  size_t warning_count() const { return warnings_; }
  bool has_errors() const { return errors_ != 0; }
  // Turns warnings into errors from now on (`--werror`).
  void set_warnings_as_errors(bool on) { werror_ = on; }
  // Stops recording after this many errors (the rest are counted, not stored).
  void set_error_limit(size_t limit) { error_limit_ = limit; }
  bool error_limit_reached() const { return error_limit_ && errors_ >= error_limit_; }
  void clear();

 private:
  std::vector<Diagnostic> diagnostics_;
  Diagnostic overflow_;  // returned once the error limit is reached
  size_t errors_ = 0, warnings_ = 0, error_limit_ = 0;
  bool werror_ = false;
};

// Closest candidate by edit distance (case-insensitive; a swap of two neighbouring letters
// is one edit, as an insertion, deletion or substitution is), or "" if none is close enough.
std::string closest_match(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace fx
