// `fxkit lsp`: the language server for effect files, over stdin and stdout (tools/lsp,
// docs/editor.md).
#include <unistd.h>

#include "command.h"
#include "language_server.h"

namespace fx::tools {

void register_lsp(CLI::App& app, Runner& run) {
  CLI::App* command = app.add_subcommand("lsp", "Serve the Language Server Protocol on stdin/stdout");
  // Editors' generic clients often pass --stdio; it is the only transport, so it changes nothing.
  command->add_flag("--stdio")->description("Talk over stdin and stdout (the default)");
  command->callback([&run] { run = [] { return lsp::run_stdio(STDIN_FILENO, STDOUT_FILENO); }; });
}

}  // namespace fx::tools
