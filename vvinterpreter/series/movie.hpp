// A movie (.mp4, H.264) from the pictures of a series, made by ffmpeg
// (Debian package ffmpeg): the frames are piped to it as raw RGBA, and it
// writes a temporary beside the movie (vv/io/output_file.hpp), which is
// renamed into place once ffmpeg has finished it. So the movie appears
// whole or not at all: a failed or killed run leaves no half movie (the
// supervisor removes the temporary of a model process that died, and
// ffmpeg dies with the process that feeds it).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vv/io/output_file.hpp>

namespace vvi {

//! Why movies cannot be made here ("" : ffmpeg is on the PATH); `movie`
//! names the file in the message.
std::string movie_maker_missing(const std::string& movie);

class movie_writer {
 public:
  //! A movie of width x height frames, `fps` a second, to be written at
  //! `path`; nullptr with `error` set when it cannot be started.
  static std::unique_ptr<movie_writer> open(const std::string& path, int width, int height, unsigned fps,
                                            std::string& error);
  //! Stops ffmpeg and removes the temporary unless finish() succeeded.
  ~movie_writer();
  movie_writer(const movie_writer&) = delete;
  movie_writer& operator=(const movie_writer&) = delete;

  //! The picture of the series at `step` (RGBA, top row first). A picture
  //! of the step of the one before replaces it (a series writes the state
  //! its run ends with again): each frame is held until the next step's
  //! arrives. "" or the error.
  std::string add(unsigned long step, std::vector<std::uint8_t> rgba, int width, int height);
  //! The last frame, then the movie put in place; "" or the error.
  std::string finish();
  const std::string& path() const { return path_; }
  unsigned long frames() const { return frames_; }

 private:
  movie_writer() = default;
  std::string send(const std::vector<std::uint8_t>& rgba);
  std::string stop_encoder(bool wait_for_it);

  std::string path_;
  std::unique_ptr<vv::io::output_file> out_;
  int width_ = 0, height_ = 0;
  pid_t encoder_ = -1;
  int frames_in_ = -1;  // ffmpeg's standard input (a socket: no SIGPIPE when it dies)
  int messages_ = -1;   // its standard error, a file read when it fails
  std::vector<std::uint8_t> held_;
  unsigned long held_step_ = 0;
  bool holding_ = false;
  unsigned long frames_ = 0;
  bool finished_ = false;
};

}  // namespace vvi
