#include "simhuman/render/video.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_split.h"

extern char** environ;

namespace simhuman::render {
namespace {

constexpr size_t kStderrTailBytes = 600;

bool IsExecutable(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// the last bytes of a file, trimmed, or "" when unreadable
std::string FileTail(const std::string& path, size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::stringstream buf;
  buf << in.rdbuf();
  std::string text = buf.str();
  if (text.size() > max_bytes) text = "..." + text.substr(text.size() - max_bytes);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) {
    text.pop_back();
  }
  return text;
}

std::string ParentDir(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

}  // namespace

absl::Status VideoOptions::Validate() const {
  if (ffmpeg.empty()) return absl::InvalidArgumentError("VideoOptions.ffmpeg is empty");
  if (crf < 0 || crf > 51) {
    return absl::InvalidArgumentError(
        absl::StrCat("VideoOptions.crf is ", crf, "; valid are 0..51"));
  }
  static const char* const kPresets[] = {"ultrafast", "superfast", "veryfast", "faster",  "fast",
                                         "medium",    "slow",      "slower",   "veryslow"};
  for (const char* p : kPresets) {
    if (preset == p) return absl::OkStatus();
  }
  return absl::InvalidArgumentError(
      absl::StrCat("VideoOptions.preset is '", preset, "'; valid are ",
                   absl::StrJoin(std::begin(kPresets), std::end(kPresets), ", ")));
}

absl::StatusOr<std::string> FindFfmpeg(const std::string& name) {
  if (name.find('/') != std::string::npos) {
    if (IsExecutable(name)) return name;
    return absl::NotFoundError(absl::StrCat("ffmpeg executable '", name,
                                            "' not found or not executable; install the "
                                            "Debian package ffmpeg (apt-get install ffmpeg)"));
  }
  const char* path_env = std::getenv("PATH");
  const std::string search = path_env != nullptr ? path_env : "/usr/bin:/bin";
  for (absl::string_view dir : absl::StrSplit(search, ':')) {
    const std::string candidate = absl::StrCat(dir.empty() ? "." : dir, "/", name);
    if (IsExecutable(candidate)) return candidate;
  }
  return absl::NotFoundError(absl::StrCat("'", name, "' not found on PATH (", search,
                                          "); install the Debian package ffmpeg "
                                          "(apt-get install ffmpeg)"));
}

absl::StatusOr<std::unique_ptr<VideoWriter>> VideoWriter::Open(const std::string& path, int w,
                                                               int h, int fps,
                                                               const VideoOptions& options) {
  if (w < 1 || h < 1 || fps < 1) {
    return absl::InvalidArgumentError(absl::StrCat("VideoWriter '", path, "': size ", w, "x", h,
                                                   " and fps ", fps, " must be >= 1"));
  }
  if (absl::Status s = options.Validate(); !s.ok()) return s;
  auto ffmpeg = FindFfmpeg(options.ffmpeg);
  if (!ffmpeg.ok()) return ffmpeg.status();
  const std::string dir = ParentDir(path);
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    return absl::NotFoundError(
        absl::StrCat("VideoWriter '", path, "': folder '", dir, "' does not exist"));
  }

  std::vector<std::string> args = {*ffmpeg,     "-y",
                                   "-loglevel", "error",
                                   "-f",        "rawvideo",
                                   "-pix_fmt",  "rgb24",
                                   "-s",        absl::StrCat(w, "x", h),
                                   "-r",        absl::StrCat(fps),
                                   "-i",        "-"};
  if (w % 2 != 0 || h % 2 != 0) {
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"});
  }
  args.insert(args.end(), {"-pix_fmt", "yuv420p", "-c:v", "libx264", "-preset", options.preset,
                           "-crf", absl::StrCat(options.crf), path});

  std::unique_ptr<VideoWriter> writer(new VideoWriter());
  writer->path_ = path;
  writer->width_ = w;
  writer->height_ = h;

