// NodeBlocks (fx/node_blocks.h), the block storage behind ast::ExprPool and ast::DeclPool:
// nodes keep their addresses as blocks are added, start value-initialized, and are
// destroyed exactly once, by whichever storage owns them after a move.
#include <gtest/gtest.h>

#include <vector>

#include "fx/node_blocks.h"

namespace {

struct Counted {
  static inline int live = 0;
  int value;  // value-initialized: 0
  Counted() : value() { ++live; }
  ~Counted() { --live; }
};

TEST(NodeBlocks, NodesKeepTheirAddressesAcrossBlocks) {
  fx::ast::NodeBlocks<Counted> nodes;
  std::vector<Counted*> made;
  for (int i = 0; i < 3000; ++i) {  // 64 + 128 + ... + 1024 + 1024: several blocks
    Counted* n = nodes.make();
    EXPECT_EQ(n->value, 0);
    n->value = i;
    made.push_back(n);
  }
  for (int i = 0; i < 3000; ++i) EXPECT_EQ(made[i]->value, i);
}

TEST(NodeBlocks, EveryNodeMadeIsDestroyedOnceByItsOwner) {
  Counted::live = 0;
  {
    fx::ast::NodeBlocks<Counted> nodes;
    for (int i = 0; i < 100; ++i) nodes.make();  // the second block is partly used
    EXPECT_EQ(Counted::live, 100);
    fx::ast::NodeBlocks<Counted> moved(std::move(nodes));
    fx::ast::NodeBlocks<Counted> assigned;
    assigned.make();
    assigned = std::move(moved);  // destroys the node `assigned` held
    EXPECT_EQ(Counted::live, 100);
    nodes.make();  // a moved-from storage is empty and usable
    EXPECT_EQ(Counted::live, 101);
  }
  EXPECT_EQ(Counted::live, 0);
}

}  // namespace
