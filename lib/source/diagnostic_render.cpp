#include "fx/diagnostic_render.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>

namespace fx {
namespace {

// "file:line:col: ", or nothing for a diagnostic about no place in a file (as compilers
// print "error: ..." for those).
std::string position(const SourceManager& sm, SourceLocation loc) {
  PresumedLocation p = sm.presumed(loc);
  if (!p.valid()) return {};
  return std::string(p.file) + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": ";
}

void append_source_line(std::string& out, const SourceManager& sm, SourceRange range) {
  SourceLocation begin = sm.file_location(range.begin);
  std::string_view line = sm.line_text(begin);
  PresumedLocation b = sm.physical(begin);
  if (!b.valid()) return;
  out.append(line).push_back('\n');
  size_t col = b.column - 1;
  size_t width = 1;
  if (range.end.valid()) {
    PresumedLocation e = sm.physical(sm.file_location(range.end));
    if (e.valid() && e.line == b.line && e.column > b.column) width = e.column - b.column;
  }
  std::string caret;
  for (size_t i = 0; i < col && i < line.size(); ++i) caret.push_back(line[i] == '\t' ? '\t' : ' ');
  caret.push_back('^');
  if (width > 1) caret.append(std::min(width, line.size() + 1 - std::min(col, line.size())) - 1, '~');
  out.append(caret).push_back('\n');
}

// Where a fix-it edits: the characters it replaces as the user wrote them. Inside a macro
// expansion that is the macro's definition (the invocation is not what to replace); text
// the preprocessor made has no place to edit, so such a fix-it is left out.
std::optional<SourceRange> editable_range(const FixIt& f, const SourceManager& sm) {
  auto written = [&](SourceLocation loc, SourceLocation& out) {
    if (!sm.is_expansion(loc)) return out = loc, !sm.is_scratch(loc);
    return sm.written_in_macro(loc, out) != nullptr;
  };
  SourceLocation begin, end;
  if (!written(f.range.begin, begin)) return std::nullopt;
  if (!f.range.end.valid() || f.range.end == f.range.begin) return SourceRange{begin, begin};
  if (!written(f.range.end, end) || sm.buffer_of(end) != sm.buffer_of(begin) || end.raw < begin.raw)
    return std::nullopt;
  return SourceRange{begin, end};
}

}  // namespace

std::vector<DiagnosticNote> context_notes(SourceLocation loc, const SourceManager& sm) {
  std::vector<DiagnosticNote> notes;
  SourceLocation spelled;
  if (const MacroExpansion* m = sm.written_in_macro(loc, spelled))
    notes.push_back({spelled, "spelled in the definition of macro '" + m->macro_name + "'"});
  // Bounded by the expansion depth the preprocessor allows.
  for (const MacroExpansion* m = sm.expansion_of(loc); m; m = sm.expansion_of(loc)) {
    notes.push_back({m->expansion.begin, "in expansion of macro '" + m->macro_name + "'"});
    loc = m->expansion.begin;
  }
  for (SourceLocation inc = sm.included_from(sm.buffer_of(loc)); inc.valid(); inc = sm.included_from(sm.buffer_of(inc)))
    notes.push_back({inc, "included from here"});
  return notes;
}

std::string render_text(const Diagnostic& d, const SourceManager& sm, const TextRenderOptions& options) {
  std::string out = position(sm, d.range.begin);
  out += to_string(d.severity);
  out += ": " + d.message;
  if (!d.id.empty()) out += " [" + d.id + "]";
  out.push_back('\n');
  if (options.show_source_line && d.range.valid()) append_source_line(out, sm, d.range);
  for (const FixIt& f : d.fixits) {
    const std::optional<SourceRange> range = editable_range(f, sm);
    if (!range) continue;
    bool insertion = !range->end.valid() || range->end == range->begin;
    out += position(sm, range->begin) + "note: fix-it: " + (insertion ? "insert '" : "replace with '") + f.replacement +
           "'\n";
  }
  std::vector<DiagnosticNote> notes = d.notes;
  std::vector<DiagnosticNote> context = context_notes(d.range.begin, sm);
  notes.insert(notes.end(), context.begin(), context.end());
  for (const DiagnosticNote& n : notes) out += position(sm, n.location) + "note: " + n.message + "\n";
  return out;
}

std::string render_text(const std::vector<Diagnostic>& ds, const SourceManager& sm, const TextRenderOptions& options) {
  std::string out;
  for (const Diagnostic& d : ds) out += render_text(d, sm, options);
  return out;
}

namespace {
nlohmann::json place(const SourceManager& sm, SourceLocation loc) {
  PresumedLocation p = sm.presumed(loc);
  if (!p.valid()) return {{"file", nullptr}, {"line", 0}, {"column", 0}};
  return {{"file", std::string(p.file)}, {"line", p.line}, {"column", p.column}};
}
}  // namespace

nlohmann::json render_json(const Diagnostic& d, const SourceManager& sm) {
  nlohmann::json j = place(sm, d.range.begin);
  nlohmann::json end = place(sm, d.range.end.valid() ? d.range.end : d.range.begin);
  j["end"] = {{"line", end["line"]}, {"column", end["column"]}};
  j["severity"] = to_string(d.severity);
  j["id"] = d.id;
  j["message"] = d.message;
  nlohmann::json notes = nlohmann::json::array();
  std::vector<DiagnosticNote> all = d.notes;
  std::vector<DiagnosticNote> context = context_notes(d.range.begin, sm);
  all.insert(all.end(), context.begin(), context.end());
  for (const DiagnosticNote& n : all) {
    nlohmann::json note = place(sm, n.location);
    note["message"] = n.message;
    notes.push_back(std::move(note));
  }
  j["notes"] = std::move(notes);
  nlohmann::json fixits = nlohmann::json::array();
  for (const FixIt& f : d.fixits) {
    const std::optional<SourceRange> range = editable_range(f, sm);
    if (!range) continue;
    nlohmann::json fix = place(sm, range->begin);
    nlohmann::json fix_end = place(sm, range->end.valid() ? range->end : range->begin);
    fix["end"] = {{"line", fix_end["line"]}, {"column", fix_end["column"]}};
    fix["replacement"] = f.replacement;
    fixits.push_back(std::move(fix));
  }
  j["fixits"] = std::move(fixits);
  return j;
}

nlohmann::json render_json(const std::vector<Diagnostic>& ds, const SourceManager& sm) {
  nlohmann::json a = nlohmann::json::array();
  for (const Diagnostic& d : ds) a.push_back(render_json(d, sm));
  return a;
}

}  // namespace fx
