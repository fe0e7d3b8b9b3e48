// What the fxkit tools (`fxkit check`, `fxkit bench`, every command) tell their caller: the
// exit-code convention (0: success, 1: errors in the input, 2: usage or I/O error) and JSON
// text for stdout.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace fx::tools {

enum ExitCode { kSuccess = 0, kInputErrors = 1, kUsageError = 2 };

// JSON text for stdout. Effect files are not always valid UTF-8, and messages quote them:
// invalid bytes become U+FFFD instead of an exception. indent < 0: one line.
inline std::string json_text(const nlohmann::json& j, int indent = 2) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace fx::tools
