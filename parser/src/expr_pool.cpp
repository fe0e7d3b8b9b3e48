// ExprPool: block storage for expression nodes (NodeBlocks) and argument lists.
#include <algorithm>

#include "fx/ast.h"

namespace fx::ast {
namespace {

// List blocks start small, so a small effect does not pay for a big block, and double up
// to a size that keeps a 10 MB effect at a few hundred allocations (as NodeBlocks does).
constexpr size_t kFirstList = 256, kMaxList = 4096;

}  // namespace

ExprPtr ExprPool::make(ExprKind kind) {
  ExprPtr e = nodes_.make();
  e->kind = kind;
  return e;
}

std::span<const ExprPtr> ExprPool::list(std::span<const ExprPtr> items) {
  if (items.empty()) return {};
  if (lists_.empty() || lists_capacity_ - lists_used_ < items.size()) {
    size_t next = lists_.empty() ? kFirstList : std::min(2 * lists_capacity_, kMaxList);
    lists_capacity_ = std::max(next, items.size());
    lists_.push_back(std::make_unique_for_overwrite<ExprPtr[]>(lists_capacity_));
    lists_used_ = 0;
  }
  ExprPtr* out = lists_.back().get() + lists_used_;
  std::copy(items.begin(), items.end(), out);
  lists_used_ += items.size();
  return {out, items.size()};
}

}  // namespace fx::ast
