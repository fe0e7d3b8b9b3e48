// Hover (language_features.h): what the identifier under the cursor is.
#include "language_features.h"
#include "state_context.h"
#include "symbol_text.h"

namespace fx::tools::lsp {
namespace {

json markdown(std::string text, const DocumentAnalysis& a, fx::SourceRange range) {
  json out = {{"contents", {{"kind", "markdown"}, {"value", std::move(text)}}}};
  if (range.valid()) out["range"] = a.range_json(range);
  return out;
}

std::string values_of(const fx::StateInfo& row) {
  std::string out;
  for (std::string_view v : fx::enum_names(row)) out += (out.empty() ? "" : ", ") + std::string(v);
  return out;
}

std::string describe_state(const fx::StateInfo& row) {
  std::string md = "**" + std::string(row.name) + "**: " + std::string(fx::to_string(row.block)) + " state (" +
                   std::string(fx::to_string(row.api)) + ")\n\n- value: " + std::string(fx::to_string(row.type));
  if (row.enums) md += "\n- allowed values: " + values_of(row);
  if (row.index_count) md += "\n- indices: 0 to " + std::to_string(row.index_count - 1);
  md += "\n- Vulkan: " + std::string(fx::to_string(row.vulkan));
  if (row.area != fx::VulkanArea::none) md += ", " + std::string(fx::to_string(row.area));
  if (!row.reason.empty()) md += "\n- " + std::string(row.reason);
  return md;
}

}  // namespace

json hover(const DocumentAnalysis& a, const TextDocument& document, Position at) {
  const std::vector<fx::Token>& tokens = a.parsed().ast.tokens;
  const std::optional<uint32_t> token = a.token_at(at);
  if (token && tokens[*token].is(fx::TokenKind::identifier)) {
    const fx::Token& t = tokens[*token];
    const fx::SourceRange range = t.range();
    if (const fx::semantic::Reference* r = a.model().reference_at(*token)) {
      if (r->symbol) return markdown(symbol_markdown(a, *r->symbol), a, range);
      if (r->intrinsic)
        return markdown("```hlsl\n" + std::string(r->intrinsic->signature) + "\n```\n\n" +
                            std::string(r->intrinsic->summary) + " (intrinsic)",
                        a, range);
      if (r->type.known()) return markdown("```hlsl\n" + r->type.spelling() + "\n```\n\nswizzle", a, range);
    }
    // In technique and state code: a state name or value.
    const std::vector<StateBlockSite> sites = state_block_sites(a.parsed().ast);
    for (const StateBlockSite& site : sites)
      for (const fx::ast::StateAssignment& s : *site.states) {
        if (s.name_range.begin == t.loc)
          if (const fx::StateInfo* row = state_row(site, s.name)) return markdown(describe_state(*row), a, range);
        if (s.value && s.value->range.begin.raw <= t.loc.raw && t.loc.raw < s.value->range.end.raw &&
            !a.model().global(t.text()))
          if (const fx::StateInfo* row = state_row(site, s.name); row && row->enums) {
            if (auto value = fx::find_enum(*row, t.text()))
              return markdown("`" + std::string(t.text()) + "` = " + std::to_string(*value) + ", a value of " +
                                  describe_state(*row),
                              a, range);
          }
      }
    if (const fx::semantic::Symbol* s = a.model().global(t.text())) return markdown(symbol_markdown(a, *s), a, range);
  }
  const std::string_view word = document.word_at(at);
  if (const MacroDefinition* m = word.empty() ? nullptr : a.macro(word))
    return markdown("```hlsl\n" + m->line + "\n```\n\nmacro", a, {});
  return nullptr;
}

}  // namespace fx::tools::lsp
