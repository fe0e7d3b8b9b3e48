// Internal state of ParameterStore, shared by its source files (not installed).
#pragma once
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "fx/model/matrix_registers.h"
#include "fx/model/parameter_store.h"
#include "model_internal.h"

namespace fx::param_detail {

// `to` = the transpose of the 4x4 matrix at `from` (16 elements each, not overlapping):
// rows stored as columns, or columns as rows.
template <class T>
inline void transpose4x4(const T* from, T* to) {
  for (uint32_t r = 0; r < 4; ++r)
    for (uint32_t c = 0; c < 4; ++c) to[r * 4 + c] = from[c * 4 + r];
}

// Stores a row-stored 4x4 matrix (16 words) at `to` as four column registers (HLSL's
// default float4x4). The per-object matrices take this path on every draw.
inline void write_columns4x4(uint8_t* to, const uint32_t* from) {
#if defined(__SSE2__)
  __m128 r0 = _mm_loadu_ps(reinterpret_cast<const float*>(from));
  __m128 r1 = _mm_loadu_ps(reinterpret_cast<const float*>(from + 4));
  __m128 r2 = _mm_loadu_ps(reinterpret_cast<const float*>(from + 8));
  __m128 r3 = _mm_loadu_ps(reinterpret_cast<const float*>(from + 12));
  _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
  fxkit::detail::matrix_registers::store(to, r0, r1, r2, r3);
#else
  uint32_t columns[16];
  transpose4x4(from, columns);
  std::memcpy(to, columns, sizeof columns);
#endif
}

inline bool float_like(BaseType b) { return b == BaseType::half || b == BaseType::float32 || b == BaseType::float64; }
inline bool int_like(BaseType b) { return !float_like(b); }

inline uint32_t float_bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
inline float bits_float(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

// One component converted to the base type and encoded as a 32-bit word.
inline uint32_t encode(double v, BaseType b) {
  double c = convert_component(v, b);
  if (float_like(b)) return float_bits(static_cast<float>(c));
  if (b == BaseType::int32) return static_cast<uint32_t>(static_cast<int32_t>(c));
  return static_cast<uint32_t>(c);
}

inline void flatten_bases(const Type& t, std::vector<BaseType>& out) {
  for (uint32_t e = 0; e < t.element_count(); ++e) {
    if (t.cls == TypeClass::structure && t.structure) {
      for (const StructMember& m : t.structure->members) flatten_bases(m.type, out);
    } else {
      for (uint32_t i = 0; i < t.element_components(); ++i) out.push_back(t.base);
    }
  }
}

inline ParamStatus fail(ParamStatus::Code code, std::string message) { return {code, std::move(message)}; }

}  // namespace fx::param_detail

namespace fx {
using namespace param_detail;

struct ParameterStore::Impl {
  struct Node {
    std::string member;  // struct member name ("" for elements and top level)
    Type type;
    uint32_t parent = kNoIndex;
    uint32_t element = 0;  // index within an array parent
    uint32_t first_child = kNoIndex, child_count = 0;
    uint32_t top = 0;     // the top-level parameter node
    uint32_t offset = 0;  // first word (in the store's or the pool's words)
    uint32_t words = 0;
    uint32_t base_offset = 0;  // first entry in `bases` (pooled nodes too)
    bool pooled = false;
    uint32_t pool_entry = kNoIndex;
    uint32_t string_slot = kNoIndex;
    bool all_float = false, all_int = false;  // every component float-like / int-like
  };
  // One copy into a block: `words` 32-bit words to consecutive bytes from `dst`, read from
  // word `src` of the store's words (the pool's when `pooled`). `gather` reads every
  // `stride` words (one column of a row-stored matrix); `columns4x4` writes a whole
  // row-stored 4x4 matrix as four column registers (HLSL's default float4x4). bind_layout
  // plans them once, so write_block only copies.
  enum class RunKind : uint8_t { copy, gather, columns4x4 };
  struct WordRun {
    uint32_t src, dst, words, stride;
    bool pooled;
    RunKind kind;
  };
  // The runs [first, first + count) of top-level parameter `top` in a block, packed when
  // the parameter's change count was `packed_version`.
  struct RunGroup {
    uint32_t top = 0, first = 0, count = 0;
    uint64_t packed_version = 0;
    bool whole4x4 = false;  // one run holding a whole 4x4 float matrix: set_matrix may write it
  };
  // A pooled parameter's group in a block and the pool version it was packed from: a write
  // through another store is packed at the next write_block.
  struct PooledRuns {
    uint32_t entry, group;
    uint64_t packed_version;
  };
  // A block keeps its bytes packed (`packed`: padding zero) as the app's own constant
  // struct would be: write_block re-packs only the changed parameters' runs there, then
  // copies the block once.
  struct Block {
    uint32_t id = 0, size = 0;
    std::vector<WordRun> runs;  // planned by plan_runs, grouped by top-level parameter
    std::vector<RunGroup> groups;
    std::vector<uint8_t> packed;
    bool written = false;            // by write_block or update_block since bind_layout
    std::vector<uint32_t> group_of;  // per top-level parameter: its group here, or kNoIndex
    std::vector<PooledRuns> pooled;
    // `draw`: this block's DrawBlock (its seen_changes and fresh flag).
    bool changed(const DrawBlock& draw, const std::vector<uint64_t>& versions, const ParameterPool* pool) const {
      if (!written || draw.fresh) return true;
      for (const RunGroup& g : groups)
        if (versions[g.top] != g.packed_version) return true;
      for (const PooledRuns& p : pooled)
        if (pool->entries_[p.entry].version != p.packed_version) return true;
      return false;
    }
  };
  // The words of top-level `top` made current again after store_hot left them stale.
  void sync(uint32_t top) const {
    if (draw.hot[top].stale) [[unlikely]]
      sync_words(top);
  }
  [[gnu::noinline]] void sync_words(uint32_t top) const;
  // Recounts holders from the blocks' groups (after a bind).
  void count_holders();
  void sync_all() const {
    for (uint32_t top = 0; top < top_count; ++top) sync(top);
  }
  // Re-packs the runs of `b` whose parameter changed since they were packed; true when
  // anything was re-packed or the block was never handed out.
  bool refresh(Block& b, DrawBlock& draw);
  // The runs of member `m`, whose slice is of top-level node `top`.
  static void plan_runs(const Node& top, const BlockMemberLayout& m, uint32_t block_size, std::vector<WordRun>& runs);
  // Copies runs [first, first + count) of `b` from the words into b.packed.
  [[gnu::always_inline]] inline void pack(Block& b, uint32_t first, uint32_t count) const;
  // Stores `count` floats into node `i` (all float-like components); dirties its blocks only
  // when a bit changes.
  ParamStatus write_floats(uint32_t i, const float* v, size_t count);

