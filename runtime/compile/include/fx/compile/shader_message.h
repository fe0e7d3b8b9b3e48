// glslang's info log parsed into located messages, and their conversion to fx::Diagnostics.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/source_manager.h"

namespace fx {

// One message from glslang's info log. The location is the one glslang reports, i.e. after
// the translation unit's #line directives: the .fx file, line and (when given) column.
struct ShaderMessage {
  Severity severity = Severity::error;
  std::string file;     // empty when glslang gave no location (link errors, summaries)
  uint32_t line = 0;    // 1-based; 0 when unknown
  uint32_t column = 0;  // 1-based; 0 when glslang gave none
  std::string text;     // glslang's message without the "ERROR: file:line:" prefix
  std::string id;       // the diagnostic id; "": chosen from the message (report_messages)
};

// Parses an info log ("ERROR: a.fx:12: 'x' : undeclared identifier", "WARNING: a.fx:3:7: ...",
// "ERROR: Linking fragment stage: ..."). Summary lines ("1 compilation errors") are dropped.
std::vector<ShaderMessage> parse_info_log(std::string_view log);

// Maps a glslang location (file, line, column) to a SourceLocation; invalid when unknown.
using ShaderLocationResolver = std::function<SourceLocation(std::string_view file, uint32_t line, uint32_t column)>;

// A resolver over the buffers of `sm`: the newest buffer named `file`, at the start of
// `line` plus column-1 (the line start when glslang gave no column). `sm` must outlive it.
ShaderLocationResolver resolver_for(const SourceManager& sm);

// Reports messages into `sink` with their own id, or a stable one chosen from the message
// ("shader-compile-error", "shader-compile-warning", "shader-link-error"). Messages the resolver cannot place keep
// their glslang location in the message text ("a.fx:12: ...") so nothing is lost when rendered as <unknown>.
void report_messages(const std::vector<ShaderMessage>& messages, const ShaderLocationResolver& resolve,
                     DiagnosticSink& sink);

}  // namespace fx
