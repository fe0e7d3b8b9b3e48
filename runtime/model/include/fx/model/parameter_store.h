// Parameter values of one effect instance: index-based handles, O(1) typed set/get,
// lookup by name and semantic, defaults applied at creation, dirty tracking per uniform
// block and packing into block bytes with D3D matrix rules; `shared` parameters live in a
// ParameterPool several stores reference (as D3DX effect pools). See docs/parameters.md.
// One thread at a time, getters included: a getter may copy back a matrix that set_matrix
// wrote only into its hot block (docs/rendering.md, uniform blocks).
// Stable: Param, ParamStatus, ParameterStore's public functions, ParameterPool, remap.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "fx/model/draw_state.h"
#include "fx/model/effect_model.h"
#include "fx/model/matrix_order.h"
#include "fx/model/param.h"
#include "fx/model/parameter_slice.h"

namespace fx {

using fxkit::Param;  // fx/model/param.h: one handle type for the store and the public API

// A bound uniform block of one store (ParameterStore::block).
struct BlockHandle {
  uint32_t slot = kNoIndex;
  bool valid() const { return slot != kNoIndex; }
};

// Result of a set/get. `removed` is a warning (the parameter went away in a reload; the
// call did nothing); the others are errors. Never UB: a bad call changes nothing.
struct ParamStatus {
  enum Code : uint8_t { ok, invalid_handle, removed, type_mismatch, size_mismatch, not_found };
  Code code = ok;
  std::string message;
  explicit operator bool() const { return code == ok; }
};

// Placement of one parameter (or struct member, array element) in a uniform block:
// fx/compile/uniform_layout.h lays a linked program's blocks out so.
struct BlockMemberLayout {
  ParameterSlice slice;                               // the words it holds (find_slice)
  uint32_t offset = 0;                                // bytes
  uint32_t size = 0;                                  // bytes, arrays included
  uint32_t array_stride = 0;                          // bytes between array elements (0: not an array)
  uint32_t matrix_stride = 16;                        // bytes between registers of a matrix
  MatrixPacking order = MatrixPacking::column_major;  // HLSL meaning (see docs/parameters.md)
};

// Storage of `shared` parameters, referenced by every store created with it. Matching is
// by name and type; a store whose shared parameter has another type gets its own storage
// and a `shared-type-mismatch` diagnostic.
class ParameterPool {
 public:
  ParameterPool() = default;
  ParameterPool(const ParameterPool&) = delete;
  ParameterPool& operator=(const ParameterPool&) = delete;
  // Number of shared parameters held.
  size_t size() const { return entries_.size(); }

 private:
  friend class ParameterStore;
  struct Entry {
    std::string name;
    Type type;
    uint32_t offset = 0;  // into words_
    uint32_t count = 0;
    uint64_t version = 1;  // bumped on every write, for the stores' dirty tracking
  };
  std::vector<Entry> entries_;
  std::unordered_map<std::string, uint32_t> by_name_;
  std::vector<uint32_t> words_;
};

class ParameterStore {
 public:
  // Creates the values of `model`'s parameters (defaults applied). `shared` ones go to
  // `pool` when given (the first store to declare one sets its default).
  explicit ParameterStore(const EffectModel& model, ParameterPool* pool = nullptr, DiagnosticSink* diags = nullptr);
  ParameterStore(const ParameterStore&) = delete;
  ParameterStore& operator=(const ParameterStore&) = delete;
  ParameterStore(ParameterStore&&) noexcept;
  ParameterStore& operator=(ParameterStore&&) noexcept;
  ~ParameterStore();

  // Lookup (top-level parameters). find: exact name; by_semantic: case-insensitive.
  Param find(std::string_view name) const;
  Param by_semantic(std::string_view semantic) const;
  // A struct member / array element of `p`; invalid Param when there is none.
  Param member(Param p, std::string_view name) const;
  Param element(Param p, uint32_t i) const;
  // The handle as the current generation sees it (translates handles from before remap()).
  Param current(Param p) const;

  // Type, name ("light.dir", "bones[3]") of a handle; nullptr / "" when invalid.
  const Type* type(Param p) const;
  std::string name(Param p) const;
  size_t parameter_count() const;