  // ffmpeg's stderr goes to a temporary file, read back for error messages
  char stderr_template[] = "/tmp/simhuman_ffmpeg_XXXXXX";
  const int stderr_fd = ::mkostemp(stderr_template, O_CLOEXEC);
  if (stderr_fd < 0) {
    return absl::InternalError(
        absl::StrCat("VideoWriter '", path,
                     "': cannot create a temporary file in /tmp: ", std::strerror(errno)));
  }
  writer->stderr_path_ = stderr_template;

  // a socket rather than a pipe: send(MSG_NOSIGNAL) reports a dead reader as EPIPE instead of
  // killing us with SIGPIPE
  int fds[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
    ::close(stderr_fd);
    return absl::InternalError(
        absl::StrCat("VideoWriter '", path, "': socketpair: ", std::strerror(errno)));
  }
  ::shutdown(fds[0], SHUT_RD);
  ::shutdown(fds[1], SHUT_WR);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, stderr_fd, STDERR_FILENO);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawn_err =
      ::posix_spawn(&pid, ffmpeg->c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  ::close(stderr_fd);
  if (spawn_err != 0) {
    ::close(fds[0]);
    return absl::InternalError(absl::StrCat("VideoWriter '", path, "': cannot start ", *ffmpeg,
                                            ": ", std::strerror(spawn_err)));
  }
  writer->fd_ = fds[0];
  writer->pid_ = pid;
  return writer;
}

VideoWriter::~VideoWriter() {
  Close().IgnoreError();
  if (!stderr_path_.empty()) ::unlink(stderr_path_.c_str());
}

absl::Status VideoWriter::AddFrame(const std::vector<uint8_t>& rgb) {
  if (closed_) {
    return absl::FailedPreconditionError(
        absl::StrCat("VideoWriter '", path_, "': AddFrame after Close"));
  }
  const size_t expected = static_cast<size_t>(width_) * height_ * 3;
  if (rgb.size() != expected) {
    return absl::InvalidArgumentError(
        absl::StrCat("VideoWriter '", path_, "': frame ", frames_written_, " has ", rgb.size(),
                     " bytes; a ", width_, "x", height_, " RGB8 frame has ", expected));
  }
  size_t sent = 0;
  while (sent < expected) {
    const ssize_t n = ::send(fd_, rgb.data() + sent, expected - sent, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      // ffmpeg stopped reading: report how it ended
      const absl::Status exit_status = Close();
      const std::string when =
          absl::StrCat(" (", std::strerror(err), " while sending frame ", frames_written_, ")");
      if (exit_status.ok()) {
        return absl::InternalError(absl::StrCat("VideoWriter '", path_,
                                                "': ffmpeg exited with status 0 before the "
                                                "end of the input",
                                                when));
      }
      return absl::InternalError(absl::StrCat(exit_status.message(), when));
    }
    sent += static_cast<size_t>(n);
  }
  ++frames_written_;
  return absl::OkStatus();
}

absl::Status VideoWriter::Close() {
  if (closed_) return close_status_;
  closed_ = true;
  if (fd_ >= 0) {
    ::close(fd_);  // end of input: ffmpeg finishes the file
    fd_ = -1;
  }
  close_status_ = Reap();
  return close_status_;
}

absl::Status VideoWriter::Reap() {
  if (pid_ < 0) return absl::OkStatus();
  int wstatus = 0;
  pid_t r;
  do {
    r = ::waitpid(pid_, &wstatus, 0);
  } while (r < 0 && errno == EINTR);
  pid_ = -1;
  if (r < 0) {
    return absl::InternalError(
        absl::StrCat("VideoWriter '", path_, "': waitpid for ffmpeg: ", std::strerror(errno)));
  }
  if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0) return absl::OkStatus();
  std::string how = WIFEXITED(wstatus)
                        ? absl::StrCat("exit status ", WEXITSTATUS(wstatus))
                        : absl::StrCat("signal ", WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : -1);
  const std::string tail = FileTail(stderr_path_, kStderrTailBytes);
  return absl::InternalError(absl::StrCat("VideoWriter '", path_, "': ffmpeg failed with ", how,
                                          tail.empty() ? "" : ": ", tail));
}

}  // namespace simhuman::render
