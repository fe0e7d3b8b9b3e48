// A stream-output declaration (ConstructGSWithSO's strings, "0:POSITION.xyz; $SKIP.x; NORMAL"):
// its entries, the bytes each output buffer gets per vertex, and what is wrong with it.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fx/source_manager.h"

namespace fx {

// One entry "[slot:] SEMANTIC[index][.mask]"; "$SKIP[.mask]" is a gap of that many components.
struct StreamOutEntry {
  uint32_t slot = 0;                // output buffer, 0 to kStreamOutSlots - 1
  std::string semantic;             // "" for a gap ($SKIP)
  uint32_t semantic_index = 0;      // TEXCOORD3 -> 3
  uint32_t start_component = 0;     // .yz -> 1
  uint32_t component_count = 4;     // .yz -> 2; no mask: 4
  bool masked = false;              // a mask is written (no mask: every component of the output)
  uint32_t offset = 0, length = 0;  // where the entry is written in the declaration text
};

// A problem in a declaration, at `offset` (`length` characters) in its text.
struct StreamOutProblem {
  uint32_t offset = 0, length = 0;
  std::string message;
};

// Output buffers a declaration may write (D3D11_SO_BUFFER_SLOT_COUNT).
inline constexpr uint32_t kStreamOutSlots = 4;

struct StreamOutDecl {
  std::vector<StreamOutEntry> entries;
  std::vector<StreamOutProblem> problems;
  // Bytes per vertex written to output buffer `slot` (4 per component, gaps included).
  uint32_t stride(uint32_t slot) const;
};

// Parses `text` as Direct3D 10/11 effects do: entries split at ';', blanks around them
// ignored, a mask a run of "xyzw" or "rgba", a slot digits before ':'. Every malformed entry
// is a problem; the entries that parse are kept.
StreamOutDecl parse_stream_out_decl(std::string_view text);

// Where characters [offset, offset + length) of the declaration `text` are in the source:
// inside the string literal at `literal` when it is written as one plain string, else the
// whole literal (a macro, a concatenation).
SourceRange stream_out_text_range(const SourceManager& sm, SourceRange literal, std::string_view text, uint32_t offset,
                                  uint32_t length);

}  // namespace fx
