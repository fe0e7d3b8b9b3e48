// fxkit::Message: one located diagnostic, as compilers print them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace fxkit {

enum class Severity : uint8_t { error, warning, note };

struct Message {
  Severity severity = Severity::error;
  std::string code{};             // stable id, e.g. "unknown-state" (docs/diagnostics.md)
  std::string file{};             // "" when the message is not about a file
  uint32_t line = 0, column = 0;  // 1-based; 0 when unknown
  std::string text{};             // the message alone
  // "file:line:col: error: text [code]", the source line with a caret under the place, then
  // the notes (include stack, "also reported for" the other passes of a shared function),
  // exactly as `fxkit check` prints it and an editor's problem matcher reads it (ends with
  // a newline).
  std::string rendered{};
};

// Whether any of `messages` is an error.
bool has_errors(const std::vector<Message>& messages);

}  // namespace fxkit
