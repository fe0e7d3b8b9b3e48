// `fxkit check [-I DIR]... [-D NAME[=VALUE]]... [--profile P] [--werror]
//  [--syntax-only | --compile] [--jobs N] [--cache DIR [--cache-limit-mb N]]
//  [--include-glob G]... [--exclude-glob G]... [--shard K/N] [--allow-empty]
//  [--format text|json|sarif|junit | --json] [-o FILE]
//  [--caps dx7|modern|FILE.json|device [--no-compile]] [--in-process] PATH...`
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>

#include "check_inputs.h"
#include "check_progress.h"
#include "check_report.h"
#include "command.h"
#include "effect_check.h"
#include "fx/diagnostic_render.h"
#include "fx/worker_pool.h"
#include "sarif_report.h"
#ifdef FXKIT_HAS_RUNTIME
#include "caps_option.h"
#include "check_cache.h"
#include "compile_workers_option.h"
#include "fx/compile/spirv_cache.h"
#include "fx/select/device_caps.h"
#endif

namespace fx::tools {
namespace {

struct CheckArgs {
  FrontEndFlags front_end;
  std::vector<std::string> paths;
  bool json = false;  // --json: --format json
  std::string format = "text";
  std::string output;  // -o: the report goes here, the summary to the terminal
  bool werror = false;
  bool syntax_only = false;
  bool compile = false;  // --compile: the default, spelled out
  unsigned jobs = 0;     // 0: one per hardware thread
  std::string cache_dir;
  unsigned cache_limit_mb = 512;
  std::vector<std::string> include_globs{"*.fx"}, exclude_globs;
  std::string shard;
  bool allow_empty = false;  // --allow-empty: no effect found is a success
  std::string caps;          // --caps: validate every technique on these caps ("" = don't)
  bool no_compile = false;   // --no-compile: validate without compiling shaders
#ifdef FXKIT_HAS_RUNTIME
  CompileWorkersFlag workers;  // glslang in worker processes, one per job
#endif
};

std::string joined(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

#ifdef FXKIT_HAS_RUNTIME
// What besides the files decides a cached result: the flags, fxkit's own build (a rebuilt
// binary may report differently) and the working directory relative paths start from.
std::string cache_options(const CheckArgs& args) {
  nlohmann::json j = {{"include_dirs", args.front_end.include_dirs},
                      {"defines", args.front_end.defines},
                      {"profile", args.front_end.profile},
                      {"compile", !args.syntax_only},
                      {"werror", args.werror},
                      {"caps", args.caps},
                      {"no_compile", args.no_compile},
                      {"glslang", fx::ShaderCompiler::glslang_version()},
                      {"cwd", std::filesystem::current_path().string()}};
  struct stat self {};
  if (::stat("/proc/self/exe", &self) == 0)
    j["fxkit"] = std::to_string(self.st_size) + "@" + std::to_string(self.st_mtim.tv_sec) + "." +
                 std::to_string(self.st_mtim.tv_nsec);
  return j.dump();
}
#endif

// Where the report goes: -o FILE or stdout.
class ReportOutput {
 public:
  bool open(const std::string& path) {
    if (path.empty()) return true;
    file_.open(path, std::ios::binary);
    return static_cast<bool>(file_);
  }
  void write(const std::string& text) {
    if (file_.is_open()) file_ << text;
    else std::fputs(text.c_str(), stdout);
  }
  bool ok() const { return !file_.is_open() || static_cast<bool>(file_); }

 private:
  std::ofstream file_;
};

int run_check(CheckArgs args) {
  auto start = std::chrono::steady_clock::now();
  if (args.json) args.format = "json";
  EffectCheckSettings settings;
  std::string error;
  if (!args.front_end.to_options(settings.front_end, error)) {
    std::fprintf(stderr, "fxkit check: %s\n", error.c_str());
    return kUsageError;
  }
  CheckInputOptions input_options{args.include_globs, args.exclude_globs, args.front_end.include_dirs};
  if (!args.shard.empty() && !parse_shard(args.shard, input_options.shard, input_options.shards)) {
    std::fprintf(stderr, "fxkit check: --shard takes K/N with 1 <= K <= N, not '%s'\n", args.shard.c_str());
    return kUsageError;
  }
  CheckInputs inputs;
  if (!find_check_inputs(args.paths, input_options, inputs, error)) {
    std::fprintf(stderr, "fxkit check: %s\n", error.c_str());
    return kUsageError;
  }
  // A CI job whose paths or globs match nothing checks nothing: that passes nothing either.
  // A shard left empty while other shards hold files is fine.
  if (inputs.files.empty() && inputs.other_shards == 0 && !args.allow_empty) {
    std::fprintf(stderr,
                 "fxkit check: no effect files found in %s (include globs:%s); pass --allow-empty if an "
                 "empty run should pass\n",
                 joined(args.paths, ", ").c_str(), (" " + joined(input_options.include_globs, " ")).c_str());
    return kUsageError;
  }
  ReportOutput report;
  if (!report.open(args.output)) {
    std::fprintf(stderr, "fxkit check: cannot write '%s'\n", args.output.c_str());
    return kUsageError;
  }
  settings.werror = args.werror;
  settings.compile = !args.syntax_only;
#ifdef FXKIT_HAS_RUNTIME
  std::optional<fx::DeviceCaps> caps;
  if (!args.caps.empty()) {
    fx::DiagnosticSink caps_diags;
    caps = load_caps_option(args.caps, caps_diags);
    if (!caps) {
      std::fputs(fx::render_text(caps_diags.diagnostics(), fx::SourceManager()).c_str(), stderr);
      return kUsageError;
    }
    settings.caps = &*caps;
    settings.caps_compile = !args.no_compile;
  }
  std::optional<CheckCache> cache;
  if (!args.cache_dir.empty()) cache.emplace(args.cache_dir, cache_options(args), uint64_t{args.cache_limit_mb} << 20);
  fx::SpirvCache spirv(cache ? cache->spirv_directory() : std::filesystem::path());
  const bool compiles = !args.syntax_only && (args.caps.empty() || !args.no_compile);
  std::unique_ptr<fx::CompileWorkers> workers = compiles ? args.workers.start("check", args.jobs) : nullptr;
  fx::ShaderCompiler compiler({}, &spirv, workers.get());
  settings.compiler = &compiler;
#endif
  fx::WorkerPool pool(args.jobs);
  settings.executor = &pool;

  CheckRun run;
  run.included_only = inputs.included_only;
  const size_t n = inputs.files.size();
  std::vector<bool> finished(n, false);
  size_t printed = 0, done = 0;
  std::mutex print_mutex;
  CheckProgress progress(n, ::isatty(STDERR_FILENO) == 1);
  const bool text = args.format == "text";
  // Results are printed in file order, by whichever thread completes the next one.
  auto publish = [&](size_t i) {
    std::lock_guard lock(print_mutex);
    finished[i] = true;
    ++done;
    for (; printed < n && finished[printed]; ++printed) {
      const EffectCheck& c = run.checks[printed];
      if (!text || (c.text.empty() && c.caps_text.empty())) continue;
      progress.clear();
      if (args.output.empty()) {
        std::fputs(c.caps_text.c_str(), stdout);
        std::fflush(stdout);
        std::fputs(c.text.c_str(), stderr);
      } else {
        report.write(c.caps_text + c.text);
      }
    }
    progress.update(done);
  };
  CheckCache* cache_used = nullptr;
#ifdef FXKIT_HAS_RUNTIME
  if (cache) cache_used = &*cache;
#endif
  check_effects(inputs.files, settings, cache_used, run.checks, publish);
  progress.clear();
#ifdef FXKIT_HAS_RUNTIME
  if (cache) cache->evict();
#endif
  for (const EffectCheck& c : run.checks) run.from_cache += c.from_cache ? 1 : 0;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (args.format == "json") report.write(json_text(json_report(run)) + "\n");
  else if (args.format == "sarif")
    report.write(json_text(sarif_report(run, std::filesystem::current_path().string())) + "\n");
  else if (args.format == "junit") report.write(junit_report(run));
  if (!report.ok()) {
    std::fprintf(stderr, "fxkit check: cannot write '%s'\n", args.output.c_str());
    return kUsageError;
  }
  // Silent for one clean file named on the command line, as compilers are; otherwise the
  // counts a CI log shows (a folder or a shard that held one file, or none, included).
  const bool one_named_file =
      n == 1 && args.paths.size() == 1 && args.shard.empty() && std::filesystem::is_regular_file(args.paths[0]);
  if (!one_named_file || run.errors() || run.warnings() || !args.output.empty())
    std::fprintf(stderr, "%s\n", summary_line(run).c_str());
  return run.failed() ? kInputErrors : kSuccess;
}

}  // namespace

void register_check(CLI::App& app, Runner& run) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand("check", "Check effect files: the front end and every shader compiled");
  args->front_end.add_to(*cmd);
  cmd->add_option("--format", args->format, "Report format: text, json, sarif (SARIF 2.1.0) or junit (JUnit XML)")
      ->check(CLI::IsMember({"text", "json", "sarif", "junit"}))
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Same as --format json");
  cmd->add_option("-o", args->output, "Write the report to FILE (the summary line still goes to stderr)");
  cmd->add_flag("--werror", args->werror, "Treat warnings as errors");
  cmd->add_option("--jobs,-j", args->jobs, "Files and shader stages checked at once (default: one per core)")
      ->check(CLI::Range(1u, 1024u));
  cmd->add_option("--include-glob", args->include_globs,
                  "Files to check in PATH folders (default *.fx; a pattern with / matches the path below the folder)")
      ->allow_extra_args(false);
  cmd->add_option("--exclude-glob", args->exclude_globs, "Files in PATH folders not to check")->allow_extra_args(false);
  cmd->add_option("--shard", args->shard, "Check shard K of N (1-based): a stable 1/N of the files, for CI machines");
  cmd->add_flag("--allow-empty", args->allow_empty, "Succeed when the paths hold no effect file (default: exit 2)");
  cmd->add_option("PATH", args->paths, "Effect files and folders (searched recursively)")->required();
  [[maybe_unused]] auto* syntax =
      cmd->add_flag("--syntax-only", args->syntax_only,
                    "The front end's checks alone: preprocess, parse, effect-level checks; no shader compiled");
#ifdef FXKIT_HAS_RUNTIME
  cmd->add_flag("--compile", args->compile, "Also compile every shader to SPIR-V (the default)")->excludes(syntax);
  cmd->add_option("--cache", args->cache_dir,
                  "Keep results and SPIR-V in DIR, by content hash of each effect, its includes and the options");
  cmd->add_option("--cache-limit-mb", args->cache_limit_mb, "Size bound of the --cache folder (oldest evicted)")
      ->capture_default_str();
  cmd->add_option("--caps", args->caps, "Validate every technique on: " + caps_option_help());
  cmd->add_flag("--no-compile", args->no_compile, "With --caps: validate without compiling shaders");
  args->workers.add_to(*cmd);
#else
  args->syntax_only = true;  // a parser-only build has no shader compiler: the flag is what it does anyway
#endif
  cmd->callback([args, &run] { run = [args] { return run_check(*args); }; });
}

}  // namespace fx::tools
