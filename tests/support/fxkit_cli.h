// Runs the built fxkit binary as a user would, for the command-line tests. Suites that use
// it are declared with `fxkit_cli_test()` in tests/CMakeLists.txt, which defines
// FXKIT_BINARY and builds fxkit first.
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <string>

namespace fx::testing {

struct CliRun {
  int status = -1;  // exit code, or -1 if fxkit did not exit normally
  std::string out;  // standard output
  std::string err;  // standard error (when requested)
};

// Runs `fxkit ARGS`; stderr is captured into `err` when `capture_stderr`, else discarded.
// `prefix` goes before the binary in the shell command (`timeout 60 `).
inline CliRun run_fxkit(const std::string& args, bool capture_stderr = false, const std::string& prefix = "") {
  CliRun r;
  std::string err_file = std::string(::testing::TempDir()) + "fxkit_cli_stderr_" + std::to_string(::getpid()) + ".txt";
  std::string cmd =
      prefix + std::string(FXKIT_BINARY) + " " + args + " 2>" + (capture_stderr ? err_file : std::string("/dev/null"));
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  int status = pclose(p);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (capture_stderr) {
    if (FILE* f = std::fopen(err_file.c_str(), "rb")) {
      while ((n = fread(buf, 1, sizeof buf, f)) > 0) r.err.append(buf, n);
      std::fclose(f);
    }
    std::remove(err_file.c_str());
  }
  return r;
}

}  // namespace fx::testing
