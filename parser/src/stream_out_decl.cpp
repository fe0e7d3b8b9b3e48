// parse_stream_out_decl: ConstructGSWithSO's declaration strings, entry by entry.
#include "fx/stream_out_decl.h"

#include <algorithm>
#include <cctype>

namespace fx {
namespace {

bool is_blank(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Parses one entry, `text` at `offset` in the declaration (blanks already trimmed).
void parse_entry(std::string_view text, uint32_t offset, StreamOutDecl& decl) {
  const auto problem = [&](size_t at, size_t length, std::string message) {
    decl.problems.push_back({offset + uint32_t(at), uint32_t(length), std::move(message)});
  };
  StreamOutEntry e;
  e.offset = offset;
  e.length = uint32_t(text.size());
  size_t at = 0;
  if (const size_t colon = text.find(':'); colon != std::string_view::npos) {
    std::string_view slot = text.substr(0, colon);
    while (!slot.empty() && is_blank(slot.back())) slot.remove_suffix(1);
    if (slot.empty() || slot.size() > 3 || !std::all_of(slot.begin(), slot.end(), is_digit)) {
      problem(0, colon, "output slot '" + std::string(slot) + "' is not a number (\"0:POSITION.xyz\")");
      return;
    }
    e.slot = uint32_t(std::stoul(std::string(slot)));
    if (e.slot >= kStreamOutSlots) {
      problem(0, slot.size(),
              "output slot " + std::to_string(e.slot) + " is out of range: there are " +
                  std::to_string(kStreamOutSlots) + " (0 to " + std::to_string(kStreamOutSlots - 1) + ")");
      return;
    }
    at = colon + 1;
    while (at < text.size() && is_blank(text[at])) ++at;
  }
  const size_t name_at = at;
  if (at < text.size() && text[at] == '$') ++at;
  while (at < text.size() && is_name_char(text[at])) ++at;
  std::string_view name = text.substr(name_at, at - name_at);
  if (name.empty() || name == "$") {
    problem(name_at, std::max<size_t>(1, text.size() - name_at),
            "expected a semantic or $SKIP, found '" + std::string(text.substr(name_at)) + "'");
    return;
  }
  if (name[0] == '$') {
    if (name != "$SKIP") {
      problem(name_at, name.size(), "unknown '" + std::string(name) + "': the only gap is $SKIP");
      return;
    }
  } else {
    size_t digits = name.size();
    while (digits > 0 && is_digit(name[digits - 1])) --digits;
    if (is_digit(name[0])) {
      problem(name_at, name.size(), "'" + std::string(name) + "' is no semantic (it starts with a digit)");
      return;
    }
    if (digits < name.size()) {
      if (name.size() - digits > 4) {
        problem(name_at + digits, name.size() - digits, "semantic index is too large");
        return;
      }
      e.semantic_index = uint32_t(std::stoul(std::string(name.substr(digits))));
    }
    e.semantic = std::string(name.substr(0, digits));
  }
  if (at < text.size()) {
    if (text[at] != '.') {
      problem(at, text.size() - at,
              "unexpected '" + std::string(text.substr(at)) + "' after '" + std::string(name) +
                  "' (a mask is written \".xyz\")");
      return;
    }
    std::string_view mask = text.substr(at + 1);
    if (mask.empty()) mask = "xyzw";  // "POSITION." is every component, as FX11 reads it
    size_t start = std::string_view::npos;
    for (std::string_view run : {std::string_view("xyzw"), std::string_view("rgba")})
      if (start == std::string_view::npos) start = run.find(mask);
    if (start == std::string_view::npos) {
      problem(at + 1, mask.size(),
              "component mask '" + std::string(mask) + "' is not a run of xyzw or rgba (\".xyz\", \".yz\", \".a\")");
      return;
    }
    e.start_component = uint32_t(start);
    e.component_count = uint32_t(mask.size());
    e.masked = text.size() > at + 1;
  }
  decl.entries.push_back(std::move(e));
}

}  // namespace

SourceRange stream_out_text_range(const SourceManager& sm, SourceRange literal, std::string_view text, uint32_t offset,
                                  uint32_t length) {
  const std::string_view written = literal.valid() && !sm.is_expansion(literal.begin)
                                       ? sm.text_at(literal.begin).substr(0, text.size() + 2)
                                       : std::string_view();
  const bool plain = written.size() == text.size() + 2 && written.front() == '"' &&
                     written.substr(1, text.size()) == text && written.back() == '"';
  if (!plain) return literal;
  SourceRange at = literal;
  at.begin = literal.begin.offset(1 + offset);
  at.end = at.begin.offset(std::max(1u, length));
  return at;
}

uint32_t StreamOutDecl::stride(uint32_t slot) const {
  uint32_t bytes = 0;
  for (const StreamOutEntry& e : entries)
    if (e.slot == slot) bytes += 4 * e.component_count;
  return bytes;
}

StreamOutDecl parse_stream_out_decl(std::string_view text) {
  StreamOutDecl decl;
  size_t begin = 0;
  while (begin <= text.size()) {
    size_t end = text.find(';', begin);
    if (end == std::string_view::npos) end = text.size();
    size_t first = begin, last = end;
    while (first < last && is_blank(text[first])) ++first;
    while (last > first && is_blank(text[last - 1])) --last;
    if (first < last) parse_entry(text.substr(first, last - first), uint32_t(first), decl);
    begin = end + 1;
  }
  return decl;
}

}  // namespace fx
