#include "simhuman/render/image_io.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "simhuman/core/testing_temp.h"

namespace simhuman::render {
namespace {

std::vector<uint8_t> Gradient(int w, int h, int seed) {
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &rgb[(static_cast<size_t>(y) * w + x) * 3];
      p[0] = static_cast<uint8_t>(x * 7 + seed);
      p[1] = static_cast<uint8_t>(y * 13 + seed);
      p[2] = static_cast<uint8_t>((x ^ y) + 3 * seed);
    }
  }
  return rgb;
}

TEST(ImageIoTest, PngRoundTripIsExact) {
  const std::string path = core::testing::UniqueTempPath("simhuman_roundtrip.png");
  const int w = 37, h = 21;  // odd sizes: no row padding anywhere
  const std::vector<uint8_t> rgb = Gradient(w, h, 5);
  ASSERT_TRUE(WritePng(path, rgb, w, h).ok());
  std::vector<uint8_t> back;
  int bw = 0, bh = 0;
  const absl::Status s = ReadPng(path, &back, &bw, &bh);
  ASSERT_TRUE(s.ok()) << s;
  EXPECT_EQ(bw, w);
  EXPECT_EQ(bh, h);
  EXPECT_EQ(back, rgb);
  std::remove(path.c_str());
}

TEST(ImageIoTest, WritePngErrorsNameTheCulprit) {
  const std::vector<uint8_t> rgb = Gradient(4, 4, 0);
  absl::Status s = WritePng(core::testing::UniqueTempPath("x.png"), rgb, 5, 4);
  EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument);
  s = WritePng("/nonexistent_dir_simhuman/x.png", rgb, 4, 4);
  EXPECT_EQ(s.code(), absl::StatusCode::kNotFound);
  EXPECT_NE(s.message().find("/nonexistent_dir_simhuman/x.png"), std::string::npos) << s;
}

TEST(ImageIoTest, ReadPngRejectsNonPng) {
  const std::string path = core::testing::UniqueTempPath("malformed_not_a.png");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  std::fputs("this is not a png", f);
  std::fclose(f);
  std::vector<uint8_t> rgb;
  int w = 0, h = 0;
  const absl::Status s = ReadPng(path, &rgb, &w, &h);
  EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find(path), std::string::npos) << s;
  std::remove(path.c_str());
  EXPECT_EQ(ReadPng(path, &rgb, &w, &h).code(), absl::StatusCode::kNotFound);
}

TEST(ImageIoTest, ContactSheetLayout) {
  const int w = 20, h = 10;
  std::vector<std::vector<uint8_t>> frames;
  for (int i = 0; i < 5; ++i) frames.push_back(Gradient(w, h, i));
  ContactSheetOptions options;
  options.cols = 3;
  options.border_px = 2;
  std::vector<uint8_t> sheet;
  int sw = 0, sh = 0;
  ASSERT_TRUE(MakeContactSheet(frames, w, h, options, &sheet, &sw, &sh).ok());
  EXPECT_EQ(sw, 3 * w + 4 * 2);
  EXPECT_EQ(sh, 2 * h + 3 * 2);
  ASSERT_EQ(sheet.size(), static_cast<size_t>(sw) * sh * 3);
  // border is white, frame 4 (row 1, col 1) is copied exactly, the unused last cell is white
  EXPECT_EQ(sheet[0], 255);
  const int x0 = 2 + 1 * (w + 2), y0 = 2 + 1 * (h + 2);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(sheet[(static_cast<size_t>(y0 + 3) * sw + x0 + 5) * 3 + c],
              frames[4][(3 * w + 5) * 3 + c]);
  }
  const int ux = 2 + 2 * (w + 2) + 4, uy = 2 + 1 * (h + 2) + 4;
  EXPECT_EQ(sheet[(static_cast<size_t>(uy) * sw + ux) * 3], 255);
}

TEST(ImageIoTest, ContactSheetDownscaleAveragesBlocks) {
  // 4x2 frame: left half black, right half 200 -> downscale 2 gives 2x1: 0 and 200
  std::vector<uint8_t> frame(4 * 2 * 3, 0);
  for (int y = 0; y < 2; ++y) {
    for (int x = 2; x < 4; ++x) {
      for (int c = 0; c < 3; ++c) frame[(y * 4 + x) * 3 + c] = 200;
    }
  }
  ContactSheetOptions options;
  options.cols = 4;  // more columns than frames: one column
  options.downscale = 2;
  options.border_px = 1;
  std::vector<uint8_t> sheet;
  int sw = 0, sh = 0;
  ASSERT_TRUE(MakeContactSheet({frame}, 4, 2, options, &sheet, &sw, &sh).ok());
  EXPECT_EQ(sw, 2 + 2);
  EXPECT_EQ(sh, 1 + 2);
  EXPECT_EQ(sheet[(1 * sw + 1) * 3], 0);
  EXPECT_EQ(sheet[(1 * sw + 2) * 3], 200);
}

TEST(ImageIoTest, ContactSheetRejectsBadInput) {
  std::vector<uint8_t> sheet;
  int sw = 0, sh = 0;
  EXPECT_EQ(MakeContactSheet({}, 4, 4, {}, &sheet, &sw, &sh).code(),
            absl::StatusCode::kInvalidArgument);
  const absl::Status s =
      MakeContactSheet({Gradient(4, 4, 0), Gradient(4, 3, 0)}, 4, 4, {}, &sheet, &sw, &sh);
  EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find("frame 1"), std::string::npos) << s;
}

TEST(ImageIoTest, WriteContactSheetWritesPngOfSheetSize) {
  const std::string path = core::testing::UniqueTempPath("simhuman_sheet.png");
  std::vector<std::vector<uint8_t>> frames(6, Gradient(16, 12, 1));
  ASSERT_TRUE(WriteContactSheet(path, frames, 16, 12, 3, 2, 1).ok());
  std::vector<uint8_t> rgb;
  int w = 0, h = 0;
  ASSERT_TRUE(ReadPng(path, &rgb, &w, &h).ok());
  EXPECT_EQ(w, 3 * 8 + 4);
  EXPECT_EQ(h, 2 * 6 + 3);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace simhuman::render
