// Effect blocks: annotations, techniques, passes, state assignments and fxgroups.
#include <utility>

#include "fx/state_table.h"
#include "parse_internal.h"

namespace fx::detail {

bool Parser::parse_annotations(ast::List<ast::Annotation>& out) {
  Token open = tok();
  advance();  // <
  // Lists of a few entries are the rule; one allocation instead of growing 1, 2, 4.
  out.reserve(arena_, out.size() + 4);
  for (;;) {
    switch (tok().kind) {
      case TokenKind::greater:
      case TokenKind::greatergreater:
      case TokenKind::greaterequal:
        split_greater();
        advance();
        return true;
      case TokenKind::eof:
      case TokenKind::l_brace:
      case TokenKind::r_brace:
        if (Diagnostic* d =
                error_here("expected-token", "expected '>' to close the annotation list, found " + describe(tok())))
          d->notes.push_back({open.loc, "to match this '<'"});
        return false;
      case TokenKind::semi: advance(); continue;
      default: break;
    }
    uint32_t depth = depth_;
    parse_annotation(out);
    if (failed_) recover(depth, /*stop_at_greater=*/true);
  }
}

void Parser::parse_annotation(ast::List<ast::Annotation>& out) {
  uint32_t first = pos_;
  const uint32_t storage = parse_storage();
  ast::TypeRef type;
  if (!parse_type(type)) return;
  // `int a = 1, b = 2;` declares two annotations of one type, as a parameter list does;
  // the first one's range starts at the type, the others' at their names.
  uint32_t start = first;
  do {
    if (!at(TokenKind::identifier)) {
      error_here("expected-identifier", "expected an annotation name, found " + describe(tok()));
      return;
    }
    if (!check_name(tok(), "an annotation")) return;
    // Elements of annotation, state, pass, member and parameter lists are parsed in place
    // and dropped if they fail: building one aside and copying it in would copy every
    // element (a Variable is 176 bytes).
    ast::Annotation& a = out.emplace_back(arena_);
    a.storage = storage;
    a.type = type;
    a.name = keep(advance().text());
    if (!parse_array_dims(a.array_dims) || !expect(TokenKind::equal, "after annotation name")) {
      out.pop_back();
      return;
    }
    a.value = parse_assignment();
    if (failed_) {
      out.pop_back();
      return;
    }
    a.range = range_from(start);
    start = pos_ + 1;  // past the ',' that continues the declaration
  } while (accept(TokenKind::comma));
  expect_semi("after annotation");
}

bool Parser::parse_technique(ast::Technique& t) {
  uint32_t first = pos_;
  t.version = technique_version(advance().text());
  if (at(TokenKind::identifier)) {
    if (!check_name(tok(), "a technique")) return false;
    t.name = keep(tok().text());
    t.name_range = tok().range();
    advance();
  }
  if (at(TokenKind::less) && !parse_annotations(t.annotations)) return false;
  if (!at(TokenKind::l_brace)) return expect(TokenKind::l_brace, "to begin the technique body");
  Token open = tok();
  advance();
  while (!at(TokenKind::r_brace)) {
    if (at_eof()) {
      unterminated(open, "technique");
      return false;
    }
    if (accept(TokenKind::semi)) continue;
    if (at(TokenKind::directive)) {
      advance();
      continue;
    }
    uint32_t depth = depth_;
    if (tok().is(TokenKind::identifier) && iequals(tok().text(), "pass")) {
      if (!parse_pass(t.passes.emplace_back(arena_))) t.passes.pop_back();  // in place, see parse_annotations
    } else {
      error_here("expected-pass", "expected 'pass' in technique body, found " + describe(tok()));
    }
    if (failed_) recover(depth);
  }
  advance();
  accept(TokenKind::semi);
  t.range = range_from(first);
  return true;
}

bool Parser::parse_pass(ast::Pass& p) {
  uint32_t first = pos_;
  advance();  // pass
  if (at(TokenKind::identifier)) {
    if (!check_name(tok(), "a pass")) return false;
    p.name = keep(tok().text());
    p.name_range = tok().range();
    advance();
  }
  if (at(TokenKind::less) && !parse_annotations(p.annotations)) return false;
  if (!parse_state_list(p.states, "pass")) return false;
  p.range = range_from(first);
  return true;
}

bool Parser::parse_state_list(ast::List<ast::StateAssignment>& out, std::string_view what) {
  if (!at(TokenKind::l_brace)) {
    std::string context = "to begin the ";
    context.append(what).append(" body");
    return expect(TokenKind::l_brace, context);
  }
  Token open = tok();
  advance();
  out.reserve(arena_, 4);
  while (!at(TokenKind::r_brace)) {
    if (at_eof()) {
      unterminated(open, what);
      return false;
    }
    if (accept(TokenKind::semi)) continue;
    if (at(TokenKind::directive)) {
      advance();
      continue;
    }
    uint32_t depth = depth_;
    if (!parse_state(out.emplace_back(arena_))) out.pop_back();  // in place, see parse_annotations
    if (failed_) recover(depth);
  }
  advance();
  return true;
}

bool Parser::parse_state(ast::StateAssignment& s) {
  uint32_t first = pos_;
  if (!at(TokenKind::identifier)) {
    error_here("expected-state", "expected a state assignment, found " + describe(tok()));
    return false;
  }
  s.name = keep(tok().text());
  s.name_range = tok().range();
  advance();
  if (at(TokenKind::l_paren)) {
    // D3D10/11: `SetVertexShader(CompileShader(vs_4_0, VS()));`
    s.call_style = true;
    s.value = make(ast::ExprKind::call, first);
    s.value->text = s.name;
    if (!parse_call_args(s.value->args)) return false;
    s.value->range = range_from(first);
    s.range = s.value->range;
    return expect_semi("after state call");
  }
  if (accept(TokenKind::l_square)) {
    s.index = parse_expression();
    if (failed_ || !expect(TokenKind::r_square, "after state index")) return false;
  }
  if (!at(TokenKind::equal))  // the message names the state, so build it only when needed
    return expect(TokenKind::equal, "after state name " + quote(s.name));
  advance();
  s.value = parse_assignment();
  if (failed_) return false;
  if (s.value->kind == ast::ExprKind::init_list && shader_state_stage(s.name) && !s.value->args.empty()) {
    // `VertexShader = { Common, Lighting };` names GLSL blocks joined into one stage.
    bool names_only = true;
    for (const ast::ExprPtr& a : s.value->args) names_only = names_only && a && a->kind == ast::ExprKind::identifier;
    if (names_only) s.value->kind = ast::ExprKind::glsl_list;
  }
  s.range = range_from(first);
  return expect_semi("after state assignment");
}

void Parser::parse_group(std::vector<ast::Decl>& out) {
  uint32_t first = pos_;
  advance();  // fxgroup
  ast::FxGroup* g = declarations_.make<ast::FxGroup>();
  if (!at(TokenKind::identifier)) {
    error_here("expected-identifier", "expected a group name, found " + describe(tok()));
    return;
  }
  g->name = keep(tok().text());
  g->name_range = tok().range();
  advance();
  if (at(TokenKind::less) && !parse_annotations(g->annotations)) return;
  if (!at(TokenKind::l_brace)) {
    expect(TokenKind::l_brace, "to begin the fxgroup body");
    return;
  }
  Token open = tok();
  advance();
  while (!at(TokenKind::r_brace)) {
    if (at_eof()) {
      unterminated(open, "fxgroup");
      return;
    }
    if (accept(TokenKind::semi)) continue;
    uint32_t depth = depth_;
    if (tok().is(TokenKind::identifier) && technique_version(tok().text())) {
      ast::Technique t;
      if (parse_technique(t)) g->techniques.push_back(arena_, t);
    } else {
      error_here("expected-technique", "expected a technique in fxgroup body, found " + describe(tok()));
    }
    if (failed_) recover(depth);
  }
  advance();
  accept(TokenKind::semi);
  g->range = range_from(first);
  ast::Decl d;
  d.kind = ast::DeclKind::group;
  d.group = g;
  out.push_back(d);
}

}  // namespace fx::detail
