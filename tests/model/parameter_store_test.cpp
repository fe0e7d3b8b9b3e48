// ParameterStore: typed set/get for every type, mismatches, lookup, dirty tracking, block
// packing with D3D matrix rules, shared pools and remap across reloads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>

#include "fx/model/parameter_store.h"
#include "model_test_util.h"

namespace fx {
namespace {

const char* kParams = R"(
  float f = 0.5; float2 f2; float3 f3 : LightDirection = {0, 1, 0}; float4 f4;
  float4x4 m : WorldViewProjection; float3x4 m34; row_major float4x4 rm;
  int i = 4; int3 i3; uint u; bool b = true; bool4 b4; half h; double d;
  float4 arr[3]; string label = "x";
  struct Light { float3 dir; int kind; float4 color; };
  Light light; Light lights[2];
  texture tex;
)";

TEST(ParameterStore, RoundTripEveryType) {
  auto b = test::build(kParams);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  ParameterStore store(b->model);
  float f = 0;
  ASSERT_TRUE(store.get(store.find("f"), f));
  EXPECT_EQ(f, 0.5f);  // default applied
  ASSERT_TRUE(store.set(store.find("f"), 2.5f));
  ASSERT_TRUE(store.get(store.find("f"), f));
  EXPECT_EQ(f, 2.5f);
  for (const char* name : {"f2", "f3", "f4", "m", "m34", "rm", "arr", "h", "d"}) {
    Param p = store.find(name);
    ASSERT_TRUE(p.valid()) << name;
    std::vector<float> in(store.type(p)->component_count()), out(in.size());
    for (size_t k = 0; k < in.size(); ++k) in[k] = static_cast<float>(k) * 0.25f - 1.0f;
    ASSERT_TRUE(store.set(p, std::span<const float>(in))) << name;
    ASSERT_TRUE(store.get(p, std::span<float>(out))) << name;
    EXPECT_EQ(in, out) << name;
  }
  for (const char* name : {"i3", "b4"}) {
    Param p = store.find(name);
    std::vector<int32_t> in(store.type(p)->component_count()), out(in.size());
    for (size_t k = 0; k < in.size(); ++k) in[k] = static_cast<int32_t>(k % 2);
    ASSERT_TRUE(store.set(p, std::span<const int32_t>(in))) << name;
    ASSERT_TRUE(store.get(p, std::span<int32_t>(out))) << name;
    EXPECT_EQ(in, out) << name;
  }
  int32_t i = 0;
  ASSERT_TRUE(store.get(store.find("i"), i));
  EXPECT_EQ(i, 4);
  ASSERT_TRUE(store.set(store.find("u"), int32_t{7}));
  bool flag = false;
  ASSERT_TRUE(store.get(store.find("b"), flag));
  EXPECT_TRUE(flag);
  ASSERT_TRUE(store.set(store.find("b"), false));
  ASSERT_TRUE(store.get(store.find("b"), flag));
  EXPECT_FALSE(flag);
  std::string label;
  ASSERT_TRUE(store.get_string(store.find("label"), label));
  EXPECT_EQ(label, "x");
  ASSERT_TRUE(store.set_string(store.find("label"), "y"));
  ASSERT_TRUE(store.get_string(store.find("label"), label));
  EXPECT_EQ(label, "y");
}

TEST(ParameterStore, MembersAndElements) {
  auto b = test::build(kParams);
  ParameterStore store(b->model);
  Param light = store.find("light");
  Param dir = store.member(light, "dir");
  ASSERT_TRUE(dir.valid());
  EXPECT_EQ(store.name(dir), "light.dir");
  const float d[3] = {1, 2, 3};
  ASSERT_TRUE(store.set(dir, std::span<const float>(d)));
  ASSERT_TRUE(store.set(store.member(light, "kind"), int32_t{2}));
  Param second = store.member(store.element(store.find("lights"), 1), "color");
  ASSERT_TRUE(second.valid());
  EXPECT_EQ(store.name(second), "lights[1].color");
  const float c[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  ASSERT_TRUE(store.set(second, std::span<const float>(c)));
  float out[4];
  ASSERT_TRUE(store.get(second, std::span<float>(out)));
  EXPECT_EQ(out[2], 0.3f);
  EXPECT_FALSE(store.element(store.find("lights"), 2).valid());
  EXPECT_FALSE(store.member(light, "nope").valid());
  EXPECT_FALSE(store.element(store.find("f4"), 0).valid());
  Param e2 = store.element(store.find("arr"), 2);
  const float v[4] = {9, 8, 7, 6};
  ASSERT_TRUE(store.set(e2, std::span<const float>(v)));
  float all[12];
  ASSERT_TRUE(store.get(store.find("arr"), std::span<float>(all)));
  EXPECT_EQ(all[8], 9);
  EXPECT_EQ(all[11], 6);
  // A struct mixing floats and ints cannot be set from floats as a whole.
  std::vector<float> whole(8);
  EXPECT_EQ(store.set(light, std::span<const float>(whole)).code, ParamStatus::type_mismatch);
}

TEST(ParameterStore, MismatchesAreErrorsNotUB) {
  auto b = test::build(kParams);
  ParameterStore store(b->model);
  const float two[2] = {1, 2};
  ParamStatus s = store.set(store.find("f3"), std::span<const float>(two));
  EXPECT_EQ(s.code, ParamStatus::size_mismatch);
  EXPECT_NE(s.message.find("f3"), std::string::npos) << s.message;
  EXPECT_EQ(store.set(store.find("i"), 1.0f).code, ParamStatus::type_mismatch);
  EXPECT_EQ(store.set(store.find("f"), int32_t{1}).code, ParamStatus::type_mismatch);
  EXPECT_EQ(store.set(store.find("tex"), 1.0f).code, ParamStatus::type_mismatch);
  EXPECT_EQ(store.set_string(store.find("f"), "s").code, ParamStatus::type_mismatch);
  EXPECT_EQ(store.set(store.find("missing"), 1.0f).code, ParamStatus::invalid_handle);
  EXPECT_EQ(store.set(Param{123456, 0}, 1.0f).code, ParamStatus::invalid_handle);
  EXPECT_EQ(store.set(Param{0, 7}, 1.0f).code, ParamStatus::invalid_handle);
  EXPECT_EQ(store.set_matrix(store.find("f4"), std::vector<float>(16)).code, ParamStatus::type_mismatch);
  float out[3];
  EXPECT_EQ(store.get(store.find("f4"), std::span<float>(out)).code, ParamStatus::size_mismatch);
  float f = 0;
  ASSERT_TRUE(store.get(store.find("f"), f));
  EXPECT_EQ(f, 0.5f) << "a failed call changes nothing";
}

TEST(ParameterStore, LookupBySemanticIgnoresCase) {
  auto b = test::build(kParams);
  ParameterStore store(b->model);
  EXPECT_EQ(store.by_semantic("worldviewprojection"), store.find("m"));
  EXPECT_EQ(store.by_semantic("LIGHTDIRECTION"), store.find("f3"));
  EXPECT_FALSE(store.by_semantic("Nope").valid());
  EXPECT_EQ(store.parameter_count(), b->model.parameters.size());
}

TEST(ParameterStore, MatrixPackingFollowsD3D) {
  auto b = test::build("float4x4 cm; row_major float4x4 rm; float4x4 ms[2]; float3 v;");
  ParameterStore store(b->model);
  // A D3DX-style row-major matrix: m[r][c] = 10*r + c (translation in row 3).
  std::vector<float> m(16);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[r * 4 + c] = static_cast<float>(10 * r + c);
  ASSERT_TRUE(store.set_matrix(store.find("cm"), m));
  ASSERT_TRUE(store.set_matrix(store.find("rm"), m));
  // The same matrix given column-major (glm memory of the transpose) reads back equal.
  std::vector<float> col(16);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) col[c * 4 + r] = m[r * 4 + c];
  std::vector<float> two(32);
  std::copy(col.begin(), col.end(), two.begin());
  std::copy(col.begin(), col.end(), two.begin() + 16);
  ASSERT_TRUE(store.set_matrix(store.find("ms"), two, fxkit::MatrixOrder::column_major));
  std::vector<float> back(16);
  ASSERT_TRUE(store.get_matrix(store.element(store.find("ms"), 1), back));
  EXPECT_EQ(back, m);
  const BlockMemberLayout layout[] = {
      test::placed(b->model, "cm", 0, 64, 0, 16, MatrixPacking::column_major),
      test::placed(b->model, "rm", 64, 64, 0, 16, MatrixPacking::row_major),
      test::placed(b->model, "ms", 128, 128, 64, 16, MatrixPacking::column_major),
      test::placed(b->model, "v", 256, 12, 0, 16, MatrixPacking::column_major),
  };
  ASSERT_TRUE(store.bind_layout(0, layout, 272));
  std::vector<uint8_t> bytes(272, 0xCD);
  ASSERT_TRUE(store.write_block(0, bytes));
  auto at = [&](size_t offset) {
    float f;
    std::memcpy(&f, bytes.data() + offset, 4);
    return f;
  };
  // column_major: register c holds column c, so the bytes read m[0][1] at offset 16.
  EXPECT_EQ(at(16), 1.0f);  // register 1, component 0 = m[0][1]
  EXPECT_EQ(at(4), 10.0f);  // register 0, component 1 = m[1][0]
  EXPECT_EQ(at(48 + 0), 3.0f);
  // row_major: register r holds row r, identical to the host's row-major floats.
  EXPECT_EQ(at(64 + 4), 1.0f);
  EXPECT_EQ(at(64 + 16), 10.0f);
  // Second array element starts at its stride.
  EXPECT_EQ(at(128 + 64 + 16), 1.0f);
  // Every component of every matrix, in both orders.
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      const float want = m[r * 4 + c];
      EXPECT_EQ(at(c * 16 + r * 4), want) << "cm " << r << c;
      EXPECT_EQ(at(64 + r * 16 + c * 4), want) << "rm " << r << c;
      EXPECT_EQ(at(128 + c * 16 + r * 4), want) << "ms[0] " << r << c;
      EXPECT_EQ(at(192 + c * 16 + r * 4), want) << "ms[1] " << r << c;
    }
  // Bytes no parameter covers are zeroed (the block may be a recycled ring slot): the
  // padding after `v` up to the block size.
  EXPECT_EQ(bytes[268], 0);
  EXPECT_EQ(bytes[271], 0);
  std::vector<uint8_t> larger(280, 0xCD);
  ASSERT_TRUE(store.write_block(0, larger));
  EXPECT_EQ(larger[272], 0xCD) << "bytes past the block size are left alone";
  std::vector<uint8_t> small(100);
  EXPECT_EQ(store.write_block(0, small).code, ParamStatus::size_mismatch);
  const BlockMemberLayout outside[] = {test::placed(b->model, "v", 300, 12, 0, 16, MatrixPacking::column_major)};
  EXPECT_EQ(store.bind_layout(1, outside, 272).code, ParamStatus::size_mismatch);
}