  const EffectModel* model = nullptr;
  ParameterPool* pool = nullptr;
  std::vector<Node> nodes;
  uint32_t top_count = 0;               // nodes [0, top_count) are the model's parameters
  mutable std::vector<uint32_t> words;  // mutable: sync() refreshes the stale words of a hot matrix
  std::vector<BaseType> bases;          // per component, see Node::base_offset
  std::vector<std::string> strings;
  // Per word of `words` and per string slot: 1 when a setter wrote it (the application's
  // value), 0 while it holds the effect's default (creation, reset(), a reload's new
  // default). remap() carries the marked ones and lets the others take the new defaults.
  // Pooled words are not marked: the pool's values are the application's.
  std::vector<uint8_t> set_by_app;
  std::vector<uint8_t> string_set_by_app;
  // The per-object state (the header's DrawState): `blocks`' DrawBlocks (parallel), the hot
  // matrices, versions, change log and generation. Mutable: sync() clears a stale flag.
  mutable DrawState draw;
  std::vector<uint32_t> holders;  // per top-level parameter: how many bound blocks hold it
  static constexpr uint32_t kTouchLog = DrawState::kTouchLog;
  std::vector<Block> blocks;
  std::unordered_map<uint32_t, uint32_t> block_slot;
  std::unordered_map<std::string, uint32_t> by_name;
  std::unordered_map<std::string, uint32_t> by_semantic;  // lower-cased
  std::vector<std::vector<uint32_t>> translate;           // [old generation][old index] -> index
  std::unordered_map<uint64_t, std::string> removed;      // (generation << 32 | index) -> name

  uint32_t* data(const Node& n) { return n.pooled ? pool->words_.data() + n.offset : words.data() + n.offset; }
  const uint32_t* data(const Node& n) const {
    return n.pooled ? pool->words_.data() + n.offset : words.data() + n.offset;
  }

  // Creates the children of node `i` (members or elements), words already assigned.
  void expand(uint32_t i) {
    Node n = nodes[i];
    std::vector<std::pair<std::string, Type>> kids;
    if (n.type.is_array()) {
      Type e = n.type.element_type();
      for (uint32_t k = 0; k < n.type.array_dims[0]; ++k) kids.emplace_back("", e);
    } else if (n.type.cls == TypeClass::structure && n.type.structure) {
      for (const StructMember& m : n.type.structure->members) kids.emplace_back(m.name, m.type);
    }
    if (kids.empty()) return;
    uint32_t first = static_cast<uint32_t>(nodes.size());
    nodes[i].first_child = first;
    nodes[i].child_count = static_cast<uint32_t>(kids.size());
    uint32_t offset = n.offset;
    for (uint32_t k = 0; k < kids.size(); ++k) {
      Node c;
      c.member = kids[k].first;
      c.type = kids[k].second;
      c.parent = i;
      c.element = k;
      c.top = n.top;
      c.offset = offset;
      c.base_offset = n.base_offset + (offset - n.offset);
      c.words = c.type.component_count();
      c.pooled = n.pooled;
      c.pool_entry = n.pool_entry;
      offset += c.words;
      nodes.push_back(std::move(c));
    }
    for (uint32_t k = 0; k < kids.size(); ++k) classify(nodes[first + k]);
    for (uint32_t k = 0; k < kids.size(); ++k) expand(first + k);
  }

