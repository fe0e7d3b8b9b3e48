// fxkit::detail::DrawState: a parameter store's per-object state (each bound uniform block's
// packed bytes, the hot matrices, the versions and change log), declared here so that
// Effect::set_matrix and the store's update_block inline into an engine's draw loop.
// Internal to fxkit: the layout may change in any release; use fxkit::Effect.
#pragma once
#include <cstdint>
#include <vector>

#include "fx/model/matrix_registers.h"

namespace fxkit::detail {

struct alignas(32) DrawBlock {  // 32 bytes: a slot's address is a shift
  const uint8_t* bytes = nullptr;  // the block's packed bytes
  uint32_t size = 0;
  bool quiet = false;  // written since its layout was bound, no pooled parameter: only logged
                       // changes or store_hot's writes into `bytes` (fresh) can change it
  bool fresh = false;  // store_hot wrote into `bytes` since they were last handed out
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
// application's values and records nothing for reloads; a reset ends it. Other blocks
// re-pack from the change log. The pointers are into the store's blocks, which clears every
// HotMatrix when it may move them; the next re-pack makes one again.
struct HotMatrix {
  DrawBlock* block = nullptr;          // the hot block's; none when null
  uint64_t* packed_version = nullptr;  // the version its bytes hold
  uint8_t* to = nullptr;               // the matrix's first byte in the block
  uint32_t words = 0;                  // the parameter's first word in the store
  bool columns = false;                // the block holds column registers (HLSL's default)
  // The value is in the hot block's bytes only: store_hot leaves the store's words behind,
  // as D3DX effects keep a constant buffer's shadow as the one copy; the store brings them
  // back before anything else reads or partly writes them.
  bool stale = false;
};

struct DrawState {
  std::vector<DrawBlock> blocks;  // by block slot
  std::vector<HotMatrix> hot;     // per top-level parameter
  // Per top-level parameter, bumped on every change: a block compares it with what it
  // packed, so a set costs the same however many blocks hold the parameter.
  std::vector<uint64_t> versions;
  // The last kTouchLog changes: touched[k % kTouchLog] is the top-level parameter of change
  // k (`changes` so far), so a block refreshed a few changes ago re-packs just those instead
  // of comparing every parameter's version.
  static constexpr uint32_t kTouchLog = 16;
  uint64_t changes = 0;
  uint32_t touched[kTouchLog] = {};
  uint32_t generation = 0;  // of the handles the store issues now

  // The per-object matrix path: stores the 16 floats at `m16` (columns: in column order)
  // for the top-level parameter `index` of handle generation `generation` when it has a
  // hot block that took every change to it. False: nothing done, take the store's checked
  // path.
  bool store_hot(uint32_t index, uint32_t handle_generation, const float* m16, bool m16_columns) {
    if (handle_generation != generation || index >= hot.size()) [[unlikely]] return false;
    HotMatrix& h = hot[index];
    uint64_t& version = versions[index];
    // No hot block, or it missed a change (a set through the words): the out-of-line path.
    if (!h.block || *h.packed_version != version) [[unlikely]] return false;
    if (!matrix_registers::store_if_changed(h.to, m16, h.columns != m16_columns)) return true;  // no bit changed
    h.stale = true;
    DrawBlock& b = *h.block;
    b.fresh = true;
    // Logged for the blocks other than the hot one, which re-pack from the words.
    const uint64_t change = changes, next = version + 1;
    touched[change % kTouchLog] = index;
    changes = change + 1;
    version = next;
    *h.packed_version = next;
    // A block that had taken every earlier change has now taken this one too: its next
    // update has no logged change to look at.
    if (b.seen_changes == change) b.seen_changes = change + 1;
    return true;
  }
};

}  // namespace fxkit::detail
