// JSON-RPC 2.0 over a byte stream as the Language Server Protocol frames it: a
// `Content-Length: N` header, a blank line, N bytes of JSON.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace fx::tools::lsp {

using json = nlohmann::json;

// Reads framed messages from a file descriptor, buffering what arrives.
class MessageReader {
 public:
  explicit MessageReader(int fd) : fd_(fd) {}
  // The next message's text; blocks until one is complete. nullopt at end of input.
  std::optional<std::string> read();
  // True when a whole message is buffered or more input is waiting (never blocks).
  bool more_waiting();

 private:
  std::optional<std::string> take_buffered();
  bool fill();  // one read(); false at end of input or on error

  int fd_;
  std::string buffer_;
  bool eof_ = false;
};

// Frames and writes one message; false if the stream is closed.
bool write_message(int fd, const json& message);
// The framed text of one message (what write_message writes).
std::string frame(const json& message);

}  // namespace fx::tools::lsp
