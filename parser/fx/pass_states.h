// A pass's states as D3D applies them: `StateBlock = <sb>;` applies, at that point, the
// states of `stateblock sb = stateblock_state { ... };` (D3DX9 captures them in a state block
// and applies it with the pass), so the model and the shader units read those states as if
// the pass had written them there.
#pragma once
#include <vector>

#include "fx/ast.h"

namespace fx {

// The states of `pass` in order, each `StateBlock = <sb>;` naming a stateblock variable of
// `effect` replaced by that variable's states; any other StateBlock assignment stays as it
// is (the model reports what it names).
std::vector<const ast::StateAssignment*> applied_pass_states(const ast::Effect& effect, const ast::Pass& pass);

}  // namespace fx
