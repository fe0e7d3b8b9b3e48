// libFuzzer target: arbitrary bytes as a DDS file through the container reader and, for
// block-compressed data, the BC1-BC5 decoder of every subresource slice. Any crash, hang,
// sanitizer report or out-of-memory is a bug; rejection with a diagnostic is fine.
#include <cstddef>
#include <cstdint>
#include <span>

#include "fx/dds.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fx::DiagnosticSink sink;
  // Any input is a DDS file to the reader: most random bytes lack the magic, so it is supplied.
  std::vector<uint8_t> bytes = {'D', 'D', 'S', ' '};
  bytes.insert(bytes.end(), data, data + size);
  auto texture = fx::decode_dds(bytes, sink);
  if (!texture || !fx::bc_decodable(texture->format)) return 0;
  for (const fx::DdsSubresource& s : texture->subresources) {
    const uint64_t slice = s.size / s.depth;
    const std::span<const uint8_t> all(texture->data);
    fx::decode_bc_rgba8(texture->format, all.subspan(s.offset, slice), s.width, s.height);
  }
  return 0;
}
