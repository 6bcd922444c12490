#pragma once
/// MP4 (H.264) video from RGB8 frames, encoded by an ffmpeg child process.

#include <sys/types.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace simhuman::render {

/// Encoder settings of a VideoWriter.
struct VideoOptions {
  /// The ffmpeg executable: a name looked up on PATH, or a path containing '/'.
  std::string ffmpeg = "ffmpeg";
  int crf = 23;                     // x264 quality, 0 (lossless) .. 51 (worst)
  std::string preset = "veryfast";  // x264 preset

  /// Checks the ranges above; the message names the field.
  absl::Status Validate() const;
};

/// Finds the ffmpeg executable `name` (on PATH unless it contains '/'). kNotFound, saying to
/// install the Debian package ffmpeg, when there is none.
absl::StatusOr<std::string> FindFfmpeg(const std::string& name = "ffmpeg");

/// Writes an H.264 video (yuv420p, libx264) by piping raw RGB8 frames into ffmpeg:
/// `ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgb24 -s WxH -r FPS -i - -pix_fmt yuv420p
/// -c:v libx264 -preset veryfast -crf 23 path`. yuv420p needs even sizes: frames of odd width
/// or height are padded by one black column / row (ffmpeg's pad filter), so the video may be
/// one pixel larger than the frames.
///
/// A dead ffmpeg makes AddFrame or Close return an error; it never raises SIGPIPE in this
/// process (frames go through a socket written with MSG_NOSIGNAL). ffmpeg's stdout is
/// discarded and its stderr is kept in a temporary file whose tail ends up in error messages.
/// Not thread-safe; one writer per thread (or lock around it).
class VideoWriter {
 public:
  /// Starts ffmpeg writing `path` (overwriting it). Errors: kInvalidArgument for bad sizes,
  /// fps or options; kNotFound when ffmpeg is missing or the output folder does not exist;
  /// kInternal when ffmpeg cannot be started.
  static absl::StatusOr<std::unique_ptr<VideoWriter>> Open(const std::string& path, int w, int h,
                                                           int fps,
                                                           const VideoOptions& options = {});

  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// Closes like Close() if that has not happened, discarding the status: call Close() to
  /// learn whether the video was written.
  ~VideoWriter();

  /// Sends one w x h RGB8 frame (top row first). Errors: kInvalidArgument for a wrong size,
  /// kFailedPrecondition after Close(), kInternal when ffmpeg died (the message names the path,
  /// ffmpeg's exit status and the end of its error output).
  absl::Status AddFrame(const std::vector<uint8_t>& rgb);

  /// Ends the stream and waits for ffmpeg. Errors (kInternal) name the path, ffmpeg's exit
  /// status or signal, and the end of its error output. Calling it again returns the first
  /// result.
  absl::Status Close();

  int frames_written() const { return frames_written_; }
  const std::string& path() const { return path_; }

 private:
  VideoWriter() = default;

  // waits for ffmpeg and turns its exit into a status
  absl::Status Reap();

  std::string path_;
  int width_ = 0;
  int height_ = 0;
  int fd_ = -1;  // our end of the socket ffmpeg reads as stdin
  pid_t pid_ = -1;
  std::string stderr_path_;  // ffmpeg's stderr
  int frames_written_ = 0;
  bool closed_ = false;
  absl::Status close_status_;
};

}  // namespace simhuman::render
