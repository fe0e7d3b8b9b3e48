// Table generators addressed by name, for texture annotations such as
// `< string Generator = "strand"; int Width = 256; float Exponent = 32; >`
// (effects/strand_aniso.fx).
// The vocabulary (generator names and their parameters) is documented in
// docs/shading-math.md. Errors are values; nothing here throws or aborts.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/shading/table.h"

namespace fx::shading {

// Name -> number or string, as read from annotations. Names compare case-insensitively
// (annotation authors write Width, width and WIDTH).
class GeneratorParams {
 public:
  using Value = std::variant<double, std::string>;
  // Sets (or replaces) a parameter.
  GeneratorParams& set(std::string_view name, double value);
  GeneratorParams& set(std::string_view name, std::string_view value);
  // The value, if present.
  const Value* find(std::string_view name) const;
  // All parameters (names lower-cased), for validation.
  const std::map<std::string, Value, std::less<>>& entries() const { return values_; }

 private:
  std::map<std::string, Value, std::less<>> values_;
};

// A baked table or an error: `id` is a stable diagnostic id ("unknown-generator",
// "bad-generator-parameter"), `message` says what and why.
struct BakeResult {
  std::optional<Table> table;
  std::string error_id;
  std::string message;
  bool ok() const { return table.has_value(); }
};

// Bakes the named generator. Parameters not in the generator's vocabulary are ignored
// (annotations carry UI names and the like) unless they are a near-miss of a known name,
// which is an error with a did-you-mean.
BakeResult bake(std::string_view generator, const GeneratorParams& params);

// As bake(), reporting a failure as a diagnostic at `where` (the annotation's range).
std::optional<Table> bake(std::string_view generator, const GeneratorParams& params, DiagnosticSink& sink,
                          SourceRange where);

// The generator names bake() knows.
std::vector<std::string_view> generator_names();

}  // namespace fx::shading