TEST(ParameterStore, DirtyTrackingPerBlock) {
  auto b = test::build("float4 a; float4 c; struct S { float3 p; float w; }; S s;");
  ParameterStore store(b->model);
  const BlockMemberLayout b0[] = {test::placed(b->model, "a", 0, 16, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout b1[] = {test::placed(b->model, "c", 0, 16, 0, 16, MatrixPacking::column_major),
                                  test::placed(b->model, "s.p", 16, 12, 0, 16, MatrixPacking::column_major),
                                  test::placed(b->model, "s.w", 28, 4, 0, 16, MatrixPacking::column_major)};
  ASSERT_TRUE(store.bind_layout(0, b0, 16));
  ASSERT_TRUE(store.bind_layout(1, b1, 32));
  EXPECT_TRUE(store.dirty(0));
  std::vector<uint8_t> bytes(32);
  ASSERT_TRUE(store.write_block(0, bytes));
  ASSERT_TRUE(store.write_block(1, bytes));
  EXPECT_FALSE(store.dirty(0));
  EXPECT_FALSE(store.dirty(1));
  ASSERT_TRUE(store.set(store.member(store.find("s"), "w"), 2.0f));
  EXPECT_FALSE(store.dirty(0));
  EXPECT_TRUE(store.dirty(1));
  ASSERT_TRUE(store.write_block(1, bytes));
  float w;
  std::memcpy(&w, bytes.data() + 28, 4);
  EXPECT_EQ(w, 2.0f);
  const float a[4] = {1, 2, 3, 4};
  ASSERT_TRUE(store.set(store.find("a"), std::span<const float>(a)));
  EXPECT_TRUE(store.dirty(0));
  EXPECT_FALSE(store.dirty(1));
  ASSERT_TRUE(store.write_block(0, bytes));
  ASSERT_TRUE(store.set(store.find("a"), std::span<const float>(a)));
  EXPECT_FALSE(store.dirty(0)) << "setting the value the parameter holds changes nothing";
  EXPECT_FALSE(find_slice(b->model, "zz")) << "a path naming no parameter has no slice";
  EXPECT_FALSE(find_slice(b->model, "s")) << "nor has a struct: its members are laid out one by one";
  const BlockMemberLayout past_the_words[] = {{{1, 4, make_numeric(BaseType::float32)}, 0, 4, 0, 16}};
  EXPECT_EQ(store.bind_layout(2, past_the_words, 4).code, ParamStatus::not_found);
}

// Members of an array of structs and of a struct inside a struct are bound by their paths;
// glslang also lists a dynamically indexed member without its index ("lights.color", at
// element 0's offset): an alias of element 0, packed once, and bound alone when it is alone.
TEST(ParameterStore, StructArrayMembersAndUnindexedAliasesAreBound) {
  auto b = test::build(R"(struct Light { float3 dir; float4 color; };
    struct Rig { Light key; float scale[2]; };
    Light lights[2] = { { float3(0, 0, 1), float4(1, 2, 3, 4) }, { float3(0, 1, 0), float4(5, 6, 7, 8) } };
    Rig rig = { { float3(1, 0, 0), float4(9, 10, 11, 12) }, { 13, 14 } };)");
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  ParameterStore store(b->model);
  const BlockMemberLayout layout[] = {
      test::placed(b->model, "lights.color", 16, 16, 0, 16, MatrixPacking::column_major),
      test::placed(b->model, "lights[0].dir", 0, 12, 0, 16, MatrixPacking::column_major),
      test::placed(b->model, "lights[0].color", 16, 16, 0, 16, MatrixPacking::column_major),
      test::placed(b->model, "lights[1].dir", 32, 12, 0, 16, MatrixPacking::column_major),
      test::placed(b->model, "lights[1].color", 48, 16, 0, 16, MatrixPacking::column_major),
      test::placed(b->model, "rig.key.dir", 64, 12, 0, 16, MatrixPacking::column_major),
      test::placed(b->model, "rig.key.color", 80, 16, 0, 16, MatrixPacking::column_major),
      test::placed(b->model, "rig.scale", 96, 20, 16, 16, MatrixPacking::column_major),
  };
  ParamStatus status = store.bind_layout(0, layout, 128);
  EXPECT_TRUE(status) << status.message;
  std::vector<uint8_t> bytes(128);
  ASSERT_TRUE(store.write_block(0, bytes));
  auto at = [&](size_t offset) {
    float f;
    std::memcpy(&f, bytes.data() + offset, 4);
    return f;
  };
  EXPECT_EQ(at(8), 1.0f);     // lights[0].dir.z
  EXPECT_EQ(at(16), 1.0f);    // lights[0].color.x
  EXPECT_EQ(at(60), 8.0f);    // lights[1].color.w
  EXPECT_EQ(at(88), 11.0f);   // rig.key.color.z
  EXPECT_EQ(at(96), 13.0f);   // rig.scale[0]
  EXPECT_EQ(at(112), 14.0f);  // rig.scale[1], one register on
  const float red[4] = {0.5f, 0, 0, 1};
  ASSERT_TRUE(store.set(store.member(store.element(store.find("lights"), 0), "color"), std::span<const float>(red)));
  ASSERT_TRUE(store.write_block(0, bytes));
  EXPECT_EQ(at(16), 0.5f);
  // The alias alone: element 0's member.
  const BlockMemberLayout alone[] = {test::placed(b->model, "lights.color", 0, 16, 0, 16, MatrixPacking::column_major)};
  status = store.bind_layout(1, alone, 16);
  EXPECT_TRUE(status) << status.message;
  std::vector<uint8_t> one(16);
  ASSERT_TRUE(store.write_block(1, one));
  float x;
  std::memcpy(&x, one.data(), 4);
  EXPECT_EQ(x, 0.5f);
}

// update_block through a handle: the same bytes write_block gives, `changed` only when a
// bit changed, and the same result whether a few changes (the recent-change log) or more
// than the log holds (the full comparison) happened since the last update.
TEST(ParameterStore, UpdateBlockThroughHandle) {
  auto b = test::build("float4x4 World; float4x4 Wvp; float4 a; float c; float e[20];");
  ParameterStore store(b->model);
  const BlockMemberLayout layout[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major),
                                      test::placed(b->model, "Wvp", 64, 64, 0, 16, MatrixPacking::row_major),
                                      test::placed(b->model, "a", 128, 16, 0, 16, MatrixPacking::column_major),
                                      test::placed(b->model, "c", 144, 4, 0, 16, MatrixPacking::column_major)};
  ASSERT_TRUE(store.bind_layout(7, layout, 160));
  EXPECT_FALSE(store.block(8).valid());
  const BlockHandle h = store.block(7);
  ASSERT_TRUE(h.valid());
  bool changed = false;
  EXPECT_TRUE(store.update_block(BlockHandle{}, changed).empty());
  EXPECT_FALSE(changed);
  std::span<const uint8_t> bytes = store.update_block(h, changed);
  ASSERT_EQ(bytes.size(), 160u);
  EXPECT_TRUE(changed) << "never handed out";
  bytes = store.update_block(h, changed);
  EXPECT_FALSE(changed);
  float m[16];
  for (int i = 0; i < 16; ++i) m[i] = float(i + 1);
  ASSERT_TRUE(store.set_matrix(store.find("World"), m));
  ASSERT_TRUE(store.set_matrix(store.find("Wvp"), m));
  ASSERT_TRUE(store.set_matrix(store.find("World"), m)) << "the same value again";
  EXPECT_TRUE(store.dirty(7));
  bytes = store.update_block(h, changed);
  EXPECT_TRUE(changed);
  EXPECT_FALSE(store.dirty(7));
  std::vector<uint8_t> written(160, 0xCD);
  ASSERT_TRUE(store.write_block(7, written));
  EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), written.begin()));
  float at;
  std::memcpy(&at, bytes.data() + 16, 4);
  EXPECT_EQ(at, 2.0f) << "column_major World: register 1 starts with m[0][1]";
  std::memcpy(&at, bytes.data() + 64 + 4, 4);
  EXPECT_EQ(at, 2.0f) << "row_major Wvp: register 0 is row 0";
  // More changes than the recent-change log holds, to parameters in and out of the block.
  const Param e = store.find("e"), a = store.find("a"), c = store.find("c");
  for (int k = 0; k < 40; ++k) ASSERT_TRUE(store.set(store.element(e, uint32_t(k % 20)), float(k)));
  ASSERT_TRUE(store.set(c, 3.0f));
  for (int k = 0; k < 40; ++k) ASSERT_TRUE(store.set(store.element(e, uint32_t(k % 20)), float(k + 100)));
  bytes = store.update_block(h, changed);
  EXPECT_TRUE(changed);
  std::memcpy(&at, bytes.data() + 144, 4);
  EXPECT_EQ(at, 3.0f);
  // Changes only outside the block leave it unchanged, logged or not.
  ASSERT_TRUE(store.set(store.element(e, 0), -1.0f));
  store.update_block(h, changed);
  EXPECT_FALSE(changed);
  for (int k = 0; k < 40; ++k) ASSERT_TRUE(store.set(store.element(e, uint32_t(k % 20)), float(k + 200)));
  store.update_block(h, changed);
  EXPECT_FALSE(changed);
  // A parameter changed twice within the log is packed with its last value.
  const float v1[4] = {1, 2, 3, 4}, v2[4] = {5, 6, 7, 8};
  ASSERT_TRUE(store.set(a, std::span<const float>(v1)));
  ASSERT_TRUE(store.set(a, std::span<const float>(v2)));
  bytes = store.update_block(h, changed);
  EXPECT_TRUE(changed);
  std::memcpy(&at, bytes.data() + 128 + 12, 4);
  EXPECT_EQ(at, 8.0f);
  // A rebind keeps the handle.
  ASSERT_TRUE(store.bind_layout(7, std::span<const BlockMemberLayout>(layout, 2), 128));
  EXPECT_EQ(store.block(7).slot, h.slot);
  EXPECT_EQ(store.update_block(h, changed).size(), 128u);
  EXPECT_TRUE(changed);
}

