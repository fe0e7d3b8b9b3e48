// ast::Arena and ast::List (fx/arena.h), the storage of the nodes' texts and lists: texts
// are copies, lists keep their elements as they grow across blocks, a move hands the
// storage over, requests larger than a block get one of their own, and the large blocks of a
// large effect are advised for huge pages.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "fx/arena.h"
#include "vm_flags.h"

namespace {

using fx::ast::Arena;
using fx::ast::List;
using fx::ast::Text;

TEST(Arena, TextIsACopyThatJoinsAsAString) {
  Arena arena;
  std::string source = "WorldViewProjection1000";
  Text t = arena.text(source);
  source.assign(source.size(), 'x');
  EXPECT_EQ(t, "WorldViewProjection1000");
  EXPECT_EQ("'" + t + "'", "'WorldViewProjection1000'");
  std::string s = t;
  EXPECT_EQ(s, "WorldViewProjection1000");
  EXPECT_TRUE(arena.text("").empty());
}

TEST(Arena, ListsGrowAcrossBlocksAndKeepTheirElements) {
  Arena arena;
  List<int> a, b;
  for (int i = 0; i < 5000; ++i) {  // interleaved, so each growth lands in a new place
    a.push_back(arena, i);
    b.emplace_back(arena) = -i;
  }
  ASSERT_EQ(a.size(), 5000u);
  for (int i = 0; i < 5000; ++i) {
    ASSERT_EQ(a[i], i);
    ASSERT_EQ(b[i], -i);
  }
  b.pop_back();
  EXPECT_EQ(b.back(), -4998);
  EXPECT_THROW(b.at(4999), std::out_of_range);
  EXPECT_EQ(b.at(1), -1);
}

TEST(Arena, LargeRequestsAndMovesKeepStorage) {
  Arena arena;
  List<double> big;
  big.reserve(arena, 100000);  // larger than any regular block
  for (int i = 0; i < 100000; ++i) big.push_back(arena, i * 0.5);
  Text t = arena.text("kept");
  Arena moved = std::move(arena);
  EXPECT_EQ(big[99999], 99999 * 0.5);
  EXPECT_EQ(t, "kept");
  List<double> more, afresh;
  more.push_back(moved, 1.5);    // the moved-to arena goes on allocating
  afresh.push_back(arena, 2.5);  // and the moved-from one starts empty
  EXPECT_EQ(more[0], 1.5);
  EXPECT_EQ(afresh[0], 2.5);
  EXPECT_NE(more.data(), afresh.data());
}

// A 10 MB effect fills tens of MB of blocks, each page written once: the blocks of 4 MB
// and up are advised for 2 MB pages, as the token stream is (fx/huge_pages.h).
TEST(Arena, LargeBlocksAreAdvisedForHugePages) {
  if (!fx::testing::kernel_has_transparent_huge_pages())
    GTEST_SKIP() << "transparent huge pages are off on this kernel";
  Arena arena;
  constexpr size_t kPiece = 64 << 10;
  std::byte* run = nullptr;  // first piece of the current block's contiguous run
  std::byte* last = nullptr;
  size_t run_bytes = 0;
  for (int i = 0; i < 1024 && run_bytes < (size_t(6) << 20); ++i) {
    auto* p = static_cast<std::byte*>(arena.allocate(kPiece, 16));
    if (last && p == last + kPiece) {
      run_bytes += kPiece;
    } else {  // a new block
      run = p;
      run_bytes = kPiece;
    }
    last = p;
  }
  ASSERT_GE(run_bytes, size_t(6) << 20) << "no block of 6 MB or more";
  // 3 MB into a block of 8 MB lies inside one of its whole 2 MB pages.
  const std::string flags = fx::testing::vm_flags_at(run + (3u << 20));
  ASSERT_FALSE(flags.empty());
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
  // A small effect's first block is left alone.
  Arena small;
  EXPECT_EQ(fx::testing::vm_flags_at(small.allocate(16, 16)).find(" hg"), std::string::npos);
}

}  // namespace
