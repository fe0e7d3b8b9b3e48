// The DDS reader (DX9 and DX10 headers, cube, volume, arrays, mips) and the BC1-BC5 decoder
// on files the test writes.
#include <gtest/gtest.h>

#include "dds_writer.h"
#include "fx/dds.h"

namespace fx {
namespace {

using testing::dds_bytes;
using testing::dds_fourcc;
using testing::DdsHeader;

std::string messages(const DiagnosticSink& sink) {
  std::string out;
  for (const Diagnostic& d : sink.diagnostics()) out += d.id + ": " + d.message + "\n";
  return out;
}

TEST(Dds, Dx9CubeHasSixFacesInOrder) {
  DdsHeader h;
  h.width = h.height = 2;
  h.cube = true;
  std::vector<uint8_t> data;
  for (uint8_t face = 0; face < 6; ++face)
    for (int texel = 0; texel < 4; ++texel) data.insert(data.end(), {uint8_t(face * 40), 0, 0, 255});
  DiagnosticSink sink;
  auto t = decode_dds(dds_bytes(h, data), sink);
  ASSERT_TRUE(t) << messages(sink);
  EXPECT_EQ(t->shape, DdsShape::cube);
  EXPECT_EQ(t->format, DxgiFormat::r8g8b8a8_unorm);
  ASSERT_EQ(t->layers, 6u);
  ASSERT_EQ(t->subresources.size(), 6u);
  EXPECT_EQ(t->data[t->subresources[5].offset], 200);
}

TEST(Dds, Dx10VolumeWithMipsHasEachLevelsSize) {
  DdsHeader h;
  h.width = 4, h.height = 2, h.depth = 2, h.mips = 3;
  h.dxgi_format = uint32_t(DxgiFormat::r8_unorm);
  h.dimension = 4;
  std::vector<uint8_t> data(4 * 2 * 2 + 2 * 1 * 1 + 1);
  DiagnosticSink sink;
  auto t = decode_dds(dds_bytes(h, data), sink);
  ASSERT_TRUE(t) << messages(sink);
  EXPECT_EQ(t->shape, DdsShape::volume);
  ASSERT_EQ(t->subresources.size(), 3u);
  EXPECT_EQ(t->subresources[1].width, 2u);
  EXPECT_EQ(t->subresources[1].depth, 1u);
  EXPECT_EQ(t->subresources[2].offset, 18u);
}

TEST(Dds, Dx10ArrayOfBc1) {
  DdsHeader h;
  h.width = h.height = 8;
  h.dxgi_format = uint32_t(DxgiFormat::bc1_unorm);
  h.array_size = 3;
  DiagnosticSink sink;
  auto t = decode_dds(dds_bytes(h, std::vector<uint8_t>(3 * 4 * 8)), sink);
  ASSERT_TRUE(t) << messages(sink);
  EXPECT_EQ(t->layers, 3u);
  EXPECT_EQ(t->subresources[2].offset, 64u);
}

TEST(Dds, TruncatedAndUnknownFilesAreReported) {
  DdsHeader h;
  h.width = h.height = 4;
  h.fourcc = dds_fourcc("DXT5");
  DiagnosticSink sink;
  EXPECT_FALSE(decode_dds(dds_bytes(h, std::vector<uint8_t>(15)), sink));
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "image-decode-failed");
  h.fourcc = dds_fourcc("ETC1");
  DiagnosticSink unknown;
  EXPECT_FALSE(decode_dds(dds_bytes(h, std::vector<uint8_t>(16)), unknown));
  ASSERT_EQ(unknown.diagnostics().size(), 1u);
  EXPECT_EQ(unknown.diagnostics()[0].id, "image-format-unsupported");
  h.fourcc = dds_fourcc("DXT5");
  h.mips = 9;  // a 4x4 texture has three levels
  DiagnosticSink mips;
  EXPECT_FALSE(decode_dds(dds_bytes(h, std::vector<uint8_t>(1024)), mips));
}

TEST(Dds, Bc3BlocksDecodeToTheirColoursAndAlpha) {
  std::vector<uint8_t> blocks = testing::bc3_solid_block(0xF800, 200);  // red
  const std::vector<uint8_t> blue = testing::bc3_solid_block(0x001F, 255);
  blocks.insert(blocks.end(), blue.begin(), blue.end());
  Image image = decode_bc_rgba8(DxgiFormat::bc3_unorm, blocks, 8, 4);
  ASSERT_EQ(image.width, 8u);
  const uint8_t* red = image.at(1, 2);
  EXPECT_EQ(red[0], 255);
  EXPECT_EQ(red[1], 0);
  EXPECT_EQ(red[3], 200);
  const uint8_t* b = image.at(6, 3);
  EXPECT_EQ(b[2], 255);
  EXPECT_EQ(b[0], 0);
}

TEST(Dds, Bc1ThreeColourModeHasTransparentBlack) {
  // c0 <= c1: index 3 is transparent black, index 2 the midpoint.
  const std::vector<uint8_t> block = {0x00, 0x00, 0xFF, 0xFF, 0b01111110, 0, 0, 0};
  Image image = decode_bc_rgba8(DxgiFormat::bc1_unorm, block, 4, 4);
  EXPECT_EQ(image.at(0, 0)[3], 255);  // index 2: mid grey
  EXPECT_NEAR(image.at(0, 0)[0], 128, 1);
  EXPECT_EQ(image.at(1, 0)[3], 0);    // index 3
  EXPECT_EQ(image.at(3, 0)[0], 255);  // index 1: white
}

}  // namespace
}  // namespace fx