  std::string path(uint32_t i) const {
    const Node& n = nodes[i];
    if (n.parent == kNoIndex) return model->parameters[i].name;
    std::string base = path(n.parent);
    return n.member.empty() ? base + "[" + std::to_string(n.element) + "]" : base + "." + n.member;
  }

  // Resolves `p` to a node index, or reports why not.
  ParamStatus resolve(Param p, uint32_t& out) const {
    if (p.generation != draw.generation) {
      if (p.generation > draw.generation || p.generation >= translate.size())
        return fail(ParamStatus::invalid_handle, "handle from another store or generation");
      const auto& table = translate[p.generation];
      if (p.index >= table.size()) return fail(ParamStatus::invalid_handle, "invalid parameter handle");
      if (table[p.index] == kNoIndex) {
        auto it = removed.find(static_cast<uint64_t>(p.generation) << 32 | p.index);
        return fail(ParamStatus::removed, "parameter '" + (it == removed.end() ? std::string("?") : it->second) +
                                              "' was removed by a reload; the call did nothing");
      }
      out = table[p.index];
      sync(nodes[out].top);
      return {};
    }
    if (p.index >= nodes.size()) return fail(ParamStatus::invalid_handle, "invalid parameter handle");
    out = p.index;
    sync(nodes[out].top);  // every call through a handle sees current words
    return {};
  }

  void touch(const Node& n) {
    draw.log_change(n.top);
    if (n.pooled) ++pool->entries_[n.pool_entry].version;
  }

  // Marks node `n`'s words as the application's (set_by_app), or as defaults again. A node
  // without words (a texture) may sit past the end of an empty set_by_app.
  void mark_set(const Node& n, bool by_app) {
    if (!n.pooled && n.words) std::memset(set_by_app.data() + n.offset, by_app ? 1 : 0, n.words);
  }
  // Copies n.words floats into node `n` (all float-like: held as float bits, half and
  // double included) as the application's value and dirties its blocks only when a bit
  // changed (the same matrix set every frame leaves them clean).
  void store_floats(const Node& n, const float* v) {
    mark_set(n, true);
    if (copy_words(data(n), v, n.words)) touch(n);
  }
  // store_floats for one 4x4 matrix given column by column.
  void store_columns4x4(const Node& n, const float* v) {
    float rows[16];
    transpose4x4(v, rows);
    store_floats(n, rows);
  }
  // The copy of store_floats: true when a bit changed. One pass, no branch per word.
  [[gnu::always_inline]] static bool copy_words(uint32_t* d, const float* v, uint32_t words) {
    uint32_t w = 0;
    bool changed = false;
#if defined(__SSE2__)
    __m128i diff = _mm_setzero_si128();
    for (; w + 4 <= words; w += 4) {
      const __m128i now = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + w));
      const __m128i next = _mm_loadu_si128(reinterpret_cast<const __m128i*>(v + w));
      diff = _mm_or_si128(diff, _mm_xor_si128(now, next));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(d + w), next);
    }
    changed = _mm_movemask_epi8(_mm_cmpeq_epi32(diff, _mm_setzero_si128())) != 0xFFFF;
#endif
    for (; w < words; ++w) {
      uint32_t word;
      std::memcpy(&word, v + w, sizeof word);
      changed = changed || d[w] != word;
      d[w] = word;
    }
    return changed;
  }

  BaseType base_at(const Node& n, uint32_t word) const { return bases[n.base_offset + word]; }

  // Checks that the handle's components are all float-like (or all int-like).
  bool uniform_kind(const Node& n, bool want_float) const { return want_float ? n.all_float : n.all_int; }
  // Computes Node::all_float / all_int from the bases (once, at creation).
  void classify(Node& n) const {
    if (!n.type.is_numeric() && n.type.cls != TypeClass::structure) return;
    n.all_float = n.all_int = n.words > 0;
    for (uint32_t w = 0; w < n.words; ++w) {
      bool f = float_like(bases[n.base_offset + w]);
      n.all_float = n.all_float && f;
      n.all_int = n.all_int && !f;
    }
  }

  // Every node index of this store mapped to `other`'s node with the same path and type.
  std::vector<uint32_t> match_into(const Impl& other) const;

  std::string describe(uint32_t i) const {
    std::string text = "'";
    text.append(path(i)).append("' (").append(nodes[i].type.to_string()).append(")");
    return text;
  }
};

}  // namespace fx
