// What a compile worker process and its pool say to each other over a socket: one request
// (a translation unit and its options) answered by one reply (the compiled shader), each a
// length-prefixed frame. Private to runtime/compile: the pool and the worker's main().
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "fx/compile/shader_compiler.h"

namespace fx::worker {

// The worker's first frame, sent once it runs: the pool knows it started the right program.
inline constexpr std::string_view kReady = "fxkit-compile-worker 1 ready";
// Its second, once glslang's built-in tables are built: compiles are timed from here on.
inline constexpr std::string_view kWarm = "warm";
// The worker's exit status when glslang ran out of memory under the worker's limit.
inline constexpr int kExitOutOfMemory = 3;

// A frame's payload is at most this long; a longer length prefix is a broken peer.
inline constexpr uint32_t kMaxFrameBytes = 256u << 20;

struct Request {
  TranslationUnit unit;
  CompileOptions options;
};

std::string encode(const Request& request);
std::optional<Request> decode_request(std::string_view payload);

// Everything of the shader the pool's caller sees (timings included).
std::string encode(const CompiledShader& shader);
std::optional<CompiledShader> decode_reply(std::string_view payload);

// Blocking frame I/O on a stream socket or pipe, retried on EINTR; false when the peer
// closed it or an error occurred. Writing to a closed socket does not raise SIGPIPE.
bool write_frame(int fd, std::string_view payload);
// `limit_ms` < 0: no limit. nullopt on end of stream, error or when the limit passed
// (then `timed_out` is set).
std::optional<std::string> read_frame(int fd, int limit_ms, bool* timed_out = nullptr);

}  // namespace fx::worker
