// reserve_with_huge_pages keeps the vector's elements and order, and on Linux marks the
// 2 MB pages of the new storage for transparent huge pages (VmFlags "hg" in smaps).
#include "fx/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <string>

#include "vm_flags.h"

namespace {

using fx::testing::kernel_has_transparent_huge_pages;
using fx::testing::vm_flags_at;

TEST(HugePages, ReserveKeepsTheElementsInOrder) {
  std::vector<uint64_t> v(1000);
  std::iota(v.begin(), v.end(), 7);
  fx::reserve_with_huge_pages(v, 1u << 20);  // 8 MB: holds whole 2 MB pages
  ASSERT_GE(v.capacity(), 1u << 20);
  ASSERT_EQ(v.size(), 1000u);
  for (size_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], i + 7) << i;
  const uint64_t* data = v.data();
  fx::reserve_with_huge_pages(v, 10);  // no smaller: nothing moves
  EXPECT_EQ(v.data(), data);
}

TEST(HugePages, LargeCapacityIsAdvised) {
  if (!kernel_has_transparent_huge_pages()) GTEST_SKIP() << "transparent huge pages are off on this kernel";
  std::vector<char> v;
  fx::reserve_with_huge_pages(v, 16u << 20);
  // The middle of a 16 MB block lies in one of its whole 2 MB pages.
  const std::string flags = vm_flags_at(v.data() + (8u << 20));
  ASSERT_FALSE(flags.empty());
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
}

TEST(HugePages, SmallRangesAreLeftAlone) {
  std::vector<char> v;
  fx::reserve_with_huge_pages(v, 4096);
  const std::string flags = vm_flags_at(v.data());
  EXPECT_EQ(flags.find(" hg"), std::string::npos) << flags;
}

}  // namespace
