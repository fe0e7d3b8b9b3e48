// Arena: the block growth behind the inline bump allocation in fx/arena.h.
#include "fx/arena.h"

#include "fx/huge_pages.h"

namespace fx::ast {

void* Arena::allocate_slow(size_t bytes, size_t align) {
  size_t need = bytes + align - 1;
  if (need > kMaxBlock) {
    // A block of its own; the rest of the current block stays in use.
    blocks_.push_back(std::make_unique_for_overwrite<std::byte[]>(need));
    std::byte* p = blocks_.back().get();
    return p + ((0 - reinterpret_cast<uintptr_t>(p)) & (align - 1));
  }
  size_t size = last_size_ == 0 ? kFirstBlock : std::min(2 * last_size_, kMaxBlock);
  while (size < need) size *= 2;
  blocks_.push_back(std::make_unique_for_overwrite<std::byte[]>(size));
  // The large blocks of a large effect are written once, front to back: 2 MB pages fault
  // 512 times less than 4 KB ones (fx/huge_pages.h). Smaller blocks hold no whole one.
  if (size >= kHugeBlock) advise_huge_pages(blocks_.back().get(), size);
  last_size_ = size;
  next_ = blocks_.back().get();
  left_ = size;
  return allocate(bytes, align);
}

}  // namespace fx::ast
