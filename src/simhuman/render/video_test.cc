#include "simhuman/render/video.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <string>
#include <vector>

#include "simhuman/core/testing_temp.h"

namespace simhuman::render {
namespace {

long FileSize(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 ? static_cast<long>(st.st_size) : -1;
}

std::vector<uint8_t> Frame(int w, int h, int t) {
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(i * 3 + t * 20);
  return rgb;
}

#define SKIP_WITHOUT_FFMPEG() \
  if (auto ff = FindFfmpeg(); !ff.ok()) GTEST_SKIP() << ff.status().message()

TEST(VideoTest, WritesNonEmptyMp4) {
  SKIP_WITHOUT_FFMPEG();
  const std::string path = core::testing::UniqueTempPath("simhuman_video_test.mp4");
  std::remove(path.c_str());
  auto writer = VideoWriter::Open(path, 64, 48, 30);
  ASSERT_TRUE(writer.ok()) << writer.status();
  for (int t = 0; t < 10; ++t) ASSERT_TRUE((*writer)->AddFrame(Frame(64, 48, t)).ok());
  EXPECT_EQ((*writer)->frames_written(), 10);
  const absl::Status s = (*writer)->Close();
  ASSERT_TRUE(s.ok()) << s;
  EXPECT_GT(FileSize(path), 500);
  EXPECT_EQ((*writer)->AddFrame(Frame(64, 48, 0)).code(), absl::StatusCode::kFailedPrecondition);
  std::remove(path.c_str());
}

TEST(VideoTest, OddSizesArePadded) {
  SKIP_WITHOUT_FFMPEG();
  const std::string path = core::testing::UniqueTempPath("simhuman_video_odd.mp4");
  auto writer = VideoWriter::Open(path, 33, 17, 10);
  ASSERT_TRUE(writer.ok()) << writer.status();
  for (int t = 0; t < 3; ++t) ASSERT_TRUE((*writer)->AddFrame(Frame(33, 17, t)).ok());
  const absl::Status s = (*writer)->Close();
  EXPECT_TRUE(s.ok()) << s;
  EXPECT_GT(FileSize(path), 0);
  std::remove(path.c_str());
}

TEST(VideoTest, WrongFrameSizeIsAnError) {
  SKIP_WITHOUT_FFMPEG();
  const std::string path = core::testing::UniqueTempPath("simhuman_video_size.mp4");
  auto writer = VideoWriter::Open(path, 16, 16, 10);
  ASSERT_TRUE(writer.ok()) << writer.status();
  EXPECT_EQ((*writer)->AddFrame(Frame(16, 15, 0)).code(), absl::StatusCode::kInvalidArgument);
  ASSERT_TRUE((*writer)->AddFrame(Frame(16, 16, 0)).ok());
  EXPECT_TRUE((*writer)->Close().ok());
  std::remove(path.c_str());
}

TEST(VideoTest, FailingFfmpegIsAnErrorNotACrash) {
  SKIP_WITHOUT_FFMPEG();
  // ffmpeg cannot guess a container for this extension: it exits with an error at once, and
  // later frames hit a closed socket (which must not raise SIGPIPE)
  const std::string path = core::testing::UniqueTempPath("simhuman_video_bad.notavideoformat");
  auto writer = VideoWriter::Open(path, 64, 64, 10);
  ASSERT_TRUE(writer.ok()) << writer.status();
  absl::Status s;
  for (int t = 0; t < 200 && s.ok(); ++t) s = (*writer)->AddFrame(Frame(64, 64, t));
  if (s.ok()) s = (*writer)->Close();
  EXPECT_EQ(s.code(), absl::StatusCode::kInternal);
  EXPECT_NE(s.message().find(path), std::string::npos) << s;
  EXPECT_NE(s.message().find("exit status"), std::string::npos) << s;
  std::remove(path.c_str());
}

TEST(VideoTest, MissingFfmpegOrFolderIsAClearError) {
  VideoOptions options;
  options.ffmpeg = "simhuman-no-such-ffmpeg";
  auto writer = VideoWriter::Open(core::testing::UniqueTempPath("x.mp4"), 16, 16, 10, options);
  EXPECT_EQ(writer.status().code(), absl::StatusCode::kNotFound);
  EXPECT_NE(writer.status().message().find("Debian package ffmpeg"), std::string::npos)
      << writer.status();

  SKIP_WITHOUT_FFMPEG();
  writer = VideoWriter::Open("/nonexistent_dir_simhuman/x.mp4", 16, 16, 10);
  EXPECT_EQ(writer.status().code(), absl::StatusCode::kNotFound);
  EXPECT_NE(writer.status().message().find("/nonexistent_dir_simhuman"), std::string::npos);
}

TEST(VideoTest, RejectsBadOptions) {
  VideoOptions options;
  options.crf = 99;
  EXPECT_EQ(VideoWriter::Open("/tmp/x.mp4", 16, 16, 10, options).status().code(),
            absl::StatusCode::kInvalidArgument);
  options = VideoOptions();
  options.preset = "warp";
  EXPECT_EQ(VideoWriter::Open("/tmp/x.mp4", 16, 16, 10, options).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(VideoWriter::Open("/tmp/x.mp4", 16, 16, 0).status().code(),
            absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace simhuman::render
