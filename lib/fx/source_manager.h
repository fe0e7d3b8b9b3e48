// Owns every source buffer (files, include instances, scratch text), macro expansion
// record and view of a token spelling too long for fx::Token to hold, and maps compact
// SourceLocations back to file, line and column.
#pragma once
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "fx/source_location.h"

namespace fx {

using BufferId = uint32_t;  // index of a buffer or expansion entry; 0 is invalid

// Where a location is, after #line directives: what an editor should jump to.
struct PresumedLocation {
  std::string_view file;  // name as given (#line may rename)
  uint32_t line = 0;      // 1-based
  uint32_t column = 0;    // 1-based, in bytes
  bool valid() const { return line != 0; }
};

// One macro expansion: tokens spelled in the macro body (spelling) that were produced
// where the macro was invoked (expansion).
struct MacroExpansion {
  std::string macro_name;
  SourceLocation spelling;  // start of the macro body in its definition
  SourceRange expansion;    // the invocation, e.g. FOO(a, b)
};

class SourceManager {
 public:
  SourceManager();
  SourceManager(const SourceManager&) = delete;
  SourceManager& operator=(const SourceManager&) = delete;

  // Adds a buffer: a file (name as shown to users) or a new instance of it included from
  // `included_from`. Returns its id; location(id, 0) is its first character.
  BufferId add_buffer(std::string name, std::string contents, SourceLocation included_from = {});
  // Copies text into scratch space (for pasted and stringified tokens) and returns its
  // location; the text stays valid for the SourceManager's lifetime.
  SourceLocation add_scratch(std::string_view text, SourceLocation origin);
  // Records a macro expansion covering `length` characters of the macro body.
  SourceLocation add_expansion(MacroExpansion expansion, uint32_t length);
  // Keeps a view of a token spelling (text this SourceManager owns) too long for the
  // 16-bit length fx::Token holds; the view stays at its address for the SourceManager's
  // lifetime, so the token can point at it.
  const std::string_view* keep_long_spelling(std::string_view spelling);
  // Remaps following lines of a buffer, as `#line line "file"` does (`file` empty keeps it).
  void add_line_directive(SourceLocation at_next_line, uint32_t line, std::string file);

  SourceLocation location(BufferId id, uint32_t offset) const;
  BufferId buffer_of(SourceLocation loc) const;
  bool is_expansion(SourceLocation loc) const;
  uint32_t offset_in_buffer(SourceLocation loc) const;

  std::string_view buffer_name(BufferId id) const;
  std::string_view buffer_text(BufferId id) const;
  // Where the buffer was #included from (invalid for top-level files and scratch).
  SourceLocation included_from(BufferId id) const;
  // For an expansion location: the record; nullptr otherwise.
  const MacroExpansion* expansion_of(SourceLocation loc) const;

  // Follows macro expansions to where the characters are written (the macro body).
  SourceLocation spelling_location(SourceLocation loc) const;
  // The macro definition a macro-expanded location's characters are written in: the last
  // expansion spelling_location() follows, with `spelled` set to where it leads. nullptr
  // when `loc` is no expansion location, or when the preprocessor made the characters (a
  // pasted or stringized token lives in scratch space, which no user wrote).
  const MacroExpansion* written_in_macro(SourceLocation loc, SourceLocation& spelled) const;
  // True for text the preprocessor made (add_scratch): pasted and stringized tokens.
  bool is_scratch(SourceLocation loc) const;
  // Follows macro expansions to where the user wrote the invocation (file text).
  SourceLocation file_location(SourceLocation loc) const;
  // File, line and column of loc's file location, honouring #line.
  PresumedLocation presumed(SourceLocation loc) const;
  // The same without #line remapping: the real file on disk.
  PresumedLocation physical(SourceLocation loc) const;
  // The whole source line containing loc's file location, without its newline.
  std::string_view line_text(SourceLocation loc) const;
  // The characters at loc's spelling location (for a token: up to the end of its buffer).
  std::string_view text_at(SourceLocation loc) const;

  size_t buffer_count() const { return entries_.size(); }

 private:
  struct LineDirective {
    uint32_t offset;  // first character of the remapped line
    uint32_t line;
    std::string file;
  };
  struct Entry {
    uint32_t base = 0;  // first raw location value
    uint32_t size = 0;  // characters (+1 for the end position)
    std::string name;
    std::unique_ptr<std::string> text;  // null for expansions
    SourceLocation included_from;
    std::unique_ptr<MacroExpansion> expansion;  // non-null for expansions
    mutable std::vector<uint32_t> line_starts;  // computed on demand
    std::vector<LineDirective> line_directives;
    bool scratch = false;  // preprocessor-made text (add_scratch)
  };
  const Entry* entry(SourceLocation loc) const;
  const Entry& entry_checked(BufferId id) const;
  const std::vector<uint32_t>& line_starts(const Entry& e) const;
  BufferId append(Entry e);

  std::vector<Entry> entries_;  // entries_[0] is a sentinel
  uint32_t next_base_ = 1;
  BufferId scratch_ = 0;
  std::deque<std::string_view> long_spellings_;  // a deque never moves its elements
};

}  // namespace fx
