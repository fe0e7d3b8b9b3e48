// remap() and the defaults of an edited effect: values the application set carry over,
// the others take the new defaults, and remap names the parameters whose value a new
// default changed. Per word: an array element or struct member set alone carries alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "fx/model/parameter_store.h"
#include "model_test_util.h"

namespace fx {
namespace {

using Names = std::vector<std::string>;

float get_float(const ParameterStore& s, Param p) {
  float v = -1;
  EXPECT_TRUE(s.get(p, v));
  return v;
}

// Each default below is added, removed (zero), edited or kept by v2; the app sets Ks and Weights[1].
TEST(RemapDefaults, ParametersNeverSetTakeTheNewDefaultsAndAreNamed) {
  auto v1 = test::build(
      "float Kd = 0.6; float Ks = 0.2; float Gain; float Bias = 1; float Same = 3; int Count = 2;"
      " string Label = \"a\"; float Weights[2] = {1, 2};");
  auto v2 = test::build(
      "float Kd = 0.05; float Ks = 0.9; float Gain = 2; float Bias; float Same = 3; int Count = 5;"
      " string Label = \"b\"; float Weights[2] = {10, 20};");
  ASSERT_FALSE(v1->diags.has_errors() || v2->diags.has_errors()) << v1->text() << v2->text();
  ParameterStore s1(v1->model);
  const Param ks = s1.find("Ks"), weights = s1.find("Weights");
  ASSERT_TRUE(s1.set(ks, 0.75f));
  ASSERT_TRUE(s1.set(s1.element(weights, 1), 7.0f));
  ParameterStore s2(v2->model);
  EXPECT_EQ(remap(s1, s2), (Names{"Kd", "Gain", "Bias", "Count", "Label", "Weights"}));
  EXPECT_EQ(get_float(s2, s1.find("Kd")), 0.05f) << "an edited default";
  EXPECT_EQ(get_float(s2, ks), 0.75f) << "the application's value";
  EXPECT_EQ(get_float(s2, s1.find("Gain")), 2.0f) << "an added default";
  EXPECT_EQ(get_float(s2, s1.find("Bias")), 0.0f) << "a removed default";
  EXPECT_EQ(get_float(s2, s1.find("Same")), 3.0f);
  int32_t count = 0;
  ASSERT_TRUE(s2.get(s1.find("Count"), count));
  EXPECT_EQ(count, 5);
  std::string label;
  ASSERT_TRUE(s2.get_string(s1.find("Label"), label));
  EXPECT_EQ(label, "b");
  float w[2] = {};
  ASSERT_TRUE(s2.get(weights, std::span<float>(w)));
  EXPECT_EQ(w[0], 10.0f) << "the element never set";
  EXPECT_EQ(w[1], 7.0f) << "the element set";

  // Back to v1's text: what the application set is still its own after one remap.
  auto v3 = test::build("float Kd = 0.6; float Ks = 0.2; float Weights[2] = {1, 2};");
  ParameterStore s3(v3->model);
  EXPECT_EQ(remap(s2, s3), (Names{"Kd", "Weights"}));
  EXPECT_EQ(get_float(s3, ks), 0.75f);
  ASSERT_TRUE(s3.get(weights, std::span<float>(w)));
  EXPECT_EQ(w[0], 1.0f);
  EXPECT_EQ(w[1], 7.0f);
}

TEST(RemapDefaults, ResetMakesAParameterFollowTheDefaultsAgain) {
  auto v1 = test::build("float Kd = 0.6; string Label = \"a\";");
  auto v2 = test::build("float Kd = 0.05; string Label = \"b\";");
  ParameterStore s1(v1->model);
  const Param kd = s1.find("Kd"), label = s1.find("Label");
  ASSERT_TRUE(s1.set(kd, 0.3f));
  ASSERT_TRUE(s1.set_string(label, "mine"));
  ASSERT_TRUE(s1.reset(kd));
  ASSERT_TRUE(s1.reset(label));
  ParameterStore s2(v2->model);
  EXPECT_EQ(remap(s1, s2), (Names{"Kd", "Label"}));
  EXPECT_EQ(get_float(s2, kd), 0.05f);
  std::string text;
  ASSERT_TRUE(s2.get_string(label, text));
  EXPECT_EQ(text, "b");
}

// Per-object matrices: a set through set_matrix's in-place path (a hot block) is the
// application's too, also one of the value the matrix held. A reload touches every
// parameter, so its first draw re-packs every matrix: the one place a matrix never set
// could become hot.
TEST(RemapDefaults, MatricesSetPerObjectAreTheApplications) {
  const std::string identity = "{1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1}", twice = "{2,0,0,0, 0,2,0,0, 0,0,2,0, 0,0,0,1}";
  auto v1 = test::build("float4x4 World = " + identity + "; float4x4 View = " + identity + ";");
  auto v2 = test::build("float4x4 World = " + twice + "; float4x4 View = " + twice + ";");
  const BlockMemberLayout layout[] = {test::placed(v1->model, "World", 0, 64, 0, 16, MatrixPacking::column_major),
                                      test::placed(v1->model, "View", 64, 64, 0, 16, MatrixPacking::column_major)};
  ParameterStore s1(v1->model), s2(v1->model);
  ASSERT_TRUE(s2.bind_layout(0, layout, 128));  // as a backend binds before the swap
  EXPECT_EQ(remap(s1, s2), Names{});
  // Handles of s2's generation: an older one always takes set_matrix's checked path.
  const Param world = s2.find("World"), view = s2.find("View");
  auto draw = [&] {
    bool changed = false;
    s2.update_block(s2.block(0), changed);
  };
  draw();
  float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  ASSERT_TRUE(s2.set_matrix(view, m)) << "the value View holds already";
  m[12] = 5;
  ASSERT_TRUE(s2.set_matrix(world, m));
  draw();  // World is hot now
  m[12] = 6;
  ASSERT_TRUE(s2.set_matrix(world, m));  // in place
  ParameterStore s3(v2->model);
  EXPECT_EQ(remap(s2, s3), Names{});
  float back[16];
  ASSERT_TRUE(s3.get_matrix(world, back));
  EXPECT_EQ(back[0], 1.0f);
  EXPECT_EQ(back[12], 6.0f) << "World keeps the value set in place";
  ASSERT_TRUE(s3.get_matrix(view, back));
  EXPECT_EQ(back[0], 1.0f) << "View keeps the identity the application set";

  ASSERT_TRUE(s2.reset(world));
  draw();
  ASSERT_TRUE(s2.get_matrix(world, back));
  EXPECT_EQ(back[12], 0.0f);
  ParameterStore s4(v2->model);
  EXPECT_EQ(remap(s2, s4), Names{"World"});
  ASSERT_TRUE(s4.get_matrix(world, back));
  EXPECT_EQ(back[0], 2.0f) << "World follows the defaults after reset()";

  m[12] = 0;
  ASSERT_TRUE(s2.set_matrix(world, m)) << "after reset(), the value World holds";
  ParameterStore s5(v2->model);
  EXPECT_EQ(remap(s2, s5), Names{});
  ASSERT_TRUE(s5.get_matrix(world, back));
  EXPECT_EQ(back[0], 1.0f) << "is the application's again";
}

// Shared parameters keep the pool's value: the pool is the application's, shared with
// effects whose files may give other defaults.
// remap() into a store whose own matrix set_matrix last wrote in place (in its hot block
// only): the value the old store never set is the new store's newest one, not the one its
// words held before.
TEST(RemapDefaults, AMatrixWrittenInPlaceInTheNewStoreKeepsItsNewestValue) {
  auto b = test::build("float4x4 World; float c;");
  ParameterStore old_store(b->model), next(b->model);
  const BlockMemberLayout whole[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major)};
  ASSERT_TRUE(next.bind_layout(1, whole, 64));
  const Param world = next.find("World");
  float x[16], y[16];
  for (int i = 0; i < 16; ++i) x[i] = float(i), y[i] = float(100 + i);
  ASSERT_TRUE(next.set_matrix(world, x));  // through the words
  bool changed = false;
  next.update_block(next.block(1), changed);  // the block takes World in place from now on
  ASSERT_TRUE(next.set_matrix(world, y));     // in place: the words lag
  remap(old_store, next);
  float got[16];
  ASSERT_TRUE(next.get(next.find("World"), std::span<float>(got)));
  EXPECT_EQ(got[1], 101.0f);
}

TEST(RemapDefaults, SharedParametersKeepThePoolsValue) {
  auto v1 = test::build("shared float Time = 1; float Kd = 0.6;");
  auto v2 = test::build("shared float Time = 5; float Kd = 0.6;");
  ParameterPool pool;
  ParameterStore s1(v1->model, &pool);
  ParameterStore s2(v2->model, &pool);
  EXPECT_EQ(remap(s1, s2), Names{});
  EXPECT_EQ(get_float(s2, s1.find("Time")), 1.0f);
}

}  // namespace
}  // namespace fx
