// The diagnostics of every stage of an effect, each shown once: a function several passes'
// shaders call reports the same error in each, which is one problem; a note lists where
// else it came from. `fxkit check`, `fxkit compile` and the runtime's reloads (Reload,
// Effect::messages) all merge through it, so they report alike.
#pragma once
#include <string>
#include <vector>

#include "fx/diagnostic.h"

namespace fx {

class ShownOnce {
 public:
  // `where` names the pass stage the diagnostics came from ("" for the effect itself).
  void add(const std::vector<Diagnostic>& diagnostics, const std::string& where);
  // In the order first seen, each with a note "also reported for ..." when it repeated.
  std::vector<Diagnostic> diagnostics() const;

 private:
  struct Shown {
    Diagnostic diagnostic;
    std::vector<std::string> also;
  };
  std::vector<Shown> shown_;
};

}  // namespace fx
