#include "compile_worker_protocol.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "shader_serialize.h"

namespace fx::worker {
namespace {

constexpr uint32_t kRequestMagic = 0x46585251;  // "FXRQ"
constexpr uint32_t kReplyMagic = 0x46585250;    // "FXRP"

class Writer {
 public:
  void u32(uint32_t v) { out_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void f64(double v) { out_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void bytes(std::string_view s) {
    u32(static_cast<uint32_t>(s.size()));
    out_.append(s);
  }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

// Reads what Writer wrote; any read past the end makes ok() false for good.
class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  uint32_t u32() { return scalar<uint32_t>(); }
  double f64() { return scalar<double>(); }
  std::string_view bytes() {
    uint32_t n = u32();
    if (!ok_ || n > in_.size() - at_) return fail(), std::string_view();
    std::string_view s = in_.substr(at_, n);
    at_ += n;
    return s;
  }
  bool ok() const { return ok_; }
  bool done() const { return ok_ && at_ == in_.size(); }

 private:
  template <class T>
  T scalar() {
    T v{};
    if (!ok_ || sizeof v > in_.size() - at_) return fail(), v;
    std::memcpy(&v, in_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  void fail() { ok_ = false; }

  std::string_view in_;
  size_t at_ = 0;
  bool ok_ = true;
};

uint32_t option_bits(const CompileOptions& o) {
  return static_cast<uint32_t>(o.target) | (o.debug_info ? 1u << 8 : 0) | (o.keep_hlsl_semantics ? 1u << 9 : 0) |
         (o.warnings_as_errors ? 1u << 10 : 0) | (o.validate ? 1u << 11 : 0);
}

CompileOptions options_from(uint32_t bits) {
  CompileOptions o;
  o.target = static_cast<VulkanTarget>(bits & 0xff);
  o.debug_info = bits & (1u << 8);
  o.keep_hlsl_semantics = bits & (1u << 9);
  o.warnings_as_errors = bits & (1u << 10);
  o.validate = bits & (1u << 11);
  return o;
}

using Clock = std::chrono::steady_clock;

// Waits until `fd` is readable; false on timeout (sets *timed_out) or error.
bool wait_readable(int fd, Clock::time_point deadline, bool limited, bool* timed_out) {
  for (;;) {
    int wait_ms = -1;
    if (limited) {
      auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        if (timed_out) *timed_out = true;
        return false;
      }
      wait_ms = static_cast<int>(std::min<long long>(left, 1 << 30));
    }
    pollfd p{fd, POLLIN, 0};
    int r = ::poll(&p, 1, wait_ms);
    if (r > 0) return true;  // readable, or hung up: read() tells which
    if (r < 0 && errno != EINTR) return false;
  }
}

bool read_exact(int fd, char* data, size_t size, Clock::time_point deadline, bool limited, bool* timed_out) {
  while (size > 0) {
    if (!wait_readable(fd, deadline, limited, timed_out)) return false;
    ssize_t n = ::read(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

std::string encode(const Request& r) {
  Writer w;
  w.u32(kRequestMagic);
  w.u32(option_bits(r.options));
  w.u32(static_cast<uint32_t>(r.unit.stage));
  w.u32(static_cast<uint32_t>(r.unit.language));
  w.bytes(r.unit.source);
  w.bytes(r.unit.entry_point);
  w.bytes(r.unit.profile);
  w.bytes(r.unit.name);
  w.u32(static_cast<uint32_t>(r.unit.defines.size()));
  for (const ShaderDefine& d : r.unit.defines) {
    w.bytes(d.name);
    w.bytes(d.value);
  }
  return w.take();
}

std::optional<Request> decode_request(std::string_view payload) {
  Reader r(payload);
  if (r.u32() != kRequestMagic) return std::nullopt;
  Request q;
  q.options = options_from(r.u32());
  uint32_t stage = r.u32(), language = r.u32();
  if (stage > static_cast<uint32_t>(ShaderStage::compute) || language > static_cast<uint32_t>(ShaderLanguage::glsl) ||
      static_cast<uint32_t>(q.options.target) > static_cast<uint32_t>(VulkanTarget::vulkan_1_3))
    return std::nullopt;
  q.unit.stage = static_cast<ShaderStage>(stage);
  q.unit.language = static_cast<ShaderLanguage>(language);
  q.unit.source = r.bytes();
  q.unit.entry_point = r.bytes();
  q.unit.profile = r.bytes();
  q.unit.name = r.bytes();
  uint32_t defines = r.u32();
  for (uint32_t i = 0; r.ok() && i < defines; ++i) {
    std::string_view name = r.bytes(), value = r.bytes();
    q.unit.defines.push_back({std::string(name), std::string(value)});
  }
  if (!r.done()) return std::nullopt;
  return q;
}

std::string encode(const CompiledShader& s) {
  Writer w;
  w.u32(kReplyMagic);
  w.u32((s.ok ? 1u : 0u) | (s.legalized ? 2u : 0u));
  w.f64(s.parse_ms);
  w.f64(s.link_ms);
  w.bytes(std::string_view(reinterpret_cast<const char*>(s.spirv.data()), s.spirv.size() * sizeof(uint32_t)));
  w.bytes(write_shader_metadata(s));
  return w.take();
}

std::optional<CompiledShader> decode_reply(std::string_view payload) {
  Reader r(payload);
  if (r.u32() != kReplyMagic) return std::nullopt;
  CompiledShader s;
  uint32_t flags = r.u32();
  s.parse_ms = r.f64();
  s.link_ms = r.f64();
  std::string_view words = r.bytes();
  std::string_view metadata = r.bytes();
  if (!r.done() || words.size() % sizeof(uint32_t) != 0 || !read_shader_metadata(metadata, s)) return std::nullopt;
  s.ok = flags & 1u;
  s.legalized = flags & 2u;
  s.spirv.resize(words.size() / sizeof(uint32_t));
  if (!words.empty()) std::memcpy(s.spirv.data(), words.data(), words.size());  // a failed compile has none
  return s;
}

bool write_frame(int fd, std::string_view payload) {
  if (payload.size() > kMaxFrameBytes) return false;
  uint32_t size = static_cast<uint32_t>(payload.size());
  std::string frame(reinterpret_cast<const char*>(&size), sizeof size);
  frame.append(payload);
  for (size_t at = 0; at < frame.size();) {
    // send() with MSG_NOSIGNAL on a socket; write() where fd is a pipe (the worker's side
    // may be given either).
    ssize_t n = ::send(fd, frame.data() + at, frame.size() - at, MSG_NOSIGNAL);
    if (n < 0 && errno == ENOTSOCK) n = ::write(fd, frame.data() + at, frame.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    at += static_cast<size_t>(n);
  }
  return true;
}

std::optional<std::string> read_frame(int fd, int limit_ms, bool* timed_out) {
  if (timed_out) *timed_out = false;
  const bool limited = limit_ms >= 0;
  const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(limited ? limit_ms : 0);
  uint32_t size = 0;
  if (!read_exact(fd, reinterpret_cast<char*>(&size), sizeof size, deadline, limited, timed_out)) return std::nullopt;
  if (size > kMaxFrameBytes) return std::nullopt;
  std::string payload(size, '\0');
  if (!read_exact(fd, payload.data(), size, deadline, limited, timed_out)) return std::nullopt;
  return payload;
}

}  // namespace fx::worker
