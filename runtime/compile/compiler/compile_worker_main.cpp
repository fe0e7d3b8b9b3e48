// fxkit-compile-worker: compiles translation units with glslang for a CompileWorkers pool,
// one request at a time on fd 3 (compile_worker_protocol.h), until the pool closes it.
// Whatever glslang does to this process, the pool's process lives on.
//
//   fxkit-compile-worker [--memory-limit-mb N] [--abort-on TEXT] [--hang-on TEXT] [--allocate-on TEXT]
//
// --abort-on / --hang-on / --allocate-on make the worker abort, stop answering or allocate
// without bound on a unit whose source contains TEXT: the pool's tests force a crash, a
// hang and a memory blow-up with them.
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "compile_worker_protocol.h"

namespace {

constexpr int kFd = 3;

struct Arguments {
  unsigned long memory_limit_mb = 0;
  std::string abort_on, hang_on, allocate_on;
};

bool parse(int argc, char** argv, Arguments& a) {
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (i + 1 >= argc) return false;
    const char* value = argv[++i];
    if (arg == "--memory-limit-mb") a.memory_limit_mb = std::strtoul(value, nullptr, 10);
    else if (arg == "--abort-on") a.abort_on = value;
    else if (arg == "--hang-on") a.hang_on = value;
    else if (arg == "--allocate-on") a.allocate_on = value;
    else return false;
  }
  return true;
}

// glslang builds its built-in symbol tables on a stage's first parse (about 100 ms): the
// worker pays it once, when it starts, not on an edit.
void warm_up() {
  const fx::ShaderCompiler compiler;
  fx::TranslationUnit vs, ps;
  vs.source = "float4 main(float4 p : POSITION) : SV_Position { return p; }";
  vs.profile = "vs_3_0";
  ps.source = "float4 main() : COLOR { return 1; }";
  ps.stage = fx::ShaderStage::fragment;
  ps.profile = "ps_3_0";
  compiler.compile(vs);
  compiler.compile(ps);
}

// Whether `text` is a test flag's marker that `source` contains.
bool marked(const std::string& source, const std::string& text) {
  return !text.empty() && source.find(text) != std::string::npos;
}

// What a runaway compile does to memory: allocate until the limit says no (an address-space
// limit refuses the allocation itself, touched or not).
[[noreturn]] void allocate_without_bound() {
  std::vector<std::unique_ptr<char[]>> held;
  for (;;) held.emplace_back(new char[64u << 20]);
}

// AddressSanitizer reserves terabytes of address space before main(): a limit on it would
// stop the sanitizer's own allocator, not glslang, so sanitizer builds run without one.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSpaceLimitWorks = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSpaceLimitWorks = false;
#else
constexpr bool kAddressSpaceLimitWorks = true;
#endif
#else
constexpr bool kAddressSpaceLimitWorks = true;
#endif

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  if (!parse(argc, argv, args)) {
    std::fputs("usage: fxkit-compile-worker [--memory-limit-mb N] (started by fxkit's compile pool)\n", stderr);
    return 2;
  }
  // Nothing else the starting process left open is ours to hold.
  ::close_range(kFd + 1, ~0u, 0);
  if (args.memory_limit_mb && kAddressSpaceLimitWorks) {
    rlimit limit{args.memory_limit_mb << 20, args.memory_limit_mb << 20};
    ::setrlimit(RLIMIT_AS, &limit);
  }
  if (!fx::worker::write_frame(kFd, fx::worker::kReady)) return 1;
  try {
    warm_up();
    if (!fx::worker::write_frame(kFd, fx::worker::kWarm)) return 1;
    while (std::optional<std::string> frame = fx::worker::read_frame(kFd, -1)) {
      std::optional<fx::worker::Request> request = fx::worker::decode_request(*frame);
      if (!request) return 1;
      const std::string& source = request->unit.source;
      if (marked(source, args.abort_on)) std::abort();
      if (marked(source, args.hang_on))
        for (;;) ::pause();
      if (marked(source, args.allocate_on)) allocate_without_bound();
      fx::CompiledShader shader = fx::ShaderCompiler(request->options).compile(request->unit);
      if (!fx::worker::write_frame(kFd, fx::worker::encode(shader))) return 1;
    }
  } catch (const std::bad_alloc&) {
    return fx::worker::kExitOutOfMemory;
  }
  return 0;  // the pool closed the socket
}
