// Block storage for the syntax-tree nodes of one type. A node is constructed when it is
// made (a block is not value-initialized up front), never moves, and is destroyed with the
// storage. Blocks start small, so a small effect does not pay for a big block, and double
// up to kMax nodes, so a 10 MB effect costs a few hundred allocations instead of one per
// node, and the nodes lie in memory in the order they were made.
#pragma once
#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace fx::ast {

template <class T, size_t kFirst = 64, size_t kMax = 1024>
class NodeBlocks {
 public:
  NodeBlocks() = default;
  NodeBlocks(NodeBlocks&& other) noexcept
      : blocks_(std::exchange(other.blocks_, {})), used_(std::exchange(other.used_, 0)) {}
  NodeBlocks& operator=(NodeBlocks&& other) noexcept {
    if (this != &other) {
      release();
      blocks_ = std::exchange(other.blocks_, {});
      used_ = std::exchange(other.used_, 0);
    }
    return *this;
  }
  ~NodeBlocks() { release(); }

  // A new value-initialized node.
  T* make() {
    if (blocks_.empty() || used_ == blocks_.back().capacity) grow();
    return std::construct_at(blocks_.back().nodes + used_++);
  }

 private:
  struct Block {
    T* nodes;
    size_t capacity;
  };

  void grow() {
    size_t capacity = blocks_.empty() ? kFirst : std::min(2 * blocks_.back().capacity, kMax);
    blocks_.reserve(blocks_.size() + 1);  // so that push_back cannot throw and leak the block
    blocks_.push_back({std::allocator<T>().allocate(capacity), capacity});
    used_ = 0;
  }
  // Every block is full except the last, which holds used_ nodes.
  void release() {
    for (size_t b = 0; b < blocks_.size(); ++b) {
      const Block& block = blocks_[b];
      std::destroy_n(block.nodes, b + 1 == blocks_.size() ? used_ : block.capacity);
      std::allocator<T>().deallocate(block.nodes, block.capacity);
    }
    blocks_.clear();
    used_ = 0;
  }

  std::vector<Block> blocks_;
  size_t used_ = 0;  // nodes constructed in blocks_.back()
};

}  // namespace fx::ast
