// The `--caps` option of `fxkit check` and `fxkit select`: a shipped profile name, a JSON
// file (saved DeviceCaps or a `vulkaninfo --json` report) or `device` (the Vulkan device
// the loader offers first, queried live).
#pragma once
#include <optional>
#include <string>

#include "fx/diagnostic.h"
#include "fx/select/device_caps.h"

namespace fx::tools {

// Help text listing the accepted values.
std::string caps_option_help();
// Resolves a --caps value; problems are reported into `sink` (ids from the caps sources,
// or "caps-file" when a file cannot be read) and give nullopt.
std::optional<fx::DeviceCaps> load_caps_option(const std::string& value, fx::DiagnosticSink& sink);

}  // namespace fx::tools
