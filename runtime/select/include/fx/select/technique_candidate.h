// fx::TechniqueCandidate: what selection needs to know about one technique of an effect
// (name, validity with reasons, typed annotations, device requirements), independent of
// the effect model that produces it. D3DX-style validate / find_next_valid live here.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "fx/select/annotation_value.h"
#include "fx/select/caps_requirement.h"
#include "fx/select/device_caps.h"
#include "fx/source_location.h"

namespace fx {

// A technique's annotations: a handful of entries, looked up case-insensitively by name,
// kept in declaration order (later duplicates shadow nothing: the first one wins).
class AnnotationMap {
 public:
  AnnotationMap() = default;
  AnnotationMap(std::initializer_list<std::pair<std::string, AnnotationValue>> entries);

  // Adds an entry (kept even when the name exists; lookups return the first).
  void set(std::string name, AnnotationValue value);
  // The value, or nullptr when absent.
  const AnnotationValue* find(std::string_view name) const;
  // A float or int annotation as float; nullopt when absent or of another type.
  std::optional<float> number(std::string_view name) const;
  // An int (or integral float) annotation; nullopt when absent or of another type.
  std::optional<int32_t> integer(std::string_view name) const;
  // A string annotation; nullopt when absent or of another type.
  std::optional<std::string_view> string(std::string_view name) const;
  std::span<const std::pair<std::string, AnnotationValue>> entries() const { return entries_; }
  bool empty() const { return entries_.empty(); }

 private:
  std::vector<std::pair<std::string, AnnotationValue>> entries_;
};

// One technique as selection sees it.
struct TechniqueCandidate {
  std::string name;
  bool valid = true;                          // false: never chosen, reasons say why
  std::vector<std::string> reasons;           // "ps_2_0 not supported on dx7"
  AnnotationMap annotations;                  // vocabulary: docs/selection.md
  std::vector<CapsRequirement> requirements;  // in addition to a `string Requires` annotation
  SourceRange range;                          // the technique's declaration, for diagnostics
};

// D3DX ValidateTechnique: checks requirements (the list and the `Requires` annotation)
// against caps, appends a reason per unmet one and clears `valid` if any. Returns `valid`.
bool validate(TechniqueCandidate& candidate, const DeviceCaps& caps);
// Validates every candidate; returns how many are valid.
size_t validate(std::span<TechniqueCandidate> candidates, const DeviceCaps& caps);

// D3DX FindNextValidTechnique: the first valid candidate after `after` (from the start
// when nullopt), in declaration order.
std::optional<size_t> find_next_valid(std::span<const TechniqueCandidate> candidates,
                                      std::optional<size_t> after = std::nullopt);

}  // namespace fx
