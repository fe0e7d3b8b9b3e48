#include "effect_summary.h"

namespace fx::tools {
namespace {

nlohmann::json annotations(const fx::ast::List<fx::ast::Annotation>& list) {
  nlohmann::json out = nlohmann::json::array();
  for (const fx::ast::Annotation& a : list)
    out.push_back({{"name", a.name}, {"type", a.type.name}, {"value", annotation_value(a.value)}});
  return out;
}

nlohmann::json technique(const fx::ast::Technique& t, const fx::SourceManager& sm) {
  nlohmann::json passes = nlohmann::json::array();
  for (const fx::ast::Pass& p : t.passes)
    passes.push_back({{"name", p.name},
                      {"states", p.states.size()},
                      {"annotations", annotations(p.annotations)},
                      {"location", source_location(sm, p.range)}});
  std::string keyword = t.version == 9 ? "technique" : "technique" + std::to_string(t.version);
  return {{"name", t.name},
          {"keyword", keyword},
          {"annotations", annotations(t.annotations)},
          {"passes", std::move(passes)},
          {"location", source_location(sm, t.range)}};
}

}  // namespace

nlohmann::json source_location(const fx::SourceManager& sm, fx::SourceRange range) {
  const fx::PresumedLocation p = range.valid() ? sm.presumed(range.begin) : fx::PresumedLocation{};
  if (!p.valid()) return nullptr;
  return {{"file", std::string(p.file)}, {"line", p.line}, {"column", p.column}};
}

nlohmann::json annotation_value(const fx::ast::Expr* e) {
  if (!e) return nullptr;
  switch (e->kind) {
    case fx::ast::ExprKind::int_literal:
    case fx::ast::ExprKind::float_literal: return e->number;
    case fx::ast::ExprKind::bool_literal: return e->number != 0;
    case fx::ast::ExprKind::string_literal: return std::string(e->text);
    case fx::ast::ExprKind::unary: {  // `float UIMin = -1;`
      const nlohmann::json operand = e->args.size() == 1 ? annotation_value(e->args[0]) : nullptr;
      if (e->text == "-" && operand.is_number()) return -operand.get<double>();
      return nullptr;
    }
    default: return nullptr;
  }
}

nlohmann::json summarize_effect(const fx::ast::Effect& effect, const fx::SourceManager& sm) {
  nlohmann::json parameters = nlohmann::json::array(), techniques = nlohmann::json::array();
  size_t functions = 0, state_objects = 0;
  for (const fx::ast::Decl& d : effect.decls) {
    switch (d.kind) {
      case fx::ast::DeclKind::variable: {
        const fx::ast::Variable& v = *d.variable;
        parameters.push_back({{"name", v.name},
                              {"type", v.type.name},
                              {"semantic", v.semantic},
                              {"annotations", annotations(v.annotations)},
                              {"location", source_location(sm, v.name_range)}});
        break;
      }
      case fx::ast::DeclKind::technique: techniques.push_back(technique(*d.technique, sm)); break;
      case fx::ast::DeclKind::group:
        for (const fx::ast::Technique& t : d.group->techniques) techniques.push_back(technique(t, sm));
        break;
      case fx::ast::DeclKind::function: ++functions; break;
      case fx::ast::DeclKind::state_object: ++state_objects; break;
      default: break;
    }
  }
  return {{"parameters", std::move(parameters)},
          {"techniques", std::move(techniques)},
          {"functions", functions},
          {"state_objects", state_objects}};
}

}  // namespace fx::tools
