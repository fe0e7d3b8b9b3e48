// Transparent huge pages for the front end's large, freshly written arrays (the token
// stream of a 10 MB effect is 56 MB). Each 4 KB page written for the first time costs a
// page fault that zeroes it; on a 10 MB effect those faults were about half of the
// preprocessor's wall time. With 2 MB pages there are 512 times fewer.
#pragma once
#include <cstddef>
#include <iterator>
#include <vector>

namespace fx {

// Asks the kernel to back the whole 2 MB pages inside [data, data + bytes) with huge pages
// when they are first touched. Advice only: nothing changes where the kernel has
// transparent huge pages off or the range holds no whole 2 MB page; a no-op off Linux.
void advise_huge_pages(const void* data, size_t bytes);

// v.reserve(n), with the new capacity advised as above before anything is written into
// it: the elements move into the new storage after the advice, so their copy faults in
// 2 MB pages too (pages already touched keep their size).
template <class T>
void reserve_with_huge_pages(std::vector<T>& v, size_t n) {
  if (n <= v.capacity()) return;
  std::vector<T> grown;
  grown.reserve(n);
  advise_huge_pages(grown.data(), grown.capacity() * sizeof(T));
  grown.insert(grown.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(grown);
}

}  // namespace fx
