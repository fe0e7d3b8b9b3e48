// fxkit::detail::DrawState: a parameter store's per-object state (each bound uniform block's
// packed bytes, the hot matrices, the versions and change log), declared here so that
// Effect::set_matrix and the store's update_block inline into an engine's draw loop.
// Internal to fxkit: the layout may change in any release; use fxkit::Effect.
#pragma once
#include <cstdint>
#include <vector>

#include "fx/model/matrix_registers.h"

namespace fxkit::detail {

struct alignas(32) DrawBlock {     // 32 bytes: a slot's address is a shift
  const uint8_t* bytes = nullptr;  // the block's packed bytes
  uint32_t size = 0;
  bool quiet = false;         // written since its layout was bound, no pooled parameter: only
                              // logged changes or store_hot's writes into `bytes` (fresh) can
                              // change it
  bool fresh = false;         // store_hot wrote into `bytes` since they were last handed out
  uint64_t seen_changes = 0;  // DrawState::changes when the block was last brought up to date
  // The top-level parameters the block holds, bit `index % 64` each: a logged change whose
  // bit is clear is not this block's (a set bit may be another parameter's).
  uint64_t holds = 0;
  bool may_hold(uint32_t top) const { return (holds >> (top & 63)) & 1; }
};

// A per-object matrix (World, WorldViewProjection): when a block re-packs a whole 4x4 float
// group, that block becomes its parameter's hot block, and store_hot writes the next value
// straight into the block's bytes, so drawing object after object with one pass re-packs
// nothing. Only a matrix the application has set becomes hot, so store_hot writes only the
// application's values and records nothing for reloads; a reset or a set through the words
// ends it. Other blocks holding the matrix learn of it from one logged change (see
// others_outdated) and re-pack it from the words. The pointers are into the store's
// blocks, which clears every HotMatrix when it may move them; the next re-pack makes one
// again.
struct HotMatrix {
  DrawBlock* block = nullptr;          // the hot block's; none when null
  uint64_t* packed_version = nullptr;  // the version its bytes hold (see outdate_others)
  uint8_t* to = nullptr;               // the matrix's first byte in the block
  uint32_t words = 0;                  // the parameter's first word in the store
  bool columns = false;                // the block holds column registers (HLSL's default)
  // The value is in the hot block's bytes only: store_hot leaves the store's words behind,
  // as D3DX effects keep a constant buffer's shadow as the one copy; the store brings them
  // back before anything else reads or partly writes them.
  bool stale = false;
  // Other bound blocks hold the parameter (another pass's or stage's): the first store_hot
  // after one of them re-packed it logs one change of the parameter for them
  // (others_outdated), so that they re-pack just it at their next update; the store_hot
  // calls after it log nothing, and the blocks that do not hold the matrix (the pass's
  // other stage, usually) have no change to look at.
  bool shared = false;
  bool others_outdated = false;
};

struct DrawState {
  // Ordered so that what store_hot and up_to_date read first shares a cache line.
  uint32_t generation = 0;  // of the handles the store issues now
  static constexpr uint32_t kTouchLog = 16;
  // The last kTouchLog changes: touched[k % kTouchLog] is the top-level parameter of change
  // k (`changes` so far), so a block refreshed a few changes ago re-packs just those instead
  // of comparing every parameter's version.
  uint64_t changes = 0;
  std::vector<HotMatrix> hot;     // per top-level parameter
  std::vector<DrawBlock> blocks;  // by block slot
  // Per top-level parameter, bumped on every change another block may need: a block
  // compares it with what it packed, so a set costs the same however many blocks hold the
  // parameter.
  std::vector<uint64_t> versions;
  uint32_t touched[kTouchLog] = {};

  // update_block's inline way: block `slot` when no change since its last update is its
  // own (store_hot's writes into its bytes aside), with `changed` telling whether store_hot
  // wrote them since they were last handed out. Null: the store re-packs the block.
  const DrawBlock* up_to_date(uint32_t slot, bool& changed) {
    if (slot >= blocks.size()) [[unlikely]]
      return nullptr;
    DrawBlock& b = blocks[slot];
    uint64_t k = b.seen_changes;
    if (k == changes && b.quiet && !b.fresh) {  // the usual other block of a pass: nothing new
      changed = false;
      return &b;
    }
    if (!b.quiet || changes - k > kTouchLog) [[unlikely]]
      return nullptr;
    while (k != changes && !b.may_hold(touched[k % kTouchLog])) ++k;
    if (k != changes) return nullptr;
    b.seen_changes = k;
    changed = b.fresh;
    b.fresh = false;
    return &b;
  }

  // The per-object matrix path: stores the 16 floats at `m16` (columns: in column order)
  // for the top-level parameter `index` of handle generation `generation` when it has a
  // hot block. False: nothing done, take the store's checked path.
  bool store_hot(uint32_t index, uint32_t handle_generation, const float* m16, bool m16_columns) {
    if (handle_generation != generation || index >= hot.size()) [[unlikely]]
      return false;
    HotMatrix& h = hot[index];
    // No hot block (none yet, or a set through the words ended it): the out-of-line path.
    if (!h.block) [[unlikely]]
      return false;
    if (!matrix_registers::store_if_changed(h.to, m16, h.columns != m16_columns)) return true;  // no bit changed
    h.stale = true;
    h.block->fresh = true;
    if (h.shared && !h.others_outdated) [[unlikely]]
      outdate_others(index, h);
    return true;
  }
  // A change of top-level parameter `index` through the words (set(), a reload's remap):
  // logged for every block holding it, and its hot block, whose bytes now lag the words,
  // is no longer written in place until that block re-packs it.
  // Callers bring stale words back (sync) before they write them; the words are then the
  // value.
  void log_change(uint32_t index) {
    hot[index] = {};
    log(index);
  }

 private:
  // A change of top-level parameter `index`: in the recent-change log, and a new version.
  void log(uint32_t index) {
    touched[changes % kTouchLog] = index;
    ++changes;
    ++versions[index];
  }
  // store_hot's first change of a matrix since another block holding it re-packed it: a
  // logged change and a new version, which the hot block holds already (it skips the
  // change when it had seen every one before it) and the others re-pack at their next
  // update. The words stay behind (stale) until one of them syncs them.
  void outdate_others(uint32_t index, HotMatrix& h) {
    const bool hot_current = h.block->seen_changes == changes;
    log(index);
    if (hot_current) h.block->seen_changes = changes;
    *h.packed_version = versions[index];
    h.others_outdated = true;
  }
};

}  // namespace fxkit::detail
