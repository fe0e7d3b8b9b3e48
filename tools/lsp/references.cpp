// References (language_features.h): every place that names the symbol under the cursor.
#include <set>

#include "language_features.h"

namespace fx::tools::lsp {

json references(const DocumentAnalysis& a, Position at, bool include_declaration) {
  json out = json::array();
  const fx::semantic::Symbol* target = a.symbol_at(at);
  if (!target) return out;
  const std::vector<fx::Token>& tokens = a.parsed().ast.tokens;
  const fx::semantic::SemanticModel& model = a.model();
  std::set<std::pair<std::string, std::string>> seen;  // uri and range, as JSON text
  auto add = [&](fx::SourceRange range) {
    json location = a.location_json(range);
    if (seen.insert({location["uri"].get<std::string>(), location["range"].dump()}).second)
      out.push_back(std::move(location));
  };
  if (include_declaration && target->name_range.valid()) add(target->name_range);
  const bool global = model.global(target->name) == target;
  for (uint32_t i = 0; i < tokens.size(); ++i) {
    const fx::Token& t = tokens[i];
    if (!t.is(fx::TokenKind::identifier) || t.text() != target->name) continue;
    const fx::semantic::Reference* r = model.reference_at(i);
    // In a body, what the model resolved; outside bodies (passes, state blocks, annotations)
    // a global's name.
    const bool names_it = r ? r->symbol == target && !r->declaration : global && !model.function_at(i);
    if (names_it && (!target->name_range.valid() || t.loc != target->name_range.begin)) add(t.range());
  }
  return out;
}

}  // namespace fx::tools::lsp
