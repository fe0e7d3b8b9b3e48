// Hover and completion text of symbols (symbol_text.h).
#include "symbol_text.h"

namespace fx::tools::lsp {
namespace {

using fx::semantic::SymbolKind;

// The declaration's text, cut before a function's body and after a dozen lines.
std::string declaration_text(const DocumentAnalysis& a, const fx::semantic::Symbol& s) {
  std::string text(a.text_of(s.range));
  if (s.kind == SymbolKind::function) text = text.substr(0, text.find('{'));
  size_t lines = 0;
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n' && ++lines == 12) {
      text = text.substr(0, i) + "\n...";
      break;
    }
  while (!text.empty() && (text.back() == ' ' || text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text.empty() ? std::string(s.name) : text;
}

}  // namespace

std::string symbol_detail(const fx::semantic::Symbol& s) {
  std::string out;
  if (s.kind != SymbolKind::structure && s.kind != SymbolKind::constant_buffer && s.kind != SymbolKind::glsl_block &&
      s.kind != SymbolKind::type_alias)
    out = s.type.spelling() + " ";
  out += std::string(s.name) + " (" + std::string(fx::semantic::to_string(s.kind));
  if (!s.container.empty()) {
    const bool member = s.kind == SymbolKind::member || s.kind == SymbolKind::cbuffer_member;
    out += (member ? " of " : " in ") + std::string(s.container);
  }
  return out + ")";
}

std::string symbol_markdown(const DocumentAnalysis& a, const fx::semantic::Symbol& s) {
  std::string md = "```hlsl\n" + declaration_text(a, s) + "\n```\n\n" + symbol_detail(s);
  if (const fx::ast::Variable* v = s.variable) {
    md += "\n\n- type: `" + s.type.spelling() + "`";
    if (!v->semantic.empty()) md += "\n- semantic: `" + std::string(v->semantic) + "`";
    if (v->initializer) {
      std::string value(a.text_of(v->initializer->range));
      if (!value.empty() && value.size() < 200) md += "\n- default: `" + value + "`";
    }
    for (const fx::ast::Annotation& an : v->annotations) {
      std::string text(a.text_of(an.range));
      md += "\n- annotation: `" + (text.empty() ? std::string(an.name) : text) + "`";
    }
  }
  return md;
}

}  // namespace fx::tools::lsp