  // Setters: the value's shape must match the handle's type exactly (a float3 takes 3
  // floats; an array of 4 float4 takes 16; int/bool handles take ints/bools; float handles
  // take floats). bool and int handles also accept the other integer-like kind. A set that
  // changes no bit leaves the parameter's blocks clean. What a setter writes is the
  // application's value: remap() keeps it where it would otherwise take a new default.
  ParamStatus set(Param p, float v);
  ParamStatus set(Param p, int32_t v);
  ParamStatus set(Param p, bool v);
  ParamStatus set(Param p, std::span<const float> v);
  ParamStatus set(Param p, std::span<const int32_t> v);
  // A matrix (or matrix array) given as 16-float host matrices (or rows*cols). Inline so
  // that the per-object call (a current handle, one matrix of the right count, either
  // order) returns without building a status: the caller's empty ParamStatus folds away.
  ParamStatus set_matrix(Param p, std::span<const float> v, fxkit::MatrixOrder order = fxkit::MatrixOrder::row_major) {
    if (store_hot(p, v, order) || set_matrix_fast(p, v.data(), v.size(), order)) return {};
    return set_matrix_checked(p, v, order);
  }
  ParamStatus set_string(Param p, std::string_view v);
  // Getters fill `out` (its size must match the handle's component count).
  ParamStatus get(Param p, float& out) const;
  ParamStatus get(Param p, int32_t& out) const;
  ParamStatus get(Param p, bool& out) const;
  ParamStatus get(Param p, std::span<float> out) const;
  ParamStatus get(Param p, std::span<int32_t> out) const;
  ParamStatus get_matrix(Param p, std::span<float> out, fxkit::MatrixOrder order = fxkit::MatrixOrder::row_major) const;
  ParamStatus get_string(Param p, std::string& out) const;
  // Restores the default of `p` (zero when it has none); from then on remap() gives `p` the
  // new file's default, as for a parameter never set.
  ParamStatus reset(Param p);

  // Uniform blocks (ids chosen by the caller, e.g. reflection's block index). A member
  // whose slice lies outside its parameter's words or the block fails the whole layout.
  ParamStatus bind_layout(uint32_t block, std::span<const BlockMemberLayout> members, uint32_t block_size);
  // The bound block `block` as a handle for per-draw calls (no id lookup); invalid when
  // the id has no layout. It stays valid for the store's life (a rebind keeps it).
  BlockHandle block(uint32_t block) const;
  // True when a parameter in `block` changed since the last write_block / update_block.
  bool dirty(uint32_t block) const;
  // Packs the block's parameters into `out` (at least the bound block size) and clears
  // its dirty flag. Bytes of the block no parameter covers are zeroed, so `out` may be
  // recycled memory (a uniform ring slot); bytes past the block size are left untouched.
  ParamStatus write_block(uint32_t block, std::span<uint8_t> out);
  // dirty + write_block in one pass: re-packs what changed and returns the block's bytes
  // (its bound size, padding zero; valid until the next call on this store), `changed`
  // telling whether they differ from what the last update or write returned. Empty for
  // an invalid handle.
  // Inline: a renderer calls it per block and draw, and a block none of whose parameters
  // was logged since its last update (set_matrix values written into it aside) needs no
  // call.
  std::span<const uint8_t> update_block(BlockHandle block, bool& changed) {
    if (const DrawBlock* b = draw_->up_to_date(block.slot, changed)) [[likely]]
      return {b->bytes, b->size};
    return update_block_slow(block, changed);
  }

  uint32_t generation() const;
  // The per-object state store_hot and update_block read, for fxkit::Effect's inline
  // set_matrix (valid for the store's life, a move included).
  fxkit::detail::DrawState* draw_state() { return draw_; }

 private:
  friend std::vector<std::string> remap(const ParameterStore& old_store, ParameterStore& new_store);
  // set_matrix's per-object path, inline: a current handle of a float4x4 with a hot block
  // (below), 16 floats. True when it stored the value (nothing to report).
  bool store_hot(Param p, std::span<const float> v, fxkit::MatrixOrder order);
  // set_matrix's out-of-line path for a current handle without a hot block (none yet, or
  // a set through the words ended it): into the words when the floats fit the node as they are; false
  // sends the call to the checked path.
  bool set_matrix_fast(Param p, const float* v, size_t count, fxkit::MatrixOrder order);
  // Everything else, with the status that says what is wrong.
  ParamStatus set_matrix_checked(Param p, std::span<const float> v, fxkit::MatrixOrder order);
  // update_block's way for a block with logged changes or pooled parameters (re-packed),
  // or an invalid handle (empty).
  std::span<const uint8_t> update_block_slow(BlockHandle block, bool& changed);

  // The state the per-object calls (store_hot, update_block) read, declared in a header of
  // its own (fx/model/draw_state.h) so that they inline into a renderer's loop, also through
  // the public API. Impl owns it (draw_ points into *impl_, so a move keeps it) and keeps it
  // current; docs/rendering.md tells the whole story.
  using DrawBlock = fxkit::detail::DrawBlock;
  using HotMatrix = fxkit::detail::HotMatrix;
  using DrawState = fxkit::detail::DrawState;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  DrawState* draw_ = nullptr;
};

inline bool ParameterStore::store_hot(Param p, std::span<const float> v, fxkit::MatrixOrder order) {
  return v.size() == 16 && draw_->store_hot(p.index, p.generation, v.data(), order == fxkit::MatrixOrder::column_major);
}

// After a reload: for every parameter of `old_store` that still exists in `new_store` with
// the same name and type, copies the values the application set (through a setter, since
// creation or the last reset()) and leaves the rest at `new_store`'s defaults, the edited
// file's. Makes handles issued by `old_store` (any generation) valid on `new_store`;
// handles of removed parameters become inert (calls return ParamStatus::removed naming the
// parameter). Returns the names of the top-level parameters whose value changed because
// the new default differs from the old value. Shared (pooled) parameters keep the pool's
// value and are never listed.
std::vector<std::string> remap(const ParameterStore& old_store, ParameterStore& new_store);

}  // namespace fx
