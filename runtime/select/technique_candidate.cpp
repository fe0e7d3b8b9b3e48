// Annotation lookup and D3DX-style validation of technique candidates.
#include "fx/select/technique_candidate.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "fx/ascii_case.h"

namespace fx {
AnnotationMap::AnnotationMap(std::initializer_list<std::pair<std::string, AnnotationValue>> entries)
    : entries_(entries) {}

void AnnotationMap::set(std::string name, AnnotationValue value) {
  entries_.emplace_back(std::move(name), std::move(value));
}

const AnnotationValue* AnnotationMap::find(std::string_view name) const {
  for (const auto& [n, v] : entries_)
    if (iequals(n, name)) return &v;
  return nullptr;
}

std::optional<float> AnnotationMap::number(std::string_view name) const {
  const AnnotationValue* v = find(name);
  if (!v) return std::nullopt;
  if (auto f = std::get_if<float>(v)) return *f;
  if (auto i = std::get_if<int32_t>(v)) return float(*i);
  return std::nullopt;
}

std::optional<int32_t> AnnotationMap::integer(std::string_view name) const {
  const AnnotationValue* v = find(name);
  if (!v) return std::nullopt;
  if (auto i = std::get_if<int32_t>(v)) return *i;
  if (auto f = std::get_if<float>(v); f && std::isfinite(*f) && std::floor(*f) == *f && std::fabs(*f) < 2147483648.f)
    return int32_t(*f);
  return std::nullopt;
}

std::optional<std::string_view> AnnotationMap::string(std::string_view name) const {
  const AnnotationValue* v = find(name);
  if (!v) return std::nullopt;
  if (auto s = std::get_if<std::string>(v)) return std::string_view(*s);
  return std::nullopt;
}

bool validate(TechniqueCandidate& candidate, const DeviceCaps& caps) {
  std::vector<CapsRequirement> reqs = candidate.requirements;
  if (const AnnotationValue* v = candidate.annotations.find("Requires")) {
    if (const auto* list = std::get_if<std::string>(v)) {
      std::vector<std::string> errors;
      for (auto& r : parse_caps_requirements(*list, &errors)) reqs.push_back(std::move(r));
      for (auto& e : errors) {
        candidate.reasons.push_back(std::move(e));
        candidate.valid = false;
      }
    } else {
      candidate.reasons.push_back("annotation Requires must be a string");
      candidate.valid = false;
    }
  }
  for (const auto& r : reqs) {
    if (auto why = unmet_reason(caps, r)) {
      candidate.reasons.push_back(std::move(*why));
      candidate.valid = false;
    }
  }
  return candidate.valid;
}

size_t validate(std::span<TechniqueCandidate> candidates, const DeviceCaps& caps) {
  size_t valid = 0;
  for (auto& c : candidates) valid += validate(c, caps) ? 1 : 0;
  return valid;
}

std::optional<size_t> find_next_valid(std::span<const TechniqueCandidate> candidates, std::optional<size_t> after) {
  if (after && *after >= candidates.size()) return std::nullopt;
  for (size_t i = after ? *after + 1 : 0; i < candidates.size(); ++i)
    if (candidates[i].valid) return i;
  return std::nullopt;
}

}  // namespace fx
