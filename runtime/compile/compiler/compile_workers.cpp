#include "fx/compile/compile_workers.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <thread>

#include "compile_worker_protocol.h"
#include "entry_location.h"

extern char** environ;

namespace fx {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kExecutableName = "fxkit-compile-worker";
constexpr int kReadyLimitMs = 120'000;  // exec, then glslang's warm-up: generous for loaded machines

bool runnable(const std::string& path) { return !path.empty() && ::access(path.c_str(), X_OK) == 0; }

std::string beside_this_program() {
  std::error_code ec;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : (self.parent_path() / kExecutableName).string();
}

// What waitpid's status says, in words: "was killed by signal 11 (Segmentation fault)".
std::string describe_exit(int status, uint32_t memory_limit_mb) {
  if (WIFSIGNALED(status)) {
    int sig = WTERMSIG(status);
    const char* name = ::strsignal(sig);
    return "was killed by signal " + std::to_string(sig) + " (" + (name ? name : "unknown") + ")";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == worker::kExitOutOfMemory)
    return "ran out of memory (limit " + std::to_string(memory_limit_mb) + " MB)";
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  return "stopped answering";
}

CompiledShader worker_failure(const TranslationUnit& unit, const std::string& what) {
  CompiledShader out;
  out.entry_point = unit.entry_point;
  out.reflection.stage = unit.stage;
  out.reflection.entry_point = unit.entry_point;
  ShaderMessage m = entry_location(unit);
  m.severity = Severity::error;
  m.id = "compiler-crashed";
  m.text = "the shader compiler (glslang) " + what + " while compiling '" + unit.entry_point +
           "'; the shader is not compiled (the compile worker was replaced)";
  out.info_log = "ERROR: " + m.text + "\n";
  out.messages.push_back(std::move(m));
  return out;
}

}  // namespace

struct CompileWorkers::Process {
  pid_t pid = -1;
  int fd = -1;  // our end of the socket
};

std::string CompileWorkers::find_executable(const CompileWorkerOptions& options, std::vector<std::string>* searched) {
  std::vector<std::string> places;
  if (!options.executable.empty()) {
    places.push_back(options.executable);
  } else {
    if (const char* env = std::getenv("FXKIT_COMPILE_WORKER"); env && *env) places.push_back(env);
    places.push_back(beside_this_program());
#ifdef FXKIT_COMPILE_WORKER_BUILD_PATH
    places.push_back(FXKIT_COMPILE_WORKER_BUILD_PATH);
#endif
  }
  for (const std::string& p : places)
    if (runnable(p)) return p;
  if (searched) *searched = places;
  return {};
}

std::unique_ptr<CompileWorkers> CompileWorkers::start(const CompileWorkerOptions& options, std::string& error) {
  std::vector<std::string> searched;
  std::string executable = find_executable(options, &searched);
  if (executable.empty()) {
    error = "no runnable " + std::string(kExecutableName) + " (looked at";
    for (const std::string& s : searched) error += " '" + s + "'";
    error += ")";
    return nullptr;
  }
  // Workers start with the first compiles that need them: a run whose every shader comes
  // from the SPIR-V cache starts none.
  return std::unique_ptr<CompileWorkers>(new CompileWorkers(executable, options));
}

CompileWorkers::CompileWorkers(std::string executable, const CompileWorkerOptions& options)
    : executable_(std::move(executable)), options_(options) {
  uint32_t n = options.workers ? options.workers : std::max(1u, std::thread::hardware_concurrency());
  for (uint32_t i = 0; i < n; ++i) {
    slots_.push_back(std::make_unique<Process>());
    idle_.push_back(i);
  }
}

CompileWorkers::~CompileWorkers() {
  for (auto& p : slots_) retire(*p);
}

