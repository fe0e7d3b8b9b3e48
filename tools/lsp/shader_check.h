// Compiled-shader findings for the language server: a snapshot of a document compiled as
// `fxkit check` compiles an effect (tools/check check_shaders: every pass stage and shader
// array element, each diagnostic once with "also reported for" notes), with glslang in
// compile worker processes so a compiler crash costs one result, not the editor's server;
// and each technique validated on the configured caps profiles as `fxkit select` validates
// it, as a code lens. The snapshot is built through fx::EffectFile, as check and hot reload
// build an effect, with its includes read from the open documents. Runtime builds only
// (FXKIT_VULKAN); CompileScheduler runs it off the request thread.
#pragma once
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "compile_scheduler.h"

namespace fx {
class CompileWorkers;
class ShaderCompiler;
class SpirvCache;
}  // namespace fx

namespace fx::tools::lsp {

class ShaderCheck {
 public:
  // `workers` (optional, taken over): glslang runs there; nullptr compiles in this process.
  explicit ShaderCheck(std::unique_ptr<fx::CompileWorkers> workers);
  ~ShaderCheck();

  // The snapshot's compiled-shader diagnostics as LSP Diagnostics of its document, and a
  // code lens per technique ("valid on dx9, modern; dx8: <first reason>", whose command
  // kTechniqueValidityCommand shows every reason); nothing when the front end or the
  // semantic model finds errors (glslang would only repeat them). Thread-safe.
  CompileFindings check(const CompileSnapshot& snapshot) const;

 private:
  std::unique_ptr<fx::CompileWorkers> workers_;
  std::unique_ptr<fx::SpirvCache> cache_;  // in memory: what an edit left unchanged is not recompiled
  std::unique_ptr<fx::ShaderCompiler> compiler_;
};

}  // namespace fx::tools::lsp
