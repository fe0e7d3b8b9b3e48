// State blocks of an effect for hover and completion (state_context.h).
#include "state_context.h"

namespace fx::tools::lsp {
namespace {

void add_technique(const fx::ast::Technique& t, std::vector<StateBlockSite>& out) {
  for (const fx::ast::Pass& p : t.passes) out.push_back({fx::StateBlock::pass, std::nullopt, p.range, &p.states});
}

// The identifier ending at `end` in `text` (skipping blanks before it), and where it starts.
std::string_view word_before(std::string_view text, size_t& end) {
  while (end > 0 && isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  size_t begin = end;
  while (begin > 0 && (isalnum(static_cast<unsigned char>(text[begin - 1])) || text[begin - 1] == '_')) --begin;
  std::string_view word = text.substr(begin, end - begin);
  end = begin;
  return word;
}

// Steps back over a bracketed group ending at `end` (`<...>` or `[...]`), if there is one.
void skip_group(std::string_view text, size_t& end, char open, char close) {
  size_t e = end;
  while (e > 0 && isspace(static_cast<unsigned char>(text[e - 1]))) --e;
  if (e == 0 || text[e - 1] != close) return;
  int depth = 0;
  for (size_t i = e; i > 0; --i) {
    if (text[i - 1] == close) ++depth;
    if (text[i - 1] == open && --depth == 0) {
      end = i - 1;
      return;
    }
  }
}

}  // namespace

std::optional<StateBlockSite> state_block_in_text(const TextDocument& document, Position at) {
  const std::string_view text = std::string_view(document.text).substr(0, document.offset_of(at));
  int depth = 0;
  size_t open = std::string_view::npos;
  for (size_t i = text.size(); i > 0; --i) {
    if (text[i - 1] == '}') ++depth;
    if (text[i - 1] == '{' && depth-- == 0) {
      open = i - 1;
      break;
    }
  }
  if (open == std::string_view::npos) return std::nullopt;
  size_t end = open;
  skip_group(text, end, '<', '>');  // annotations of a pass
  skip_group(text, end, '[', ']');  // a state object array
  const std::string_view last = word_before(text, end);
  const std::string_view before = word_before(text, end);
  const StateBlockSite none{};
  if (last == "pass" || before == "pass")
    return StateBlockSite{fx::StateBlock::pass, std::nullopt, none.range, nullptr};
  if (last == "sampler_state")
    return StateBlockSite{fx::StateBlock::sampler_state, fx::StateBlock::sampler_object, none.range, nullptr};
  if (auto block = fx::state_object_block(before)) return StateBlockSite{*block, std::nullopt, none.range, nullptr};
  return std::nullopt;
}

std::vector<StateBlockSite> state_block_sites(const fx::ast::Effect& effect) {
  std::vector<StateBlockSite> out;
  for (const fx::ast::Decl& d : effect.decls) {
    switch (d.kind) {
      case fx::ast::DeclKind::technique: add_technique(*d.technique, out); break;
      case fx::ast::DeclKind::group:
        for (const fx::ast::Technique& t : d.group->techniques) add_technique(t, out);
        break;
      case fx::ast::DeclKind::state_object:
        if (auto block = fx::state_object_block(d.state_object->kind)) {
          out.push_back({*block, std::nullopt, d.state_object->range, &d.state_object->states});
          for (const auto& element : d.state_object->element_states)
            out.push_back({*block, std::nullopt, d.state_object->range, &element});
        }
        break;
      case fx::ast::DeclKind::variable:
        if (const fx::ast::Expr* init = d.variable->initializer; init && init->kind == fx::ast::ExprKind::state_block)
          out.push_back({fx::StateBlock::sampler_state, fx::StateBlock::sampler_object, init->range, &init->states});
        break;
      default: break;
    }
  }
  return out;
}

const fx::StateInfo* state_row(const StateBlockSite& site, std::string_view name) {
  const fx::StateInfo* row = fx::find_state(name, site.block);
  if (!row && site.also) row = fx::find_state(name, *site.also);
  return row;
}

}  // namespace fx::tools::lsp
