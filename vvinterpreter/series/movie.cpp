#include "series/movie.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "runner/fault_guard.hpp"
#include "series/step_names.hpp"

namespace vvi {

namespace {

const char* const encoder = "ffmpeg";

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path && *path ? path : "/usr/bin:/bin";
  for (std::size_t from = 0, colon; from <= dirs.size(); from = colon + 1) {
    colon = dirs.find(':', from);
    if (colon == std::string::npos) colon = dirs.size();
    std::string dir = colon == from ? "." : dirs.substr(from, colon - from);
    if (::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

// What ffmpeg said on its standard error (a file), on one line.
std::string said(int fd) {
  std::string text;
  char buf[4096];
  ::lseek(fd, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (char& c : text)
    if (c == '\n') c = ' ';
  return text.empty() ? "it said nothing" : text;
}

}  // namespace

std::string movie_maker_missing(const std::string& movie) {
  if (on_path(encoder)) return "";
  std::string pictures = movie.substr(0, movie.size() - 4) + ".png";
  return movie + ": a movie is made by ffmpeg, which is not installed (no ffmpeg on the PATH); install it "
                 "(Debian package ffmpeg), or write the frames as pictures: --screenshot " +
         with_step_mark(pictures);
}

std::unique_ptr<movie_writer> movie_writer::open(const std::string& path, int width, int height, unsigned fps,
                                                 std::string& error) {
  std::unique_ptr<movie_writer> m(new movie_writer);
  m->path_ = path;
  m->width_ = width, m->height_ = height;
  m->out_ = std::make_unique<vv::io::output_file>(path);
  if (std::string why = m->out_->make_temporary(); !why.empty()) {
    error = path + ": cannot write file: " + why;
    return nullptr;
  }
  const std::string temporary = m->out_->temporary();
  fault_guard::note_writing(temporary, path);
  int target = ::open(temporary.c_str(), O_WRONLY | O_CLOEXEC);
  int pair[2] = {-1, -1};
  m->messages_ = ::memfd_create("ffmpeg messages", MFD_CLOEXEC);
  if (target < 0 || m->messages_ < 0 || ::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) {
    error = path + ": cannot start ffmpeg: " + std::strerror(errno);
    if (target >= 0) ::close(target);
    return nullptr;
  }
  std::string size = std::to_string(width) + "x" + std::to_string(height), rate = std::to_string(fps);
  // Raw RGBA frames in; H.264 in an MP4 out, written into the temporary
  // through the descriptor the child holds (fd 3), so that a temporary
  // removed by the supervisor is never made again by ffmpeg. x264 needs
  // even sizes: an odd one gets a row or column of padding. The bitexact
  // flags leave out the encoder's version and the time, so the same frames
  // make the same bytes.
  const char* argv[] = {encoder, "-hide_banner", "-loglevel", "error", "-f", "rawvideo", "-pixel_format", "rgba",
                        "-video_size", size.c_str(), "-framerate", rate.c_str(), "-i", "pipe:0", "-vf",
                        "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-fflags",
                        "+bitexact", "-flags:v", "+bitexact", "-movflags", "+faststart", "-f", "mp4", "-y",
                        "/proc/self/fd/3", nullptr};
  pid_t parent = ::getpid();
  pid_t pid = ::fork();
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // it dies with the process that feeds it
    if (::getppid() != parent) _exit(127);
    int null = ::open("/dev/null", O_WRONLY);
    if (::dup2(pair[1], 0) < 0 || ::dup2(null, 1) < 0 || ::dup2(m->messages_, 2) < 0 || ::dup2(target, 3) < 0)
      _exit(127);
    ::execvp(encoder, const_cast<char* const*>(argv));
    const char* why = "cannot run ffmpeg\n";
    if (::write(2, why, std::strlen(why)) < 0) _exit(127);
    _exit(127);
  }
  int e = errno;
  ::close(target);
  ::close(pair[1]);
  m->frames_in_ = pair[0];
  if (pid < 0) {
    error = path + ": cannot start ffmpeg: " + std::strerror(e);
    return nullptr;
  }
  m->encoder_ = pid;
  return m;
}

movie_writer::~movie_writer() {
  if (!finished_) stop_encoder(false);
  if (messages_ >= 0) ::close(messages_);
  std::string temporary = out_ ? out_->temporary() : "";
  out_.reset();  // an uncommitted temporary is removed
  if (!temporary.empty()) fault_guard::note_written(temporary);
}

std::string movie_writer::add(unsigned long step, std::vector<std::uint8_t> rgba, int width, int height) {
  if (width != width_ || height != height_)
    return path_ + ": the frames of a movie must all have one size (the first " + std::to_string(width_) + "x" +
           std::to_string(height_) + ", this one " + std::to_string(width) + "x" + std::to_string(height) + ")";
  if (holding_ && step != held_step_)
    if (std::string e = send(held_); !e.empty()) return e;
  held_ = std::move(rgba);
  held_step_ = step;
  holding_ = true;
  return "";
}

std::string movie_writer::send(const std::vector<std::uint8_t>& rgba) {
  const char* bytes = reinterpret_cast<const char*>(rgba.data());
  std::size_t left = rgba.size();
  while (left > 0) {
    ssize_t n = ::send(frames_in_, bytes, left, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return stop_encoder(true);  // it ended: why
    bytes += n;
    left -= static_cast<std::size_t>(n);
  }
  ++frames_;
  return "";
}

// Ends ffmpeg: after its last frame (wait_for_it), or at once. "" when it
// ended well, else what it said.
std::string movie_writer::stop_encoder(bool wait_for_it) {
  if (frames_in_ >= 0) ::close(frames_in_), frames_in_ = -1;
  if (encoder_ < 0) return path_ + ": ffmpeg is not running";
  if (!wait_for_it) ::kill(encoder_, SIGKILL);
  int status = 0;
  while (::waitpid(encoder_, &status, 0) < 0 && errno == EINTR) {
  }
  encoder_ = -1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  return path_ + ": ffmpeg failed: " + said(messages_);
}

std::string movie_writer::finish() {
  if (finished_) return "";
  if (holding_)
    if (std::string e = send(held_); !e.empty()) return e;
  holding_ = false;
  if (std::string e = stop_encoder(true); !e.empty()) return e;
  std::string temporary = out_->temporary();
  std::string why = out_->commit();
  fault_guard::note_written(temporary);
  if (!why.empty()) return path_ + ": cannot write file: " + why;
  finished_ = true;
  return "";
}

}  // namespace vvi
