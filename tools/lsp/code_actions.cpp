// Code actions (language_features.h): the fix-its of the diagnostics under the requested
// range as quick fixes (a did-you-mean's replacement, a missing `;`).
#include "language_features.h"

namespace fx::tools::lsp {
namespace {

bool before(const json& p, const json& q) {
  return p["line"] != q["line"] ? p["line"] < q["line"] : p["character"] < q["character"];
}

// Whether two LSP ranges touch (an empty range at the end of the other counts).
bool overlap(const json& r, const json& s) { return !before(r["end"], s["start"]) && !before(s["end"], r["start"]); }

std::string title_of(const fx::FixIt& fix) {
  if (fix.range.begin == fix.range.end) return "Insert '" + fix.replacement + "'";
  return "Change to '" + fix.replacement + "'";
}

}  // namespace

json code_actions(const DocumentAnalysis& a, const TextDocument& document, const json& range) {
  json out = json::array();
  for (const fx::Diagnostic& d : a.diagnostics()) {
    if (d.fixits.empty() || !d.range.begin.valid() || !a.in_document(d.range.begin)) continue;
    json diagnostic = document_diagnostics(a, {d})[0];
    if (!overlap(diagnostic["range"], range)) continue;
    for (const fx::FixIt& fix : d.fixits) {
      if (!a.in_document(fix.range.begin)) continue;
      json edit = {{"range", a.range_json(fix.range)}, {"newText", fix.replacement}};
      out.push_back({{"title", title_of(fix)},
                     {"kind", "quickfix"},
                     {"diagnostics", json::array({diagnostic})},
                     {"isPreferred", d.fixits.size() == 1},
                     {"edit", {{"changes", {{document.uri, json::array({edit})}}}}}});
    }
  }
  return out;
}

}  // namespace fx::tools::lsp
