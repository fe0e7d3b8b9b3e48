// The analysis's diagnostics as the document's LSP diagnostics (language_features.h).
#include <filesystem>

#include "language_features.h"

namespace fx::tools::lsp {
namespace {

int lsp_severity(fx::Severity s) {
  switch (s) {
    case fx::Severity::fatal:
    case fx::Severity::error: return 1;
    case fx::Severity::warning: return 2;
    case fx::Severity::note: return 3;
  }
  return 1;
}

json related(const DocumentPlaces& a, fx::SourceLocation at, const std::string& message) {
  return {{"location", a.location_json({at, at})}, {"message", message}};
}

}  // namespace

json document_diagnostics(const DocumentAnalysis& a) { return document_diagnostics(a, a.diagnostics()); }

json document_diagnostics(const DocumentPlaces& a, const std::vector<fx::Diagnostic>& diagnostics) {
  json out = json::array();
  const fx::SourceManager& sm = a.sources();
  for (const fx::Diagnostic& d : diagnostics) {
    json item = {{"severity", lsp_severity(d.severity)}, {"code", d.id}, {"source", "fxkit"}};
    json info = json::array();
    fx::SourceLocation at = d.range.begin;
    if (!at.valid()) {
      item["range"] = {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}};
      item["message"] = d.message;
    } else if (a.in_document(at)) {
      item["range"] = a.range_json(d.range);
      item["message"] = d.message;
    } else {
      // In an included file: shown on the #include of this document that leads there,
      // with the place itself and each step of the include stack as related information.
      info.push_back(related(a, at, d.message));
      fx::SourceLocation step = sm.file_location(at);
      for (int depth = 0; depth < 256 && step.valid() && !a.in_document(step); ++depth) {
        step = sm.included_from(sm.buffer_of(step));
        if (step.valid()) info.push_back(related(a, step, "included from here"));
      }
      const std::string file = std::filesystem::path(a.file_of(at)).filename().string();
      item["message"] = "in included file " + file + ": " + d.message;
      item["range"] = a.range_json({step.valid() ? step : fx::SourceLocation{}, {}});
      if (!step.valid())
        item["range"] = {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}};
    }
    for (const fx::DiagnosticNote& n : d.notes)
      if (n.location.valid()) info.push_back(related(a, n.location, n.message));
    if (!info.empty()) item["relatedInformation"] = std::move(info);
    out.push_back(std::move(item));
  }
  return out;
}

}  // namespace fx::tools::lsp
