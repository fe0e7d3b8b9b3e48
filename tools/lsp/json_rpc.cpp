// Message framing for the language server (json_rpc.h).
#include "json_rpc.h"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

namespace fx::tools::lsp {

std::optional<std::string> MessageReader::take_buffered() {
  const size_t header_end = buffer_.find("\r\n\r\n");
  if (header_end == std::string::npos) return std::nullopt;
  size_t length = 0;
  bool has_length = false;
  for (size_t at = 0; at < header_end;) {
    size_t eol = buffer_.find("\r\n", at);
    if (eol == std::string::npos || eol > header_end) eol = header_end;
    const std::string line = buffer_.substr(at, eol - at);
    constexpr std::string_view kLength = "content-length:";
    if (line.size() > kLength.size()) {
      std::string lower = line.substr(0, kLength.size());
      for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (lower == kLength) {
        length = std::strtoull(line.c_str() + kLength.size(), nullptr, 10);
        has_length = true;
      }
    }
    at = eol + 2;
  }
  const size_t body = header_end + 4;
  if (!has_length) {  // a header without a length: drop it rather than wait forever
    buffer_.erase(0, body);
    return std::string();
  }
  if (buffer_.size() < body + length) return std::nullopt;
  std::string message = buffer_.substr(body, length);
  buffer_.erase(0, body + length);
  return message;
}

bool MessageReader::fill() {
  char chunk[65536];
  for (;;) {
    const ssize_t n = ::read(fd_, chunk, sizeof chunk);
    if (n > 0) {
      buffer_.append(chunk, static_cast<size_t>(n));
      return true;
    }
    if (n < 0 && errno == EINTR) continue;
    eof_ = true;
    return false;
  }
}

std::optional<std::string> MessageReader::read() {
  for (;;) {
    if (auto message = take_buffered()) return message;
    if (eof_ || !fill()) return std::nullopt;
  }
}

bool MessageReader::more_waiting() {
  if (buffer_.find("\r\n\r\n") != std::string::npos) {
    // A header is buffered: is its body complete, or is more of it arriving?
    std::string copy = buffer_;
    if (take_buffered()) {
      buffer_ = std::move(copy);
      return true;
    }
  }
  if (eof_) return false;
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0 && (p.revents & (POLLIN | POLLHUP));
}

std::string frame(const json& message) {
  const std::string body = message.dump(-1, ' ', false, json::error_handler_t::replace);
  return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

bool write_message(int fd, const json& message) {
  const std::string text = frame(message);
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace fx::tools::lsp
