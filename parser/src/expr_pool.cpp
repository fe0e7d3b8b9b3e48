// ExprPool: block storage for expression nodes and argument lists.
#include <algorithm>

#include "fx/ast.h"

namespace fx::ast {
namespace {

// A 10 MB effect has about a million nodes: blocks of this size keep the allocations
// few without wasting much on a small effect's last block.
constexpr size_t kNodesPerBlock = 1024;
constexpr size_t kListBlock = 4096;

}  // namespace

ExprPtr ExprPool::make(ExprKind kind) {
  if (nodes_.empty() || nodes_used_ == kNodesPerBlock) {
    nodes_.push_back(std::make_unique<Expr[]>(kNodesPerBlock));
    nodes_used_ = 0;
  }
  ExprPtr e = &nodes_.back()[nodes_used_++];
  e->kind = kind;
  return e;
}

std::span<const ExprPtr> ExprPool::list(std::span<const ExprPtr> items) {
  if (items.empty()) return {};
  if (lists_.empty() || lists_capacity_ - lists_used_ < items.size()) {
    lists_capacity_ = std::max(kListBlock, items.size());
    lists_.push_back(std::make_unique_for_overwrite<ExprPtr[]>(lists_capacity_));
    lists_used_ = 0;
  }
  ExprPtr* out = lists_.back().get() + lists_used_;
  std::copy(items.begin(), items.end(), out);
  lists_used_ += items.size();
  return {out, items.size()};
}

}  // namespace fx::ast