// The per-draw path (World written into its hot block, update_block's inline check) keeps
// working on the store a move leaves the values in, by construction and by assignment,
// and a second block that holds World re-packs it from the change log.
TEST(ParameterStore, MovedStoreKeepsItsBlocks) {
  auto b = test::build("float4x4 World; float4 a;");
  ParameterStore first(b->model);
  const BlockMemberLayout object[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout material[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::row_major),
                                        test::placed(b->model, "a", 64, 16, 0, 16, MatrixPacking::column_major)};
  ASSERT_TRUE(first.bind_layout(0, object, 64));
  ASSERT_TRUE(first.bind_layout(1, material, 80));
  ParameterStore store(std::move(first));
  const BlockHandle h = store.block(0), other = store.block(1);
  bool changed = false;
  float m[16];
  for (int draw = 0; draw < 3; ++draw) {
    for (int i = 0; i < 16; ++i) m[i] = float(draw * 16 + i);
    ASSERT_TRUE(store.set_matrix(store.find("World"), m));
    const std::span<const uint8_t> bytes = store.update_block(h, changed);
    ASSERT_EQ(bytes.size(), 64u);
    EXPECT_TRUE(changed) << "draw " << draw;
    float at;
    std::memcpy(&at, bytes.data() + 4, 4);
    EXPECT_EQ(at, float(draw * 16 + 4)) << "column_major: register 0 is column 0, m[1][0]";
    store.update_block(h, changed);
    EXPECT_FALSE(changed) << "nothing set since";
  }
  const std::span<const uint8_t> bytes = store.update_block(other, changed);
  EXPECT_TRUE(changed);
  float at;
  std::memcpy(&at, bytes.data() + 4, 4);
  EXPECT_EQ(at, 33.0f) << "row_major: register 0 is row 0, m[0][1] of the last draw";
  ParameterStore assigned(b->model);
  assigned = std::move(store);
  for (int i = 0; i < 16; ++i) m[i] = float(100 + i);
  ASSERT_TRUE(assigned.set_matrix(assigned.find("World"), m));
  EXPECT_EQ(assigned.update_block(h, changed).size(), 64u);
  EXPECT_TRUE(changed);
  float back[16];
  ASSERT_TRUE(assigned.get_matrix(assigned.find("World"), back));
  EXPECT_EQ(back[5], 105.0f);
}

