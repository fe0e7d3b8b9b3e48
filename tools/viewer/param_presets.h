// Parameter presets: the values of an effect's numeric parameters as JSON
// ({"effect": "lit.fx", "params": {"Tint": [1, 0.5, 0.2, 1], "Count": [3]}}), for
// --save-params and --load-params.
#pragma once
#include <fxkit/fxkit.h>

#include <string>

// Writes every settable numeric parameter's current value; false with `error` on failure.
bool save_params(const fxkit::Effect& effect, const std::string& path, std::string& error);
// Sets every parameter the file names that the effect has (others are listed in `error`
// as a warning, the call still succeeds); false when the file cannot be read or parsed.
bool load_params(fxkit::Effect& effect, const std::string& path, std::string& error);
