// What fxc refuses inside function bodies that the front end, which keeps a body as tokens
// for the shader compiler, would otherwise let through to glslang (which takes it).
#include <algorithm>

#include "checker_internal.h"

namespace fx {
namespace check {

void Checker::check_local_annotations(const ast::Function& f) {
  // `float var < int a = 1; > = 0;` in a function: a declaration's name followed by `<`, a
  // type and a name. No expression reads so (`a < int b` is no expression), so the pattern
  // finds annotations only. fxc refuses them on locals (vkd3d's effect-annotations tests).
  const std::vector<Token>& toks = effect_.tokens;
  const uint32_t end = std::min<uint32_t>(f.body.last, static_cast<uint32_t>(toks.size()));
  for (uint32_t i = f.body.first; i + 4 < end; ++i) {
    if (!toks[i].is(TokenKind::identifier) || !toks[i + 1].is(TokenKind::identifier) ||
        !toks[i + 2].is(TokenKind::less) || !toks[i + 3].is(TokenKind::identifier) ||
        !toks[i + 4].is(TokenKind::identifier))
      continue;
    if (toks[i].text() == "return") continue;
    diags_.error(
        "annotation-on-local", toks[i + 2].range(),
        "annotations are allowed on global variables only; fxc refuses them on the local " + quote(toks[i + 1].text()));
    i += 4;
  }
}

}  // namespace check
}  // namespace fx