// Per object, the block of the pass that does not hold the per-object matrices passes over
// their logged changes (update_block's inline check, by the block's parameter bits), and
// still takes a change of its own parameter, also one whose index shares a bit with a
// matrix it passes over (index 64 and index 0).
TEST(ParameterStore, BlockPassesOverChangesItDoesNotHold) {
  std::string text = "float4x4 World; ";
  for (int i = 1; i < 64; ++i) text += "float p" + std::to_string(i) + "; ";
  text += "float4 tint; float4 far;";
  auto b = test::build(text);
  ParameterStore store(b->model);
  const Param world = store.find("World"), tint = store.find("tint"), far = store.find("far");
  ASSERT_EQ(world.index, 0u);
  ASSERT_EQ(tint.index, 64u);
  const BlockMemberLayout object[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout material[] = {test::placed(b->model, "far", 0, 16, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout shared_bit[] = {test::placed(b->model, "tint", 0, 16, 0, 16, MatrixPacking::column_major)};
  ASSERT_TRUE(store.bind_layout(0, object, 64));
  ASSERT_TRUE(store.bind_layout(1, material, 16));
  ASSERT_TRUE(store.bind_layout(2, shared_bit, 16));
  const BlockHandle h[3] = {store.block(0), store.block(1), store.block(2)};
  bool changed = false;
  for (const BlockHandle& k : h) store.update_block(k, changed);
  float m[16] = {};
  for (int draw = 0; draw < 40; ++draw) {  // past the change log's 16 entries
    m[12] = float(draw + 1);
    ASSERT_TRUE(store.set_matrix(world, m));
    store.update_block(h[0], changed);
    EXPECT_TRUE(changed) << "draw " << draw;
    store.update_block(h[1], changed);
    EXPECT_FALSE(changed) << "draw " << draw;
    store.update_block(h[2], changed);
    EXPECT_FALSE(changed) << "draw " << draw;
    if (draw % 10 == 9) {
      const float v[4] = {float(draw), 1, 2, 3};
      ASSERT_TRUE(store.set(far, std::span<const float>(v)));
      ASSERT_TRUE(store.set(tint, std::span<const float>(v)));
      for (int k = 1; k < 3; ++k) {
        const std::span<const uint8_t> bytes = store.update_block(h[k], changed);
        EXPECT_TRUE(changed) << "draw " << draw << ", block " << k;
        float at;
        std::memcpy(&at, bytes.data(), 4);
        EXPECT_EQ(at, float(draw)) << "block " << k;
      }
    }
  }
}

// set_matrix writes a 4x4 matrix that blocks hold whole straight into the packed bytes of
// the block that last re-packed it (no re-pack at that block's next update_block). Checked
// against a second store given the same values through set(), which re-packs from the
// recent-change log: the bytes must match after every step, in two blocks holding World
// in different places and orders, when only one block is being handed out, mixed with
// set() on the same matrix, more changes than the log holds, and after a third block holds
// World with another register stride (World then takes the logged path everywhere).
TEST(ParameterStore, SetMatrixPacksBoundMatricesInPlace) {
  auto b = test::build("float4x4 World; float4x4 Wvp; float c; float e[20];");
  ParameterStore direct(b->model), logged(b->model);
  const BlockMemberLayout one[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major),
                                   test::placed(b->model, "Wvp", 64, 64, 0, 16, MatrixPacking::row_major),
                                   test::placed(b->model, "c", 128, 4, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout two[] = {test::placed(b->model, "c", 0, 4, 0, 16, MatrixPacking::column_major),
                                   test::placed(b->model, "World", 16, 64, 0, 16, MatrixPacking::row_major)};
  const BlockMemberLayout strided[] = {test::placed(b->model, "World", 0, 128, 0, 32, MatrixPacking::column_major)};
  for (ParameterStore* s : {&direct, &logged}) {
    ASSERT_TRUE(s->bind_layout(1, one, 144));
    ASSERT_TRUE(s->bind_layout(2, two, 80));
  }
  const Param world = direct.find("World"), wvp = direct.find("Wvp"), c = direct.find("c"), e = direct.find("e");
  auto expect_same = [&](const char* step, int k) {
    for (uint32_t id : {1u, 2u, 3u}) {
      const BlockHandle h = direct.block(id);
      if (!h.valid()) continue;
      const bool was_dirty = direct.dirty(id);
      bool changed = false;
      std::span<const uint8_t> got = direct.update_block(h, changed);
      EXPECT_EQ(changed, was_dirty) << step << " " << k << " block " << id;
      std::vector<uint8_t> want(got.size(), 0xCD);
      ASSERT_TRUE(logged.write_block(id, want));
      EXPECT_TRUE(std::equal(got.begin(), got.end(), want.begin())) << step << " " << k << " block " << id;
    }
  };
  float m[16], n[16];
  for (int k = 0; k < 40; ++k) {
    for (int i = 0; i < 16; ++i) m[i] = float(k * 16 + i), n[i] = -float(k * 16 + i) * 0.5f;
    ASSERT_TRUE(direct.set_matrix(world, m));
    ASSERT_TRUE(direct.set_matrix(wvp, n));
    ASSERT_TRUE(logged.set(world, std::span<const float>(m)));
    ASSERT_TRUE(logged.set(wvp, std::span<const float>(n)));
    if (k % 4 == 1) {  // block 1 drawn with, block 2 not: it must re-pack when it is
      bool changed = false;
      direct.update_block(direct.block(1), changed);
      logged.update_block(logged.block(1), changed);
      for (int i = 0; i < 16; ++i) m[i] += 0.25f;
      ASSERT_TRUE(direct.set_matrix(world, m));
      ASSERT_TRUE(logged.set(world, std::span<const float>(m)));
    }
    expect_same("set_matrix", k);
    ASSERT_TRUE(direct.set_matrix(world, m)) << "the same value: the blocks stay clean";
    EXPECT_FALSE(direct.dirty(1));
    EXPECT_FALSE(direct.dirty(2));
    if (k % 3 == 0) {  // set() on a matrix that set_matrix writes in place
      for (ParameterStore* s : {&direct, &logged}) ASSERT_TRUE(s->set(world, std::span<const float>(n)));
      expect_same("set", k);
    }
    if (k % 5 == 0) {  // more changes than the log holds, then one in place
      for (ParameterStore* s : {&direct, &logged}) {
        for (int j = 0; j < 20; ++j) ASSERT_TRUE(s->set(s->element(e, uint32_t(j)), float(k + j)));
        ASSERT_TRUE(s->set(c, float(k)));
      }
      ASSERT_TRUE(direct.set_matrix(world, m));
      ASSERT_TRUE(logged.set(world, std::span<const float>(m)));
    }
    expect_same("log", k);
    if (k == 20) {
      for (ParameterStore* s : {&direct, &logged}) ASSERT_TRUE(s->bind_layout(3, strided, 128));
    }
  }
}

// The same comparison under random operations: per-object matrices set in place (row- and
// column-major input), other values and long runs of changes set through the words, blocks
// handed out in random order (as passes of several techniques sharing one store are). Every
// handed-out block must match the logged store's, and `changed` false must mean the bytes
// handed out last.
TEST(ParameterStore, SetMatrixAgreesWithSetUnderRandomOperations) {
  auto b = test::build("float4x4 World; float4x4 Wvp; float c; float e[20];");
  const BlockMemberLayout one[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major),
                                   test::placed(b->model, "Wvp", 64, 64, 0, 16, MatrixPacking::row_major),
                                   test::placed(b->model, "c", 128, 4, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout two[] = {test::placed(b->model, "c", 0, 4, 0, 16, MatrixPacking::column_major),
                                   test::placed(b->model, "World", 16, 64, 0, 16, MatrixPacking::row_major)};
  const BlockMemberLayout three[] = {test::placed(b->model, "Wvp", 0, 64, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout four[] = {test::placed(b->model, "e", 0, 320, 16, 16, MatrixPacking::column_major),
                                    test::placed(b->model, "World", 320, 64, 0, 16, MatrixPacking::column_major)};
  const std::pair<std::span<const BlockMemberLayout>, uint32_t> layouts[] = {
      {one, 144}, {two, 80}, {three, 64}, {four, 384}};
  for (uint32_t seed = 1; seed <= 200; ++seed) {
    ParameterStore direct(b->model), logged(b->model);
    for (ParameterStore* s : {&direct, &logged})
      for (uint32_t id = 1; id <= 4; ++id)
        ASSERT_TRUE(s->bind_layout(id, layouts[id - 1].first, layouts[id - 1].second));
    const Param world = direct.find("World"), wvp = direct.find("Wvp"), c = direct.find("c"), e = direct.find("e");
    std::mt19937 rng(seed);
    auto pick = [&](uint32_t n) { return uint32_t(rng() % n); };
    std::vector<std::vector<uint8_t>> last(5);  // by block id: the bytes handed out last
    auto hand_out = [&](uint32_t id, int op) {
      bool changed = false;
      std::span<const uint8_t> got = direct.update_block(direct.block(id), changed);
      std::vector<uint8_t> want(got.size(), 0xCD);
      ASSERT_TRUE(logged.write_block(id, want));
      ASSERT_TRUE(std::equal(got.begin(), got.end(), want.begin()))
          << "seed " << seed << " op " << op << " block " << id;
      if (!changed && !last[id].empty()) {
        ASSERT_TRUE(std::equal(got.begin(), got.end(), last[id].begin())) << "unchanged: seed " << seed << " op " << op;
      }
      last[id].assign(got.begin(), got.end());
    };
    float m[16], t[16];
    for (int op = 0; op < 300; ++op) {
      const uint32_t what = pick(100);
      if (what < 50) {  // a per-object matrix, in place where it can be
        const Param p = pick(2) ? world : wvp;
        for (float& v : m) v = float(pick(7)) - 3.0f;  // small values repeat: unchanged sets too
        for (int r = 0; r < 4; ++r)
          for (int k = 0; k < 4; ++k) t[k * 4 + r] = m[r * 4 + k];
        if (pick(2)) {
          ASSERT_TRUE(direct.set_matrix(p, m));
        } else {
          ASSERT_TRUE(direct.set_matrix(p, t, fxkit::MatrixOrder::column_major));
        }
        ASSERT_TRUE(logged.set(p, std::span<const float>(m)));
      } else if (what < 58) {
        const float v = float(pick(5));
        for (ParameterStore* s : {&direct, &logged}) ASSERT_TRUE(s->set(c, v));
      } else if (what < 61) {  // more changes than the recent-change log holds
        for (ParameterStore* s : {&direct, &logged})
          for (uint32_t j = 0; j < 20; ++j) ASSERT_TRUE(s->set(s->element(e, j), float(op + int(j))));
      } else if (what < 64) {  // a per-object matrix through the words
        for (float& v : m) v = float(pick(9));
        const Param p = pick(2) ? world : wvp;
        for (ParameterStore* s : {&direct, &logged}) ASSERT_TRUE(s->set(p, std::span<const float>(m)));
      } else {
        hand_out(1 + pick(4), op);
      }
    }
    for (uint32_t id = 1; id <= 4; ++id) hand_out(id, 300);
  }
}

// A block that holds World with its registers apart (not one 4x4 group) never takes the
// matrix in place: it re-packs from the words, at every update after set_matrix changed
// the block that does (store_hot logs one change for it again each time it caught up). Checked
// against a store given the same values through set().
TEST(ParameterStore, SetMatrixReachesABlockThatRepacksIt) {
  auto b = test::build("float4x4 World; float c;");
  ParameterStore direct(b->model), logged(b->model);
  const BlockMemberLayout whole[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout apart[] = {test::placed(b->model, "World", 0, 128, 0, 32, MatrixPacking::column_major)};
  for (ParameterStore* s : {&direct, &logged}) {
    ASSERT_TRUE(s->bind_layout(1, whole, 64));
    ASSERT_TRUE(s->bind_layout(2, apart, 128));
  }
  const Param world = direct.find("World");
  float m[16];
  for (int k = 0; k < 6; ++k) {
    for (int i = 0; i < 16; ++i) m[i] = float(k * 16 + i);
    ASSERT_TRUE(direct.set_matrix(world, m));
    ASSERT_TRUE(logged.set(world, std::span<const float>(m)));
    for (uint32_t id : {1u, 2u}) {
      bool changed = false;
      std::span<const uint8_t> got = direct.update_block(direct.block(id), changed);
      EXPECT_TRUE(changed) << "step " << k << " block " << id;
      std::vector<uint8_t> want(got.size(), 0xCD);
      ASSERT_TRUE(logged.write_block(id, want));
      EXPECT_TRUE(std::equal(got.begin(), got.end(), want.begin())) << "step " << k << " block " << id;
    }
  }
}

// A column-major host matrix takes the same paths as a row-major one (no allocation, the
// hot block written in place): checked against a store given the transposed floats
// row-major, into a block with column registers and one with row registers, before the
// block is hot (the plain store) and after.
TEST(ParameterStore, SetMatrixTakesColumnMajorInput) {
  auto b = test::build("float4x4 World; float4x4 Wvp;");
  ParameterStore cols(b->model), rows(b->model);
  const BlockMemberLayout layout[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major),
                                      test::placed(b->model, "Wvp", 64, 64, 0, 16, MatrixPacking::row_major)};
  for (ParameterStore* s : {&cols, &rows}) ASSERT_TRUE(s->bind_layout(1, layout, 128));
  const Param world = cols.find("World"), wvp = cols.find("Wvp");
  float m[16], mt[16];
  for (int k = 0; k < 6; ++k) {
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[r * 4 + c] = float(k * 100 + r * 10 + c), mt[c * 4 + r] = m[r * 4 + c];
    ASSERT_TRUE(cols.set_matrix(world, mt, fxkit::MatrixOrder::column_major));
    ASSERT_TRUE(cols.set_matrix(wvp, mt, fxkit::MatrixOrder::column_major));
    ASSERT_TRUE(rows.set_matrix(world, m));
    ASSERT_TRUE(rows.set_matrix(wvp, m));
    bool cols_changed = false, rows_changed = false;
    std::span<const uint8_t> got = cols.update_block(cols.block(1), cols_changed);
    std::span<const uint8_t> want = rows.update_block(rows.block(1), rows_changed);
    EXPECT_TRUE(cols_changed) << k;
    EXPECT_TRUE(rows_changed) << k;
    ASSERT_TRUE(std::equal(got.begin(), got.end(), want.begin(), want.end())) << k;
    float back[16];
    ASSERT_TRUE(cols.get_matrix(world, back));
    EXPECT_TRUE(std::equal(back, back + 16, m)) << k;
    ASSERT_TRUE(cols.set_matrix(world, mt, fxkit::MatrixOrder::column_major)) << "the same value again";
    EXPECT_FALSE(cols.dirty(1)) << k;
  }
}

// Once a block is hot, set_matrix writes only that block's bytes and leaves the stored
// words behind. Every other reader must see the value the block holds: get_matrix, a block
// laid out later, a second block re-packing, remap(), and a set() of the value the words
// still hold (which is a change, not a no-op).
TEST(ParameterStore, MatrixWrittenInPlaceIsTheOneValue) {
  auto b = test::build("float4x4 World; float Gloss;");
  ParameterStore s(b->model);
  const BlockMemberLayout columns[] = {test::placed(b->model, "World", 0, 64, 0, 16, MatrixPacking::column_major)};
  const BlockMemberLayout rows[] = {test::placed(b->model, "World", 16, 64, 0, 16, MatrixPacking::row_major),
                                    test::placed(b->model, "Gloss", 0, 4, 0, 16, MatrixPacking::column_major)};
  ASSERT_TRUE(s.bind_layout(1, columns, 64));
  const Param world = s.find("World"), gloss = s.find("Gloss");
  float a[16], c[16], back[16];
  for (int i = 0; i < 16; ++i) a[i] = float(i + 1), c[i] = -float(i + 1);
  auto drawn = [&](uint32_t block) {
    bool changed = false;
    std::span<const uint8_t> bytes = s.update_block(s.block(block), changed);
    return std::vector<uint8_t>(bytes.begin(), bytes.end());
  };
  auto as_columns = [](const float* m) {
    std::vector<uint8_t> out(64);
    for (int col = 0; col < 4; ++col)
      for (int r = 0; r < 4; ++r) std::memcpy(out.data() + (col * 4 + r) * 4, &m[r * 4 + col], 4);
    return out;
  };
  ASSERT_TRUE(s.set_matrix(world, a));
  EXPECT_EQ(drawn(1), as_columns(a)) << "the first draw packs the words and makes block 1 hot";
  ASSERT_TRUE(s.set_matrix(world, c));  // in place: the words still hold `a`
  EXPECT_TRUE(s.dirty(1));
  EXPECT_EQ(drawn(1), as_columns(c));
  EXPECT_FALSE(s.dirty(1));
  ASSERT_TRUE(s.get_matrix(world, back));
  EXPECT_TRUE(std::equal(back, back + 16, c)) << "get_matrix reads the block's value";

  ASSERT_TRUE(s.set_matrix(world, a));
  ASSERT_TRUE(s.bind_layout(2, rows, 80)) << "a block laid out now packs the current value";
  std::vector<uint8_t> two = drawn(2);
  EXPECT_EQ(0, std::memcmp(two.data() + 16, a, 64));
  EXPECT_EQ(drawn(1), as_columns(a));

  ASSERT_TRUE(s.set_matrix(world, c));  // in place into block 1 again, logged for block 2
  EXPECT_TRUE(s.dirty(2));
  ASSERT_TRUE(s.set(gloss, 0.5f));
  two = drawn(2);
  EXPECT_EQ(0, std::memcmp(two.data() + 16, c, 64)) << "block 2 re-packs the value block 1 holds";

  ASSERT_TRUE(s.set_matrix(world, a));
  EXPECT_EQ(drawn(1), as_columns(a));
  ASSERT_TRUE(s.set_matrix(world, c));  // in place: the words hold `a` until synced
  ASSERT_TRUE(s.set(world, std::span<const float>(a))) << "a set() of the stale words' value";
  EXPECT_EQ(drawn(1), as_columns(a)) << "is a change";
  ASSERT_TRUE(s.set_matrix(world, c));

  ParameterStore reloaded(b->model);
  remap(s, reloaded);
  ASSERT_TRUE(reloaded.get_matrix(world, back));
  EXPECT_TRUE(std::equal(back, back + 16, c)) << "remap carries the in-place value";
}

TEST(ParameterStore, SharedPool) {
  auto one = test::build("shared float4x4 ViewProj; shared float Time = 1; float local = 2;");
  auto two = test::build("shared float Time = 5; shared float4x4 ViewProj; shared int Time2;");
  auto bad = test::build("shared float3 Time;");
  ParameterPool pool;
  ParameterStore a(one->model, &pool), b(two->model, &pool);
  EXPECT_EQ(pool.size(), 3u);
  float t = 0;
  ASSERT_TRUE(b.get(b.find("Time"), t));
  EXPECT_EQ(t, 1.0f) << "the first store to declare a shared parameter sets its default";
  const BlockMemberLayout layout[] = {test::placed(two->model, "Time", 0, 4, 0, 16, MatrixPacking::column_major)};
  ASSERT_TRUE(b.bind_layout(0, layout, 16));
  std::vector<uint8_t> bytes(16);
  ASSERT_TRUE(b.write_block(0, bytes));
  EXPECT_FALSE(b.dirty(0));
  ASSERT_TRUE(a.set(a.find("Time"), 9.0f));
  EXPECT_TRUE(b.dirty(0)) << "a write through another store dirties this store's block";
  ASSERT_TRUE(b.get(b.find("Time"), t));
  EXPECT_EQ(t, 9.0f);
  DiagnosticSink diags;
  ParameterStore c(bad->model, &pool, &diags);
  EXPECT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].id, "shared-type-mismatch");
  const float three[3] = {1, 2, 3};
  ASSERT_TRUE(c.set(c.find("Time"), std::span<const float>(three)));
  ASSERT_TRUE(a.get(a.find("Time"), t));
  EXPECT_EQ(t, 9.0f);
}

TEST(ParameterStore, RemapSurvivesReload) {
  auto v1 = test::build("float Gloss = 0.5; float4 Tint; float Removed; int Count;");
  auto v2 = test::build("float4 Tint; float Gloss = 0.1; int Count = 3; float Added;");
  auto v3 = test::build("float Gloss; float3 Tint;");
  ParameterStore s1(v1->model);
  Param gloss = s1.find("Gloss"), tint = s1.find("Tint"), removed = s1.find("Removed"), count = s1.find("Count");
  ASSERT_TRUE(s1.set(gloss, 0.75f));
  ASSERT_TRUE(s1.set(count, int32_t{9}));
  ParameterStore s2(v2->model);
  remap(s1, s2);
  EXPECT_EQ(s2.generation(), 1u);
  float g = 0;
  ASSERT_TRUE(s2.get(gloss, g));
  EXPECT_EQ(g, 0.75f) << "the value carries over and the old handle still works";
  int32_t n = 0;
  ASSERT_TRUE(s2.get(count, n));
  EXPECT_EQ(n, 9);
  EXPECT_EQ(s2.current(tint), s2.find("Tint"));
  ParamStatus st = s2.set(removed, 1.0f);
  EXPECT_EQ(st.code, ParamStatus::removed);
  EXPECT_NE(st.message.find("Removed"), std::string::npos) << st.message;
  // A second reload changes Tint's type: handles from both generations follow or go inert.
  ParameterStore s3(v3->model);
  remap(s2, s3);
  ASSERT_TRUE(s3.get(gloss, g));
  EXPECT_EQ(g, 0.75f);
  EXPECT_EQ(s3.set(tint, 1.0f).code, ParamStatus::removed);
  EXPECT_EQ(s3.set(count, int32_t{1}).code, ParamStatus::removed);
  EXPECT_EQ(s3.set(s2.find("Added"), 1.0f).code, ParamStatus::removed);
}

}  // namespace
}  // namespace fx
