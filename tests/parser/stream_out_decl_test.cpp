// parse_stream_out_decl: ConstructGSWithSO's declaration strings read as FX11 reads them
// (entries, slots, semantic indices, masks, $SKIP gaps, strides) and their problems located.
#include <gtest/gtest.h>

#include "fx/stream_out_decl.h"

namespace fx {
namespace {

TEST(StreamOutDecl, EntriesSlotsIndicesMasksAndGaps) {
  const StreamOutDecl d = parse_stream_out_decl(" POSITION.xyz ;1: TEXCOORD3.yz; $SKIP.x; NORMAL; COLOR.rgba;");
  ASSERT_TRUE(d.problems.empty()) << d.problems[0].message;
  ASSERT_EQ(d.entries.size(), 5u);
  EXPECT_EQ(d.entries[0].semantic, "POSITION");
  EXPECT_EQ(d.entries[0].component_count, 3u);
  EXPECT_EQ(d.entries[0].offset, 1u);
  EXPECT_EQ(d.entries[0].length, 12u);
  EXPECT_EQ(d.entries[1].slot, 1u);
  EXPECT_EQ(d.entries[1].semantic, "TEXCOORD");
  EXPECT_EQ(d.entries[1].semantic_index, 3u);
  EXPECT_EQ(d.entries[1].start_component, 1u);
  EXPECT_EQ(d.entries[1].component_count, 2u);
  EXPECT_EQ(d.entries[2].semantic, "") << "a gap";
  EXPECT_EQ(d.entries[2].component_count, 1u);
  EXPECT_EQ(d.entries[3].component_count, 4u) << "no mask: every component";
  EXPECT_FALSE(d.entries[3].masked);
  EXPECT_TRUE(d.entries[0].masked);
  EXPECT_EQ(d.entries[4].component_count, 4u);
  EXPECT_FALSE(parse_stream_out_decl("POSITION.").entries.at(0).masked) << "an empty mask is every component";
  EXPECT_EQ(d.stride(0), 4u * (3 + 1 + 4 + 4));
  EXPECT_EQ(d.stride(1), 8u);
  EXPECT_EQ(d.stride(2), 0u);
  EXPECT_TRUE(parse_stream_out_decl("").entries.empty());
}

TEST(StreamOutDecl, EachMalformedEntryIsAProblemAtItsPlace) {
  const StreamOutDecl d =
      parse_stream_out_decl("x:POSITION; 9:NORMAL; POSITION.xz; $SKIPPED; TEXCOORD.q; COLOR-1; :A; 3TEX");
  ASSERT_EQ(d.problems.size(), 8u);
  EXPECT_EQ(d.problems[0].offset, 0u);
  EXPECT_EQ(d.problems[0].message, "output slot 'x' is not a number (\"0:POSITION.xyz\")");
  EXPECT_EQ(d.problems[1].offset, 12u);
  EXPECT_EQ(d.problems[1].message, "output slot 9 is out of range: there are 4 (0 to 3)");
  EXPECT_EQ(d.problems[2].offset, 31u);
  EXPECT_EQ(d.problems[2].length, 2u);
  EXPECT_EQ(d.problems[3].message, "unknown '$SKIPPED': the only gap is $SKIP");
  EXPECT_EQ(d.problems[4].message, "component mask 'q' is not a run of xyzw or rgba (\".xyz\", \".yz\", \".a\")");
  EXPECT_EQ(d.problems[5].message, "unexpected '-1' after 'COLOR' (a mask is written \".xyz\")");
  EXPECT_EQ(d.problems[6].message, "output slot '' is not a number (\"0:POSITION.xyz\")");
  EXPECT_EQ(d.problems[7].message, "'3TEX' is no semantic (it starts with a digit)");
  EXPECT_TRUE(d.entries.empty());
}

}  // namespace
}  // namespace fx
