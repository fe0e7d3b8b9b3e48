#include "fx/source_manager.h"

#include <algorithm>

namespace fx {
namespace {
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
constexpr uint32_t kScratchChunk = 64 * 1024;
}  // namespace

SourceManager::SourceManager() { entries_.emplace_back(); }

BufferId SourceManager::append(Entry e) {
  e.base = next_base_;
  // +1 so that the one-past-the-end position of a buffer still belongs to it.
  next_base_ += e.size + 1;
  entries_.push_back(std::move(e));
  return static_cast<BufferId>(entries_.size() - 1);
}

BufferId SourceManager::add_buffer(std::string name, std::string contents, SourceLocation included_from) {
  Entry e;
  e.size = static_cast<uint32_t>(contents.size());
  e.name = std::move(name);
  e.text = std::make_unique<std::string>(std::move(contents));
  e.included_from = included_from;
  return append(std::move(e));
}

SourceLocation SourceManager::add_scratch(std::string_view text, SourceLocation origin) {
  // Scratch chunks reserve their address range and capacity up front, so earlier
  // string_views into them stay valid.
  bool fits = scratch_ != 0 && entries_[scratch_].text->size() + text.size() + 1 <= entries_[scratch_].size;
  if (!fits) {
    Entry e;
    e.size = std::max<uint32_t>(kScratchChunk, static_cast<uint32_t>(text.size()) + 1);
    e.name = "<scratch space>";
    e.scratch = true;
    e.text = std::make_unique<std::string>();
    e.text->reserve(e.size);
    scratch_ = append(std::move(e));
  }
  Entry& s = entries_[scratch_];
  uint32_t offset = static_cast<uint32_t>(s.text->size());
  s.text->append(text);
  s.text->push_back('\n');
  (void)origin;
  return {s.base + offset};
}

const std::string_view* SourceManager::keep_long_spelling(std::string_view spelling) {
  return &long_spellings_.emplace_back(spelling);
}

SourceLocation SourceManager::add_expansion(MacroExpansion expansion, uint32_t length) {
  Entry e;
  e.size = length;
  e.name = expansion.macro_name;
  e.expansion = std::make_unique<MacroExpansion>(std::move(expansion));
  return {entries_[append(std::move(e))].base};
}

void SourceManager::add_line_directive(SourceLocation at_next_line, uint32_t line, std::string file) {
  BufferId id = buffer_of(at_next_line);
  if (id == 0) return;
  Entry& e = entries_[id];
  e.line_directives.push_back({at_next_line.raw - e.base, line, std::move(file)});
}

const SourceManager::Entry* SourceManager::entry(SourceLocation loc) const {
  BufferId id = buffer_of(loc);
  return id ? &entries_[id] : nullptr;
}

const SourceManager::Entry& SourceManager::entry_checked(BufferId id) const {
  return id < entries_.size() ? entries_[id] : entries_[0];
}

BufferId SourceManager::buffer_of(SourceLocation loc) const {
  if (!loc.valid() || loc.raw >= next_base_) return 0;
  auto it = std::upper_bound(entries_.begin() + 1, entries_.end(), loc.raw,
                             [](uint32_t raw, const Entry& e) { return raw < e.base; });
  return static_cast<BufferId>((it - entries_.begin()) - 1);
}

SourceLocation SourceManager::location(BufferId id, uint32_t offset) const {
  if (id == 0 || id >= entries_.size()) return {};
  return {entries_[id].base + std::min(offset, entries_[id].size)};
}

bool SourceManager::is_expansion(SourceLocation loc) const {
  const Entry* e = entry(loc);
  return e && e->expansion;
}

uint32_t SourceManager::offset_in_buffer(SourceLocation loc) const {
  const Entry* e = entry(loc);
  return e ? loc.raw - e->base : 0;
}

std::string_view SourceManager::buffer_name(BufferId id) const { return entry_checked(id).name; }

std::string_view SourceManager::buffer_text(BufferId id) const {
  const Entry& e = entry_checked(id);
  return e.text ? std::string_view(*e.text) : std::string_view();
}

SourceLocation SourceManager::included_from(BufferId id) const { return entry_checked(id).included_from; }

const MacroExpansion* SourceManager::expansion_of(SourceLocation loc) const {
  const Entry* e = entry(loc);
  return e ? e->expansion.get() : nullptr;
}

SourceLocation SourceManager::spelling_location(SourceLocation loc) const {
  // Bounded: each step moves to an entry created earlier than the current one.
  for (const Entry* e = entry(loc); e && e->expansion; e = entry(loc))
    loc = e->expansion->spelling.offset(loc.raw - e->base);
  return loc;
}

bool SourceManager::is_scratch(SourceLocation loc) const {
  const Entry* e = entry(loc);
  return e && e->scratch;
}

const MacroExpansion* SourceManager::written_in_macro(SourceLocation loc, SourceLocation& spelled) const {
  const MacroExpansion* macro = nullptr;
  for (const Entry* e = entry(loc); e && e->expansion; e = entry(loc)) {
    macro = e->expansion.get();
    loc = e->expansion->spelling.offset(loc.raw - e->base);
  }
  if (!macro || is_scratch(loc)) return nullptr;
  spelled = loc;
  return macro;
}

SourceLocation SourceManager::file_location(SourceLocation loc) const {
  for (const Entry* e = entry(loc); e && e->expansion; e = entry(loc)) loc = e->expansion->expansion.begin;
  return loc;
}

const std::vector<uint32_t>& SourceManager::line_starts(const Entry& e) const {
  if (e.line_starts.empty() && e.text) {
    const std::string& t = *e.text;
    // A UTF-8 byte-order mark is not part of line 1: columns count from after it.
    e.line_starts.push_back(t.starts_with(kByteOrderMark) ? static_cast<uint32_t>(kByteOrderMark.size()) : 0);
    for (uint32_t i = 0; i < t.size(); ++i)
      if (t[i] == '\n') e.line_starts.push_back(i + 1);
  }
  return e.line_starts;
}

PresumedLocation SourceManager::physical(SourceLocation loc) const {
  loc = file_location(loc);
  const Entry* e = entry(loc);
  if (!e || !e->text) return {};
  uint32_t offset = loc.raw - e->base;
  const auto& starts = line_starts(*e);
  offset = std::max(offset, starts.front());  // inside a byte-order mark: where line 1 starts
  auto it = std::upper_bound(starts.begin(), starts.end(), offset);
  uint32_t line = static_cast<uint32_t>(it - starts.begin());
  return {e->name, line, offset - starts[line - 1] + 1};
}

PresumedLocation SourceManager::presumed(SourceLocation loc) const {
  PresumedLocation p = physical(loc);
  const Entry* e = entry(file_location(loc));
  if (!p.valid() || e->line_directives.empty()) return p;
  uint32_t offset = file_location(loc).raw - e->base;
  const LineDirective* active = nullptr;
  for (const LineDirective& d : e->line_directives)
    if (d.offset <= offset) active = &d;
  if (!active) return p;
  const auto& starts = line_starts(*e);
  uint32_t directive_line =
      static_cast<uint32_t>(std::upper_bound(starts.begin(), starts.end(), active->offset) - starts.begin());
  p.line = active->line + (p.line - directive_line);
  if (!active->file.empty()) p.file = active->file;
  // Later directives without a file name keep the name of the latest one that had one.
  if (active->file.empty())
    for (const LineDirective& d : e->line_directives)
      if (d.offset <= offset && !d.file.empty()) p.file = d.file;
  return p;
}

std::string_view SourceManager::line_text(SourceLocation loc) const {
  loc = file_location(loc);
  const Entry* e = entry(loc);
  if (!e || !e->text) return {};
  std::string_view text = *e->text;
  size_t offset = loc.raw - e->base;
  size_t newline = offset == 0 ? std::string_view::npos : text.rfind('\n', offset - 1);
  size_t begin = newline == std::string_view::npos ? line_starts(*e).front() : newline + 1;
  size_t end = text.find('\n', offset);
  if (end == std::string_view::npos) end = text.size();
  std::string_view line = text.substr(begin, end - begin);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

std::string_view SourceManager::text_at(SourceLocation loc) const {
  loc = spelling_location(loc);
  const Entry* e = entry(loc);
  if (!e || !e->text) return {};
  return std::string_view(*e->text).substr(loc.raw - e->base);
}

}  // namespace fx
