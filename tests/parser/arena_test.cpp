// ast::Arena and ast::List (fx/arena.h), the storage of the nodes' texts and lists: texts
// are copies, lists keep their elements as they grow across blocks, a move hands the
// storage over, and requests larger than a block get one of their own.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "fx/arena.h"

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

}  // namespace
