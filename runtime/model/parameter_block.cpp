// ParameterStore: uniform-block layouts, dirty tracking, packing with D3D matrix rules,
// and remap() across reloads.
#include <algorithm>
#include <cstring>

#include "parameter_store_impl.h"

namespace fx {
namespace {

// Bytes one element of `t` occupies with D3D cbuffer rules when the layout gives no stride:
// every array element and every matrix register starts a 16-byte register.
uint32_t default_element_stride(const Type& t, uint32_t matrix_stride) {
  if (t.cls == TypeClass::matrix) {
    uint32_t registers = t.order == MatrixPacking::row_major ? t.rows : t.cols;
    return registers * matrix_stride;
  }
  return 16;
}

}  // namespace

std::vector<uint32_t> ParameterStore::Impl::match_into(const Impl& other) const {
  std::vector<uint32_t> out(nodes.size(), kNoIndex);
  // Top levels by name and type; children follow by position (same type => same shape).
  for (uint32_t i = 0; i < top_count; ++i) {
    auto it = other.by_name.find(model->parameters[i].name);
    if (it == other.by_name.end() || !other.nodes[it->second].type.same_as(nodes[i].type)) continue;
    std::vector<std::pair<uint32_t, uint32_t>> stack{{i, it->second}};
    while (!stack.empty()) {
      auto [a, b] = stack.back();
      stack.pop_back();
      out[a] = b;
      for (uint32_t k = 0; k < nodes[a].child_count && k < other.nodes[b].child_count; ++k)
        stack.emplace_back(nodes[a].first_child + k, other.nodes[b].first_child + k);
    }
  }
  return out;
}

// The copies that place one member's words into a block, with D3D matrix conventions:
// column_major puts HLSL column c in register c, row_major puts row r in register r.
// Words that would fall outside the member's range or the block are left out. Words are
// visited in destination order, so each register becomes one run (a whole row-major
// matrix with packed registers, one).
void ParameterStore::Impl::plan_runs(const Node& top, const BlockMemberLayout& m, uint32_t block_size,
                                     std::vector<WordRun>& runs) {
  const Type& type = m.slice.type;
  const Type elem = type.without_arrays();
  const uint32_t per = elem.component_count();
  const uint32_t count = type.element_count();
  const uint32_t from = top.offset + m.slice.first_word;
  const uint32_t mstride = m.matrix_stride ? m.matrix_stride : 16;
  const uint32_t astride = m.array_stride ? m.array_stride : default_element_stride(elem, mstride);
  const uint64_t limit = std::min<uint64_t>(static_cast<uint64_t>(m.offset) + m.size, block_size);
  auto put = [&](uint64_t at, uint32_t word) {
    if (at + 4 > limit) return;
    const auto dst = static_cast<uint32_t>(at);
    const uint32_t src = from + word;
    if (!runs.empty()) {
      WordRun& last = runs.back();
      if (last.kind != RunKind::columns4x4 && last.pooled == top.pooled && last.dst + last.words * 4 == dst &&
          src > last.src && (last.words == 1 || last.src + last.words * last.stride == src)) {
        if (last.words == 1) last.stride = src - last.src;
        last.kind = last.stride == 1 ? RunKind::copy : RunKind::gather;
        ++last.words;
        return;
      }
    }
    runs.push_back({src, dst, 1, 1, top.pooled, RunKind::copy});
  };
  for (uint32_t e = 0; e < count; ++e) {
    const uint64_t base = m.offset + static_cast<uint64_t>(e) * (count > 1 ? astride : 0);
    const uint32_t first = e * per;
    const bool columns = elem.cls == TypeClass::matrix && m.order == MatrixPacking::column_major;
    if (columns && elem.rows == 4 && elem.cols == 4 && mstride == 16 && base + 64 <= limit) {
      runs.push_back({from + first, static_cast<uint32_t>(base), 16, 4, top.pooled, RunKind::columns4x4});
    } else if (columns) {
      for (uint32_t c = 0; c < elem.cols; ++c)
        for (uint32_t r = 0; r < elem.rows; ++r) put(base + c * mstride + r * 4, first + r * elem.cols + c);
    } else if (elem.cls == TypeClass::matrix) {
      for (uint32_t r = 0; r < elem.rows; ++r)
        for (uint32_t c = 0; c < elem.cols; ++c) put(base + r * mstride + c * 4, first + r * elem.cols + c);
    } else {
      // Doubles are held as float; booleans are 32-bit 0/1 as HLSL's bool in a cbuffer.
      for (uint32_t k = 0; k < per; ++k) put(base + k * 4, first + k);
    }
  }
}

ParamStatus ParameterStore::bind_layout(uint32_t block, std::span<const BlockMemberLayout> members,
                                        uint32_t block_size) {
  Impl& s = *impl_;
  s.sync_all();  // the block being laid out again may be a hot one
  Impl::Block b;
  b.id = block;
  b.size = block_size;
  std::vector<std::pair<uint32_t, std::vector<Impl::WordRun>>> per_top;  // runs grouped by top-level node
  for (const BlockMemberLayout& m : members) {
    const ParameterSlice& slice = m.slice;
    if (slice.parameter >= s.top_count ||
        uint64_t(slice.first_word) + slice.type.component_count() > s.nodes[slice.parameter].words)
      return fail(ParamStatus::not_found,
                  "a member's slice lies outside the words of parameter #" + std::to_string(slice.parameter));
    if (m.offset > block_size || m.size > block_size - m.offset)
      return fail(ParamStatus::size_mismatch, "member '" + s.path(slice.parameter) + "' word " +
                                                  std::to_string(slice.first_word) + " lies outside the block (" +
                                                  std::to_string(block_size) + " bytes)");
    auto group =
        std::find_if(per_top.begin(), per_top.end(), [&](const auto& g) { return g.first == slice.parameter; });
    if (group == per_top.end()) group = per_top.insert(per_top.end(), {slice.parameter, {}});
    Impl::plan_runs(s.nodes[slice.parameter], m, block_size, group->second);
  }
  uint32_t slot;
  if (auto it = s.block_slot.find(block); it != s.block_slot.end()) {
    slot = it->second;
  } else {
    slot = static_cast<uint32_t>(s.blocks.size());
    s.blocks.emplace_back();
    s.block_slot.emplace(block, slot);
  }
  for (const auto& [top, runs] : per_top) {
    const auto group = static_cast<uint32_t>(b.groups.size());
    const Impl::Node& n = s.nodes[top];
    const bool whole4x4 = !n.pooled && n.all_float && n.type.cls == TypeClass::matrix && n.type.rows == 4 &&
                          n.type.cols == 4 && runs.size() == 1 && runs[0].src == n.offset && runs[0].words == 16 &&
                          (runs[0].kind == Impl::RunKind::columns4x4 || runs[0].kind == Impl::RunKind::copy);
    b.groups.push_back({top, static_cast<uint32_t>(b.runs.size()), static_cast<uint32_t>(runs.size()),
                        s.draw.versions[top], whole4x4});
    b.runs.insert(b.runs.end(), runs.begin(), runs.end());
    if (s.nodes[top].pooled) b.pooled.push_back({s.nodes[top].pool_entry, group, 0});
  }
  b.group_of.assign(s.top_count, kNoIndex);
  for (uint32_t g = 0; g < b.groups.size(); ++g) b.group_of[b.groups[g].top] = g;
  b.packed.assign(block_size, 0);
  s.pack(b, 0, static_cast<uint32_t>(b.runs.size()));
  for (Impl::PooledRuns& p : b.pooled) p.packed_version = s.pool->entries_[p.entry].version;
  s.blocks[slot] = std::move(b);
  s.draw.blocks.resize(s.blocks.size());
  uint64_t holds = 0;
  for (const Impl::RunGroup& g : s.blocks[slot].groups) holds |= uint64_t{1} << (g.top & 63);
  s.draw.blocks[slot] = {s.blocks[slot].packed.data(), block_size, false, false, s.draw.changes, holds};
  s.draw.hot.assign(s.top_count, {});  // `blocks` and `draw.blocks` may have moved
  s.count_holders();
  return {};
}

void ParameterStore::Impl::sync_words(uint32_t top) const {
  HotMatrix& h = draw.hot[top];
  const uint8_t* from = h.to;
  uint32_t* held = words.data() + h.words;
  uint32_t bytes[16];
  std::memcpy(bytes, from, sizeof bytes);
  if (h.columns) transpose4x4(bytes, held);  // column registers back to rows
  else std::memcpy(held, bytes, sizeof bytes);
  h.stale = false;
}

void ParameterStore::Impl::count_holders() {
  holders.assign(top_count, 0);
  for (const Block& b : blocks)
    for (const RunGroup& g : b.groups) ++holders[g.top];
}

inline void ParameterStore::Impl::pack(Block& b, uint32_t first, uint32_t count) const {
  const uint32_t* own = words.data();
  const uint32_t* pooled = pool ? pool->words_.data() : nullptr;
  uint8_t* to = b.packed.data();
  for (uint32_t i = first; i < first + count; ++i) {
    const WordRun& r = b.runs[i];
    const uint32_t* from = (r.pooled ? pooled : own) + r.src;
    switch (r.kind) {
      case RunKind::copy: std::memcpy(to + r.dst, from, r.words * sizeof(uint32_t)); break;
      case RunKind::gather:
        for (uint32_t k = 0; k < r.words; ++k) std::memcpy(to + r.dst + k * 4, from + k * r.stride, sizeof(uint32_t));
        break;
      case RunKind::columns4x4: write_columns4x4(to + r.dst, from); break;
    }
  }
}

bool ParameterStore::Impl::refresh(Block& b, DrawBlock& d) {
  bool changed = !b.written || d.fresh;
  b.written = true;
  d.quiet = b.pooled.empty();
  d.fresh = false;
  auto repack = [&](RunGroup& g) {
    const uint64_t version = draw.versions[g.top];
    if (version == g.packed_version) return;  // unchanged, written by store_hot, or touched twice
    sync(g.top);                              // another block may hold its value
    pack(b, g.first, g.count);
    g.packed_version = version;
    changed = true;
    // Hot only once the application has set the matrix: store_hot then writes nothing but
    // the application's values and has no set_by_app to record.
    if (g.whole4x4 && set_by_app[b.runs[g.first].src]) {
      const WordRun& r = b.runs[g.first];
      const bool shared = holders[g.top] > 1;
      draw.hot[g.top] = {&d,    &g.packed_version, b.packed.data() + r.dst, r.src, r.kind == RunKind::columns4x4, false,
                         shared};
    } else if (HotMatrix& h = draw.hot[g.top]; h.block) {
      h.others_outdated = false;  // this block is current: the next store_hot logs a change again
    }
  };
  const uint64_t changes = draw.changes;
  if (changes - d.seen_changes <= kTouchLog) {
    for (uint64_t k = d.seen_changes; k < changes; ++k)
      if (const uint32_t group = b.group_of[draw.touched[k % kTouchLog]]; group != kNoIndex) repack(b.groups[group]);
  } else {
    for (RunGroup& g : b.groups) repack(g);
  }
  d.seen_changes = changes;
  for (PooledRuns& p : b.pooled) {
    const uint64_t version = pool->entries_[p.entry].version;
    if (version == p.packed_version) continue;
    pack(b, b.groups[p.group].first, b.groups[p.group].count);
    p.packed_version = version;
    changed = true;
  }
  return changed;
}

BlockHandle ParameterStore::block(uint32_t block) const {
  auto it = impl_->block_slot.find(block);
  return it == impl_->block_slot.end() ? BlockHandle{} : BlockHandle{it->second};
}

bool ParameterStore::dirty(uint32_t block) const {
  const Impl& s = *impl_;
  auto it = s.block_slot.find(block);
  if (it == s.block_slot.end()) return false;
  return s.blocks[it->second].changed(s.draw.blocks[it->second], s.draw.versions, s.pool);
}

ParamStatus ParameterStore::write_block(uint32_t block, std::span<uint8_t> out) {
  Impl& s = *impl_;
  auto it = s.block_slot.find(block);
  if (it == s.block_slot.end())
    return fail(ParamStatus::not_found, "block " + std::to_string(block) + " has no layout");
  Impl::Block& b = s.blocks[it->second];
  if (out.size() < b.size)
    return fail(ParamStatus::size_mismatch, "block " + std::to_string(block) + " needs " + std::to_string(b.size) +
                                                " bytes, the buffer has " + std::to_string(out.size()));
  s.refresh(b, s.draw.blocks[it->second]);
  std::memcpy(out.data(), b.packed.data(), b.size);
  return {};
}

std::span<const uint8_t> ParameterStore::update_block_slow(BlockHandle block, bool& changed) {
  Impl& s = *impl_;
  changed = false;
  if (block.slot >= s.blocks.size()) return {};
  Impl::Block& b = s.blocks[block.slot];
  changed = s.refresh(b, s.draw.blocks[block.slot]);
  return {b.packed.data(), b.size};
}

std::vector<std::string> remap(const ParameterStore& old_store, ParameterStore& new_store) {
  const ParameterStore::Impl& o = *old_store.impl_;
  ParameterStore::Impl& n = *new_store.impl_;
  std::vector<uint32_t> map = o.match_into(n);
  std::vector<std::string> defaults_changed;
  // Matched top-level parameters: the words and strings the application set carry over
  // (and stay the application's); the others keep the new store's defaults. Pooled ones
  // live in the pool already; a value leaving the pool is carried as the application's.
  for (uint32_t i = 0; i < o.top_count; ++i) {
    uint32_t j = map[i];
    if (j == kNoIndex) continue;
    const auto& a = o.nodes[i];
    auto& b = n.nodes[j];
    bool default_changed = false;
    if (a.string_slot != kNoIndex && b.string_slot != kNoIndex) {
      if (o.string_set_by_app[a.string_slot]) {
        n.strings[b.string_slot] = o.strings[a.string_slot];
        n.string_set_by_app[b.string_slot] = 1;
      } else {
        default_changed = n.strings[b.string_slot] != o.strings[a.string_slot];
      }
    }
    if (!b.pooled && a.words == b.words && a.words != 0) {
      o.sync(i);
      n.sync(j);  // the new store may hold a value set_matrix wrote in place: words first
      const uint32_t* from = o.data(a);
      uint32_t* to = n.data(b);
      for (uint32_t w = 0; w < a.words; ++w) {
        if (a.pooled || o.set_by_app[a.offset + w]) {
          to[w] = from[w];
          n.set_by_app[b.offset + w] = 1;
        } else {
          default_changed = default_changed || to[w] != from[w];
        }
      }
      n.touch(b);
    }
    if (default_changed) defaults_changed.push_back(o.model->parameters[i].name);
  }
  n.draw.generation = o.draw.generation + 1;
  n.translate.assign(n.draw.generation, {});
  n.removed.clear();
  for (uint32_t g = 0; g < o.draw.generation; ++g) {
    const auto& older = o.translate[g];
    auto& t = n.translate[g];
    t.resize(older.size(), kNoIndex);
    for (size_t k = 0; k < older.size(); ++k) {
      if (older[k] != kNoIndex) t[k] = map[older[k]];
      if (t[k] == kNoIndex) {
        auto it = o.removed.find(static_cast<uint64_t>(g) << 32 | k);
        n.removed[static_cast<uint64_t>(g) << 32 | k] = it != o.removed.end()  ? it->second
                                                        : older[k] != kNoIndex ? o.path(older[k])
                                                                               : std::string("?");
      }
    }
  }
  n.translate[o.draw.generation] = map;
  for (size_t k = 0; k < map.size(); ++k)
    if (map[k] == kNoIndex)
      n.removed[static_cast<uint64_t>(o.draw.generation) << 32 | k] = o.path(static_cast<uint32_t>(k));
  return defaults_changed;
}

}  // namespace fx
