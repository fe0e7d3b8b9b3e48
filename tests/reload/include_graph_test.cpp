// IncludeGraph: which effects read which files, and what to watch / unwatch on changes.
#include <gtest/gtest.h>

#include "fx/reload/include_graph.h"

namespace fx {
namespace {

using Files = std::vector<std::string>;

TEST(IncludeGraph, SharedIncludeIsWatchedOnceAndMapsToEveryReader) {
  IncludeGraph g;
  IncludeGraph::Change c1 = g.set_files(1, {"/a.fx", "/common.fxh"});
  EXPECT_EQ(c1.added, (Files{"/a.fx", "/common.fxh"}));
  IncludeGraph::Change c2 = g.set_files(2, {"/b.fx", "/common.fxh"});
  EXPECT_EQ(c2.added, (Files{"/b.fx"})) << "common.fxh is already watched";
  EXPECT_EQ(g.effects_of("/common.fxh"), (std::vector<uint32_t>{1, 2}));
  EXPECT_EQ(g.effects_of("/a.fx"), (std::vector<uint32_t>{1}));
  EXPECT_TRUE(g.effects_of("/other.fxh").empty());
  EXPECT_EQ(g.file_count(), 3u);
}

TEST(IncludeGraph, SetFilesDropsIncludesNoLongerReadAndAddFilesKeepsThem) {
  IncludeGraph g;
  g.set_files(1, {"/a.fx", "/old.fxh"});
  IncludeGraph::Change c = g.add_files(1, {"/a.fx", "/new.fxh"});
  EXPECT_EQ(c.added, (Files{"/new.fxh"}));
  EXPECT_TRUE(c.removed.empty());
  c = g.set_files(1, {"/a.fx", "/new.fxh"});
  EXPECT_TRUE(c.added.empty());
  EXPECT_EQ(c.removed, (Files{"/old.fxh"}));
  EXPECT_EQ(g.files_of(1), (Files{"/a.fx", "/new.fxh"}));
}

TEST(IncludeGraph, RemoveReturnsOnlyFilesNobodyElseReads) {
  IncludeGraph g;
  g.set_files(1, {"/a.fx", "/common.fxh"});
  g.set_files(2, {"/b.fx", "/common.fxh"});
  EXPECT_EQ(g.remove(1), (Files{"/a.fx"}));
  EXPECT_EQ(g.remove(2), (Files{"/b.fx", "/common.fxh"}));
  EXPECT_EQ(g.file_count(), 0u);
  EXPECT_TRUE(g.remove(3).empty());
}

}  // namespace
}  // namespace fx
