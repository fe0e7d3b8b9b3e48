// Go to definition (language_features.h): the declaration of what is under the cursor.
#include "language_features.h"

namespace fx::tools::lsp {

json definition(const DocumentAnalysis& a, const TextDocument& document, Position at) {
  if (const fx::semantic::Symbol* target = a.symbol_at(at); target && target->name_range.valid())
    return a.location_json(target->name_range);
  const std::string_view word = document.word_at(at);
  if (const MacroDefinition* m = word.empty() ? nullptr : a.macro(word))
    return a.location_json({m->at, m->at.offset(static_cast<uint32_t>(m->name.size()))});
  // `#include "file"`: the file.
  const std::string_view line = document.line(at.line);
  if (line.find("#") != std::string_view::npos && line.find("include") != std::string_view::npos)
    for (const fx::IncludeEdge& e : a.parsed().includes)
      if (a.in_document(e.at) && a.position_of(e.at).line == at.line)
        return {{"uri", path_to_uri(e.included)},
                {"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}}}};
  return nullptr;
}

}  // namespace fx::tools::lsp
