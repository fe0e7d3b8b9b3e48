// Where the effect's state assignments are (passes, sampler_state blocks, D3D10/11 state
// objects) and which state block each belongs to: what hover and completion ask of a
// position inside technique or state code.
#pragma once
#include <optional>
#include <vector>

#include "document_analysis.h"
#include "fx/state_table.h"

namespace fx::tools::lsp {

// A block of state assignments and the table block its names are looked up in.
struct StateBlockSite {
  fx::StateBlock block;
  std::optional<fx::StateBlock> also;  // a sampler_state also takes the D3D10 fields
  fx::SourceRange range;
  const fx::ast::List<fx::ast::StateAssignment>* states;
};

// Every state block of the effect.
std::vector<StateBlockSite> state_block_sites(const fx::ast::Effect& effect);
// The state row an assignment names, in its block (or the block's alternative).
const fx::StateInfo* state_row(const StateBlockSite& site, std::string_view name);
// The kind of state block the text of `document` has open at `at` (`pass P0 {`,
// `sampler_state {`, `BlendState B {`), read from the text alone: while the user types,
// the block may not parse. nullopt outside any.
std::optional<StateBlockSite> state_block_in_text(const TextDocument& document, Position at);

}  // namespace fx::tools::lsp
