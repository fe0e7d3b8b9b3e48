// The document's outline (language_features.h): LSP DocumentSymbols for the declarations written in
// the document itself (not its includes).
#include "language_features.h"
#include "symbol_text.h"

namespace fx::tools::lsp {
namespace {

// LSP SymbolKind numbers.
enum Kind {
  kModule = 2,
  kNamespace = 3,
  kPackage = 4,
  kClass = 5,
  kMethod = 6,
  kField = 8,
  kFunction = 12,
  kVariable = 13,
  kObject = 19,
  kStruct = 23,
  kTypeParameter = 26
};

json symbol(const DocumentAnalysis& a, std::string_view name, std::string_view fallback, int kind,
            fx::SourceRange range, fx::SourceRange name_range, std::string detail = {}) {
  if (!name_range.valid()) name_range = {range.begin, range.begin};
  json s = {{"name", name.empty() ? std::string(fallback) : std::string(name)},
            {"kind", kind},
            {"range", a.range_json(range)},
            {"selectionRange", a.range_json(name_range)}};
  // The selection must lie inside the range; a name from a macro may not.
  if (a.position_of(name_range.begin).line < a.position_of(range.begin).line) s["selectionRange"] = s["range"];
  if (!detail.empty()) s["detail"] = std::move(detail);
  s["children"] = json::array();
  return s;
}

json variable(const DocumentAnalysis& a, const fx::ast::Variable& v, int kind) {
  std::string type(v.type.name);
  return symbol(a, v.name, "(unnamed)", kind, v.range, v.name_range, type);
}

json technique(const DocumentAnalysis& a, const fx::ast::Technique& t) {
  json out = symbol(a, t.name, "(unnamed technique)", kModule, t.range, t.name_range,
                    "technique" + (t.version == 9 ? std::string() : std::to_string(t.version)));
  for (const fx::ast::Pass& p : t.passes)
    out["children"].push_back(symbol(a, p.name, "(unnamed pass)", kMethod, p.range, p.name_range, "pass"));
  return out;
}

json structure(const DocumentAnalysis& a, const fx::ast::Struct& s) {
  json out = symbol(a, s.name, "(anonymous struct)", kStruct, s.range, s.name_range);
  for (const fx::ast::Variable& m : s.members) out["children"].push_back(variable(a, m, kField));
  for (const fx::ast::Function& f : s.methods)
    out["children"].push_back(symbol(a, f.name, "(method)", kMethod, f.range, f.name_range));
  return out;
}

}  // namespace

json document_symbols(const DocumentAnalysis& a) {
  json out = json::array();
  for (const fx::ast::Decl& d : a.parsed().ast.decls) {
    switch (d.kind) {
      case fx::ast::DeclKind::variable:
        if (a.in_document(d.variable->range.begin)) out.push_back(variable(a, *d.variable, kVariable));
        break;
      case fx::ast::DeclKind::function:
        if (a.in_document(d.function->range.begin)) {
          const fx::semantic::Symbol* s = a.model().global(d.function->name);
          out.push_back(symbol(a, d.function->name, "(function)", kFunction, d.function->range, d.function->name_range,
                               s ? s->type.spelling() : std::string()));
        }
        break;
      case fx::ast::DeclKind::structure:
        if (a.in_document(d.structure->range.begin)) out.push_back(structure(a, *d.structure));
        break;
      case fx::ast::DeclKind::type_alias:
        if (a.in_document(d.type_alias->range.begin))
          out.push_back(symbol(a, d.type_alias->name, "(typedef)", kTypeParameter, d.type_alias->range, {}));
        break;
      case fx::ast::DeclKind::technique:
        if (a.in_document(d.technique->range.begin)) out.push_back(technique(a, *d.technique));
        break;
      case fx::ast::DeclKind::group:
        if (a.in_document(d.group->range.begin)) {
          json g = symbol(a, d.group->name, "(fxgroup)", kPackage, d.group->range, d.group->name_range, "fxgroup");
          for (const fx::ast::Technique& t : d.group->techniques) g["children"].push_back(technique(a, t));
          out.push_back(std::move(g));
        }
        break;
      case fx::ast::DeclKind::state_object:
        if (a.in_document(d.state_object->range.begin))
          out.push_back(symbol(a, d.state_object->name, "(state)", kObject, d.state_object->range,
                               d.state_object->name_range, std::string(d.state_object->kind)));
        break;
      case fx::ast::DeclKind::constant_buffer:
        if (a.in_document(d.constant_buffer->range.begin)) {
          const fx::ast::ConstantBuffer& c = *d.constant_buffer;
          json cb = symbol(a, c.name, "(cbuffer)", kNamespace, c.range, c.name_range,
                           c.texture_buffer ? "tbuffer" : "cbuffer");
          for (const fx::ast::Variable& m : c.members) cb["children"].push_back(variable(a, m, kField));
          out.push_back(std::move(cb));
        }
        break;
      case fx::ast::DeclKind::glsl_block:
        if (a.in_document(d.glsl_block->range.begin))
          out.push_back(symbol(a, d.glsl_block->name, "(GLSL block)", kClass, d.glsl_block->range,
                               d.glsl_block->name_range, "GLSL block"));
        break;
      default: break;
    }
  }
  return out;
}

}  // namespace fx::tools::lsp
