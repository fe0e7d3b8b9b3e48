// fx::Image PNG round trips, conversions, comparison and error reporting.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "fx/image.h"

namespace fx {
namespace {

Image gradient(uint32_t w, uint32_t h, uint32_t channels) {
  Image image = Image::blank(w, h, channels);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (uint32_t c = 0; c < channels; ++c) image.at(x, y)[c] = uint8_t(x * 7 + y * 13 + c * 50);
  return image;
}

std::filesystem::path temp_file(const char* name) { return std::filesystem::temp_directory_path() / name; }

TEST(Png, RoundTripsEveryChannelCountBitExactly) {
  for (uint32_t channels = 1; channels <= 4; ++channels) {
    DiagnosticSink sink;
    Image original = gradient(37, 19, channels);  // odd sizes catch stride bugs
    std::vector<uint8_t> png = encode_png(original, sink);
    ASSERT_FALSE(png.empty());
    EXPECT_EQ(png[1], 'P');
    auto decoded = decode_image(png, sink);
    ASSERT_TRUE(decoded) << channels;
    EXPECT_EQ(decoded->channels, channels);
    ImageDiff diff = compare(original, *decoded);
    EXPECT_TRUE(diff.comparable);
    EXPECT_EQ(diff.max_abs, 0u) << channels;
    EXPECT_FALSE(sink.has_errors());
  }
}

TEST(Png, FileRoundTripAndChannelConversionOnRead) {
  DiagnosticSink sink;
  Image rgb = gradient(8, 8, 3);
  auto path = temp_file("fxkit_image_io_test.png");
  ASSERT_TRUE(write_png(path, rgb, sink));
  auto rgba = read_png(path, sink, 4);
  ASSERT_TRUE(rgba);
  EXPECT_EQ(rgba->channels, 4u);
  EXPECT_EQ(rgba->at(5, 6)[0], rgb.at(5, 6)[0]);
  EXPECT_EQ(rgba->at(5, 6)[2], rgb.at(5, 6)[2]);
  EXPECT_EQ(rgba->at(5, 6)[3], 255);  // added alpha is opaque
  auto as_float = read_image_float(path, sink);
  ASSERT_TRUE(as_float);
  EXPECT_FLOAT_EQ(as_float->at(5, 6)[1], rgb.at(5, 6)[1] / 255.0f) << "8-bit reads stay linear";
  EXPECT_FALSE(sink.has_errors());
  std::filesystem::remove(path);
}

TEST(Png, MissingAndCorruptFilesAreDiagnostics) {
  DiagnosticSink sink;
  EXPECT_FALSE(read_png("/nonexistent/dir/nothing.png", sink));
  auto path = temp_file("fxkit_image_io_corrupt.png");
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("\x89PNG\r\n\x1a\n but not really", f);
    std::fclose(f);
  }
  EXPECT_FALSE(read_png(path, sink));
  EXPECT_FALSE(read_png(path, sink, 7));
  ASSERT_EQ(sink.error_count(), 3u);
  EXPECT_EQ(sink.diagnostics()[0].id, "image-open-failed");
  EXPECT_EQ(sink.diagnostics()[1].id, "image-decode-failed");
  EXPECT_NE(sink.diagnostics()[1].message.find(path.string()), std::string::npos) << "the message names the file";
  EXPECT_EQ(sink.diagnostics()[2].id, "image-decode-failed");
  std::filesystem::remove(path);
}

TEST(Png, RefusesToEncodeInconsistentImages) {
  DiagnosticSink sink;
  Image bad = Image::blank(4, 4, 4);
  bad.pixels.pop_back();
  EXPECT_TRUE(encode_png(bad, sink).empty());
  Image five = Image::blank(2, 2, 5);
  EXPECT_TRUE(encode_png(five, sink).empty());
  EXPECT_FALSE(write_png(temp_file("fxkit_never_written.png"), Image{}, sink));
  EXPECT_FALSE(write_png("/nonexistent/dir/x.png", Image::blank(1, 1, 1), sink));
  ASSERT_EQ(sink.error_count(), 4u);
  EXPECT_EQ(sink.diagnostics()[0].id, "image-encode-failed");
  EXPECT_EQ(sink.diagnostics()[3].id, "image-write-failed");
  EXPECT_FALSE(std::filesystem::exists(temp_file("fxkit_never_written.png")));
}

TEST(ImageConversion, Unorm8RoundsClampsAndZeroesNan) {
  ImageF f = ImageF::blank(6, 1, 1);
  f.pixels = {-0.5f, 0.0f, 0.5f, 1.0f / 510.0f, 2.0f, std::numeric_limits<float>::quiet_NaN()};
  Image u = to_unorm8(f);
  EXPECT_EQ(u.pixels, (std::vector<uint8_t>{0, 0, 128, 1, 255, 0}));
  ImageF back = to_float(u);
  EXPECT_FLOAT_EQ(back.pixels[4], 1.0f);
  EXPECT_FLOAT_EQ(back.pixels[2], 128.0f / 255.0f);
  // Every byte survives byte -> float -> byte.
  Image all = Image::blank(256, 1, 1);
  for (int i = 0; i < 256; ++i) all.pixels[size_t(i)] = uint8_t(i);
  EXPECT_EQ(to_unorm8(to_float(all)).pixels, all.pixels);
}

TEST(ImageCompare, CountsChannelsOverToleranceAndFindsTheFirst) {
  Image a = gradient(10, 10, 4), b = a;
  b.at(3, 7)[1] = uint8_t(b.at(3, 7)[1] + 5);
  b.at(8, 8)[0] = uint8_t(b.at(8, 8)[0] + 1);
  ImageDiff d = compare(a, b, 1);
  EXPECT_TRUE(d.comparable);
  EXPECT_EQ(d.max_abs, 5u);
  EXPECT_EQ(d.channels_over, 1u);
  EXPECT_EQ(d.first_x, 3u);
  EXPECT_EQ(d.first_y, 7u);
  EXPECT_EQ(compare(a, b, 0).channels_over, 2u);
  EXPECT_FALSE(compare(a, gradient(10, 9, 4)).comparable);
}

}  // namespace
}  // namespace fx
