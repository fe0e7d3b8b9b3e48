// Semantic checks on a parsed effect that need no GPU and no shader compiler: state names,
// values and indices against the state table, duplicate definitions, references to
// undefined parameters and functions, annotation value types, and effect-profile rules.
// Every finding is a Diagnostic (ids listed in docs/diagnostics.md).
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

#include "fx/ast.h"
#include "fx/diagnostic.h"
#include "fx/source_manager.h"

namespace fx {

// The effect dialect: D3DX9 (fx_2_0), FX10 (fx_4_0), FX11 (fx_5_0), or inferred.
enum class EffectProfile : uint8_t { automatic, fx_2_0, fx_4_0, fx_4_1, fx_5_0 };
std::string_view to_string(EffectProfile profile);
// Parses "fx_2_0", "fx.2.0", "fx_4_0", "fx_4_1", "fx_5_0" (case-insensitive).
std::optional<EffectProfile> parse_effect_profile(std::string_view text);

struct CheckOptions {
  // `automatic` infers the profile from the effect (see infer_profile).
  EffectProfile profile = EffectProfile::automatic;
  // An effect with no technique is an error unless it is a library (an .fxh include).
  bool require_technique = true;
};

// The profile an effect's contents need: its `fx.N.0` header if any, else fx_5_0 when it
// uses technique11, fxgroup or D3D11 pass calls, fx_4_0 when it uses technique10, state
// objects, cbuffers or D3D10 pass calls, fx_2_0 otherwise.
EffectProfile infer_profile(const ast::Effect& effect);

// Runs every check and reports findings into `diags`. Never throws; the effect may be a
// partial tree from a parse that reported errors.
void check_effect(const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& diags,
                  const CheckOptions& options = {});

}  // namespace fx
