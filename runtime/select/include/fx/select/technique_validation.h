// Technique validation against device caps, from an effect's real passes: shader profiles
// (HLSL, shader model 1 assembly, GLSL), fixed-function and caps-dependent states, texture
// stages, texture formats, compiled programs within the device limits, compile success and
// the technique's own `Requires` annotation. Every rejection is a located fx::Diagnostic.
//
// Results carry annotations in selection's vocabulary (technique_candidate.h); the model
// types are only forward-declared here so callers need not include the model.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/select/annotation_value.h"
#include "fx/select/device_caps.h"
#include "fx/source_manager.h"

namespace fx {

struct EffectFile;
struct EffectModel;
struct TechniqueInfo;
class EffectPrograms;
class ShaderCompiler;
namespace ast {
struct Effect;
}

// A technique annotation as selection reads it.
using TechniqueAnnotation = std::pair<std::string, AnnotationValue>;

// One technique validated on one device.
struct TechniqueValidation {
  std::string name;
  SourceRange range;  // the technique's declaration
  bool valid = true;
  // Why not, one per cause, each with the range that caused it; severity note, ids in
  // docs/diagnostics.md ("Technique validation"). Empty when valid.
  std::vector<Diagnostic> reasons;
  std::vector<TechniqueAnnotation> annotations;  // literal annotations, in declaration order
  // How a Vulkan device runs what it has no native form of, one line per kind
  // ("emulated: vs.1.1 assembly translated to HLSL"). Empty on historic caps profiles.
  std::vector<std::string> emulation;
};

// What validation may use besides the model.
struct TechniqueValidationOptions {
  // When set, every pass with HLSL or GLSL stages is compiled (lazily, memoised by the
  // programs object) and checked for compile errors and against the device limits.
  EffectPrograms* programs = nullptr;
};

// D3DX ValidateTechnique: one technique of `model` on `caps`.
TechniqueValidation validate_technique(const EffectModel& model, const TechniqueInfo& technique, const DeviceCaps& caps,
                                       const TechniqueValidationOptions& options = {});
// Every technique of `model`, in declaration order.
std::vector<TechniqueValidation> validate_techniques(const EffectModel& model, const DeviceCaps& caps,
                                                     const TechniqueValidationOptions& options = {});

// Every technique of `effect`, the one-call path for tools: its model is built first when
// it was not (its diagnostics go to `diags`); with `compile`, passes are compiled through
// its programs, built first when they were not (with `compiler`, or a default one when
// null; the units' diagnostics repeat the model's and are not reported).
std::vector<TechniqueValidation> validate_effect(EffectFile& effect, const DeviceCaps& caps, DiagnosticSink& diags,
                                                 bool compile = true, const ShaderCompiler* compiler = nullptr);

// D3DX FindNextValidTechnique: the first valid technique after `after` (from the start when
// nullopt), in declaration order.
std::optional<size_t> find_next_valid(std::span<const TechniqueValidation> techniques,
                                      std::optional<size_t> after = std::nullopt);

// "file.fx:12: message": a reason with its presumed file and line, for one-line reports.
std::string located_reason(const Diagnostic& reason, const SourceManager& sm);

}  // namespace fx
