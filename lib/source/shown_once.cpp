#include "fx/shown_once.h"

#include <algorithm>

namespace fx {

void ShownOnce::add(const std::vector<Diagnostic>& diagnostics, const std::string& where) {
  for (const Diagnostic& d : diagnostics) {
    auto same = std::find_if(shown_.begin(), shown_.end(), [&](const Shown& s) {
      return s.diagnostic.id == d.id && s.diagnostic.severity == d.severity &&
             s.diagnostic.range.begin == d.range.begin && s.diagnostic.message == d.message;
    });
    if (same == shown_.end()) shown_.push_back({d, {}});
    else if (!where.empty()) same->also.push_back(where);
  }
}

std::vector<Diagnostic> ShownOnce::diagnostics() const {
  std::vector<Diagnostic> out;
  for (const Shown& s : shown_) {
    out.push_back(s.diagnostic);
    if (s.also.empty()) continue;
    std::string list;
    for (const std::string& w : s.also) list += (list.empty() ? "" : ", ") + w;
    out.back().notes.push_back({s.diagnostic.range.begin, "also reported for " + list});
  }
  return out;
}

}  // namespace fx
