// `fxkit lsp`: the language server for effect files, over stdin and stdout (tools/lsp,
// docs/editor.md).
#include <unistd.h>

#include "command.h"
#include "language_server.h"
#ifdef FXKIT_HAS_RUNTIME
#include "compile_workers_option.h"
#include "shader_check.h"
#endif

namespace fx::tools {

void register_lsp(CLI::App& app, Runner& run) {
  CLI::App* command = app.add_subcommand("lsp", "Serve the Language Server Protocol on stdin/stdout");
  // Editors' generic clients often pass --stdio; it is the only transport, so it changes nothing.
  command->add_flag("--stdio")->description("Talk over stdin and stdout (the default)");
#ifdef FXKIT_HAS_RUNTIME
  // Compiled-shader diagnostics: glslang in one worker process (the editor's edits are
  // compiled one snapshot at a time), or here with --in-process.
  auto workers = std::make_shared<CompileWorkersFlag>();
  workers->add_to(*command);
  command->callback([&run, workers] {
    run = [workers] {
      lsp::ShaderCheck check(workers->start("lsp", 1));
      return lsp::run_stdio(STDIN_FILENO, STDOUT_FILENO,
                            [&check](const lsp::CompileSnapshot& s) { return check.check(s); });
    };
  });
#else
  command->callback([&run] { run = [] { return lsp::run_stdio(STDIN_FILENO, STDOUT_FILENO); }; });
#endif
}

}  // namespace fx::tools
