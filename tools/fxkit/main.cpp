// fxkit: validate, inspect, compile, render, select, watch and benchmark effect files.
#include <cstdio>

#include "command.h"

namespace fx::tools {

void FrontEndFlags::add_to(CLI::App& command) {
  // One value per flag, as in fxc and clang (`-I a -I b`, `-Ia`, `-DNAME=V`): otherwise the
  // FILE after `-I DIR` would be read as a second folder.
  command.add_option("-I", include_dirs, "Add a folder to the include search path")->allow_extra_args(false);
  command.add_option("-D", defines, "Define a macro: NAME or NAME=VALUE")->allow_extra_args(false);
  command.add_option("--profile", profile, "Effect profile: fx_2_0, fx_4_0, fx_4_1, fx_5_0 or auto")
      ->capture_default_str();
}

bool FrontEndFlags::to_options(fx::FrontEndOptions& options, std::string& error) const {
  options.preprocessor.include_dirs = include_dirs;
  for (const std::string& d : defines) options.preprocessor.defines.push_back(fx::parse_define(d));
  auto parsed = fx::parse_effect_profile(profile);
  if (profile != "auto" && !parsed) {
    error = "unknown --profile '" + profile + "' (use fx_2_0, fx_4_0, fx_4_1, fx_5_0 or auto)";
    return false;
  }
  options.check.profile = parsed.value_or(fx::EffectProfile::automatic);
  return true;
}

}  // namespace fx::tools

int main(int argc, char** argv) {
  CLI::App app{"fxkit: effect files (.fx) for Vulkan"};
  app.require_subcommand(1);
  fx::tools::Runner run;
  fx::tools::register_check(app, run);
  fx::tools::register_bench(app, run);
  fx::tools::register_lsp(app, run);
#ifdef FXKIT_HAS_RUNTIME
  fx::tools::register_compile(app, run);
  fx::tools::register_info(app, run);
  fx::tools::register_watch(app, run);
  fx::tools::register_select(app, run);
  fx::tools::register_render(app, run);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? fx::tools::kSuccess : fx::tools::kUsageError;
  }
  return run ? run() : fx::tools::kUsageError;
}