bool CompileWorkers::spawn(Process& p, std::string& error) {
  Clock::time_point t0 = Clock::now();
  int fds[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
    error = std::string("socketpair: ") + std::strerror(errno);
    return false;
  }
  // The worker reads and writes fd 3; dup2 onto it clears close-on-exec (unless the socket
  // already is fd 3, which a process with closed standard streams may get: move it first).
  if (fds[1] == 3) {
    int moved = ::fcntl(fds[1], F_DUPFD_CLOEXEC, 4);
    ::close(fds[1]);
    fds[1] = moved;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  // glslang may print; a worker's output must never reach the tool's stdout (JSON reports).
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 3);
  std::vector<std::string> args = {executable_, "--memory-limit-mb", std::to_string(options_.memory_limit_mb)};
  args.insert(args.end(), options_.arguments.begin(), options_.arguments.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  int rc = ::posix_spawn(&pid, executable_.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (rc != 0) {
    ::close(fds[0]);
    error = "cannot start '" + executable_ + "': " + std::strerror(rc);
    return false;
  }
  p.pid = pid;
  p.fd = fds[0];
  std::optional<std::string> ready = worker::read_frame(p.fd, kReadyLimitMs);
  Clock::time_point t1 = Clock::now();
  std::optional<std::string> warm = ready ? worker::read_frame(p.fd, kReadyLimitMs) : std::nullopt;
  if (!ready || *ready != worker::kReady || !warm || *warm != worker::kWarm) {
    retire(p);
    error = "'" + executable_ + "' did not start as a compile worker";
    return false;
  }
  std::lock_guard lock(mutex_);
  ++stats_.started;
  stats_.start_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  stats_.warm_up_ms = std::chrono::duration<double, std::milli>(Clock::now() - t1).count();
  return true;
}

int CompileWorkers::retire(Process& p) {
  int status = 0;
  if (p.fd >= 0) ::close(p.fd);
  if (p.pid > 0) {
    // It holds nothing worth a clean exit, and must not keep us waiting. A worker that has
    // already died keeps the status it died with: a signal to it changes nothing.
    ::kill(p.pid, SIGKILL);
    while (::waitpid(p.pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
  p.fd = -1;
  p.pid = -1;
  return status;
}

size_t CompileWorkers::acquire() {
  std::unique_lock lock(mutex_);
  idle_changed_.wait(lock, [&] { return !idle_.empty(); });
  size_t slot = idle_.back();
  idle_.pop_back();
  return slot;
}

void CompileWorkers::release(size_t slot) {
  {
    std::lock_guard lock(mutex_);
    idle_.push_back(slot);
  }
  idle_changed_.notify_one();
}

CompiledShader CompileWorkers::compile(const TranslationUnit& unit, const CompileOptions& options) {
  const size_t slot = acquire();
  Process& p = *slots_[slot];
  std::string error;
  if (p.pid < 0 && !spawn(p, error)) {  // its first use, or a replacement that failed to start
    release(slot);
    return worker_failure(unit, "could not be started (" + error + ")");
  }
  bool timed_out = false;
  std::optional<std::string> reply;
  if (worker::write_frame(p.fd, worker::encode(worker::Request{unit, options})))
    reply = worker::read_frame(p.fd, static_cast<int>(options_.time_limit_ms), &timed_out);
  std::optional<CompiledShader> shader = reply ? worker::decode_reply(*reply) : std::nullopt;
  if (shader) {
    {
      std::lock_guard lock(mutex_);
      ++stats_.compiles;
    }
    release(slot);
    return std::move(*shader);
  }
  // The worker died, hung or answered nonsense: it is not trusted with another unit.
  const int status = retire(p);
  char limit[32];
  std::snprintf(limit, sizeof limit, "%.1f", options_.time_limit_ms / 1000.0);
  std::string what = timed_out ? "did not finish within " + std::string(limit) + " s (it was stopped)"
                     : reply   ? "sent a malformed reply"
                               : describe_exit(status, options_.memory_limit_mb);
  {
    std::lock_guard lock(mutex_);
    ++(timed_out ? stats_.timed_out : stats_.crashed);
  }
  spawn(p, error);  // on failure the next compile on this slot tries again
  release(slot);
  return worker_failure(unit, what);
}

CompileWorkerStats CompileWorkers::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

}  // namespace fx
