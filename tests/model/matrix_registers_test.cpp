// fxkit::detail::matrix_registers::store_if_changed, the per-object matrix store: the registers it
// writes (as given or transposed), and "changed" meaning a bit differs, so -0 against +0
// is a change and the same NaN is not.
#include "fx/model/matrix_registers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace {

using fxkit::detail::matrix_registers::store_if_changed;

struct Registers {
  alignas(16) uint8_t bytes[64 + 1];  // +1: stores at an odd address too
  float at(const uint8_t* base, int i) const {
    float f;
    std::memcpy(&f, base + 4 * i, 4);
    return f;
  }
};

TEST(MatrixRegisters, StoresAsGivenOrTransposed) {
  float v[16];
  for (int i = 0; i < 16; ++i) v[i] = float(i + 1);
  for (int offset : {0, 1}) {
    Registers r{};
    uint8_t* to = r.bytes + offset;
    EXPECT_TRUE(store_if_changed(to, v, false));
    for (int i = 0; i < 16; ++i) EXPECT_EQ(r.at(to, i), v[i]) << i;
    EXPECT_FALSE(store_if_changed(to, v, false)) << "the same bits again";
    EXPECT_TRUE(store_if_changed(to, v, true));
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col) EXPECT_EQ(r.at(to, row * 4 + col), v[col * 4 + row]) << row << "," << col;
    EXPECT_FALSE(store_if_changed(to, v, true)) << "the same transpose again";
  }
}

TEST(MatrixRegisters, ChangedMeansABitDiffers) {
  float v[16] = {};
  Registers r{};
  EXPECT_FALSE(store_if_changed(r.bytes, v, false)) << "zeros over zeros";
  v[15] = -0.0f;
  EXPECT_TRUE(store_if_changed(r.bytes, v, false)) << "-0 is another bit pattern than +0";
  EXPECT_TRUE(std::signbit(r.at(r.bytes, 15)));
  v[7] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(store_if_changed(r.bytes, v, false));
  EXPECT_FALSE(store_if_changed(r.bytes, v, false)) << "the same NaN bits";
  // One changed element anywhere is found, in either order.
  for (int i = 0; i < 16; ++i) {
    float w[16];
    std::memcpy(w, v, sizeof w);
    Registers t{};
    store_if_changed(t.bytes, w, true);
    w[i] = 3.0f;
    EXPECT_TRUE(store_if_changed(t.bytes, w, true)) << i;
    EXPECT_EQ(t.at(t.bytes, (i % 4) * 4 + i / 4), 3.0f) << i;
  }
}

}  // namespace
