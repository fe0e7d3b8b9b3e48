// Previews of techniques that only compute: what their passes wrote, read back as a picture,
// and the pattern a preview puts in the buffers no pass writes, so that what reads them varies.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <set>

#include "effect_test_util.h"
#include "fx/binding/storage_picture.h"

namespace fx::vk::testing {
namespace {

// The float pattern spreads over [-1, 1) without repeating early; the integer one stays
// below 64 (an index into any stand-in); other kinds stay zero.
TEST(StandInPattern, FloatsSpreadIntegersStaySmallOthersAreZero) {
  const std::vector<uint32_t> floats = stand_in_pattern(ScalarKind::float32, 4096);
  std::set<float> seen;
  float lo = 1, hi = -1;
  for (uint32_t w : floats) {
    const float f = std::bit_cast<float>(w);
    ASSERT_TRUE(std::isfinite(f));
    lo = std::min(lo, f), hi = std::max(hi, f);
    seen.insert(f);
  }
  EXPECT_GE(lo, -1.0f);
  EXPECT_LT(hi, 1.0f);
  EXPECT_LT(lo, -0.99f);
  EXPECT_GT(hi, 0.99f);
  EXPECT_EQ(seen.size(), floats.size());
  for (ScalarKind k : {ScalarKind::int32, ScalarKind::uint32}) {
    const std::vector<uint32_t> ints = stand_in_pattern(k, 200);
    EXPECT_EQ(ints[0], 0u);
    EXPECT_EQ(ints[63], 63u);
    EXPECT_EQ(ints[64], 0u);
    EXPECT_EQ(*std::max_element(ints.begin(), ints.end()), 63u);
  }
  const std::vector<uint32_t> others = stand_in_pattern(ScalarKind::float16, 16);
  EXPECT_TRUE(std::all_of(others.begin(), others.end(), [](uint32_t w) { return w == 0; }));
}

// Words scale from the smallest (black) to the largest (white) as their kind reads them;
// equal words are one flat grey; NaN is black and does not stretch the scale.
TEST(StoragePicture, BufferWordsScaleFromSmallestToLargest) {
  const std::vector<uint32_t> words = {std::bit_cast<uint32_t>(-2.0f), std::bit_cast<uint32_t>(0.0f),
                                       std::bit_cast<uint32_t>(2.0f), std::bit_cast<uint32_t>(NAN),
                                       std::bit_cast<uint32_t>(INFINITY)};
  const fx::Image picture = buffer_picture(words, ScalarKind::float32, 4);
  ASSERT_EQ(picture.width, 4u);
  ASSERT_EQ(picture.height, 2u);
  auto grey = [&](size_t i) { return picture.pixels[i * 4]; };
  EXPECT_EQ(grey(0), 0);
  EXPECT_EQ(grey(1), 128);
  EXPECT_EQ(grey(2), 255);
  EXPECT_EQ(grey(3), 0);  // NaN
  EXPECT_EQ(grey(4), 0);  // infinity
  EXPECT_EQ(picture.pixels[3], 255);
  // As signed integers, -1 is the smallest; as unsigned, the largest.
  const std::vector<uint32_t> ints = {0xFFFFFFFFu, 0u, 1u};
  EXPECT_EQ(buffer_picture(ints, ScalarKind::int32, 3).pixels[0], 0);
  EXPECT_EQ(buffer_picture(ints, ScalarKind::uint32, 3).pixels[0], 255);
  EXPECT_TRUE(buffer_picture(std::vector<uint32_t>(100, 7u), ScalarKind::uint32, 64).constant());
}

// Float texels are clamped to [0, 1]; a one-channel image shows in red.
TEST(StoragePicture, TexelsOfFloatImagesAreClampedColours) {
  StorageTexels texels;
  texels.width = 2, texels.height = 1, texels.format = VK_FORMAT_R32_SFLOAT;
  texels.words = {std::bit_cast<uint32_t>(0.5f), std::bit_cast<uint32_t>(3.0f)};
  const fx::Image picture = texel_picture(texels);
  EXPECT_EQ(picture.pixels[0], 128);
  EXPECT_EQ(picture.pixels[1], 0);
  EXPECT_EQ(picture.pixels[4], 255);
  EXPECT_EQ(picture.pixels[7], 255);
}

class ComputePreviewTest : public VulkanTest {
 protected:
  // Binds technique T of `source` for a 32x32 preview, renders one frame with no new
  // validation message, and reads back what its compute passes wrote.
  std::optional<EffectBinding::ComputeOutput> computed(const std::string& name, const std::string& source,
                                                       bool preview_stand_ins,
                                                       std::vector<std::string>* patterned = nullptr) {
    const std::string path = write_effect(name + ".fx", source);
    auto r = bind_effect(ctx(), path, "T", "sphere", 32, std::nullopt, VK_FORMAT_R8G8B8A8_UNORM, preview_stand_ins);
    EXPECT_TRUE(r);
    if (!r) return std::nullopt;
    EXPECT_TRUE(r->binding->computes_only(r->technique));
    const size_t errors = ctx().validation_error_count();
    EXPECT_TRUE(r->render());
    ctx().wait_idle();
    DiagnosticSink sink;
    auto out = r->binding->compute_output(r->technique, sink);
    EXPECT_FALSE(sink.has_errors()) << describe(sink);
    EXPECT_EQ(ctx().validation_error_count(), errors) << describe_messages(ctx());
    if (patterned) *patterned = r->binding->storage().patterned();
    return out;
  }
};

// A compute-only technique that squares a buffer it only reads into one it writes: with the
// preview's pattern in the input the output varies; with zeros in, the picture is flat.
TEST_F(ComputePreviewTest, ABufferItWritesIsPicturedAndWhatItReadsHoldsAPattern) {
  const std::string source = R"(StructuredBuffer<float> Weights;
RWStructuredBuffer<float> Squares;
[numthreads(64, 1, 1)] void Square(uint3 id : SV_DispatchThreadID) { Squares[id.x] = Weights[id.x] * Weights[id.x]; }
technique11 T { pass P < int3 Dispatch = {16, 1, 1}; > { SetComputeShader(CompileShader(cs_5_0, Square())); } }
)";
  std::vector<std::string> patterned;
  auto shown = computed("fxkit_compute_preview_buffer", source, true, &patterned);
  ASSERT_TRUE(shown);
  EXPECT_TRUE(shown->buffer);
  EXPECT_EQ(shown->name, "Squares");
  EXPECT_EQ(patterned, std::vector<std::string>{"Weights"});
  EXPECT_EQ(shown->picture.width, 64u);
  EXPECT_FALSE(shown->picture.constant());
  // Word 0 holds -1, whose square 1 is the largest (white); word 1 holds 2·frac(0.618) − 1,
  // squared 0.0557 (level 14); the words past the 16 x 64 the dispatch reached stay 0 (black).
  auto grey = [&](size_t word) { return int(shown->picture.pixels[word * 4]); };
  EXPECT_EQ(grey(0), 255);
  EXPECT_NEAR(grey(1), 14, 1);
  EXPECT_EQ(grey(16 * 64), 0);
  auto neutral = computed("fxkit_compute_preview_buffer_zeros", source, false, &patterned);
  ASSERT_TRUE(neutral);
  EXPECT_TRUE(patterned.empty());
  EXPECT_TRUE(neutral->picture.constant());
}

// A compute-only technique that paints a storage image: the picture is its texels.
TEST_F(ComputePreviewTest, AStorageImageItWritesIsPictured) {
  auto shown = computed("fxkit_compute_preview_image", R"(RWTexture2D<float4> Canvas;
[numthreads(8, 8, 1)] void Paint(uint3 id : SV_DispatchThreadID) { Canvas[id.xy] = float4(id.x / 32.0, 0.75, id.y / 32.0, 1); }
technique11 T { pass P { SetComputeShader(CompileShader(cs_5_0, Paint())); } }
)",
                        true);
  ASSERT_TRUE(shown);
  EXPECT_FALSE(shown->buffer);
  EXPECT_EQ(shown->name, "Canvas");
  ASSERT_EQ(shown->picture.width, 32u);
  auto at = [&](uint32_t x, uint32_t y, int c) { return int(shown->picture.pixels[(y * 32 + x) * 4 + c]); };
  EXPECT_EQ(at(0, 0, 0), 0);
  EXPECT_NEAR(at(16, 0, 0), 128, 1);
  EXPECT_NEAR(at(16, 8, 1), 191, 1);
  EXPECT_NEAR(at(0, 24, 2), 191, 1);
}

}  // namespace
}  // namespace fx::vk::testing
