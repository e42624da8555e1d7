// Paths that no reader may read: a FIFO, a symbolic link to /dev/zero, a
// folder and a file over a size limit (sparse, so that it costs neither
// time nor disk), made in the scratch folder; and a guard that keeps a test
// of a reader that blocks on a FIFO from hanging.
#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>

#include "test_files.hpp"

namespace special_files {

inline std::string fresh(const std::string& name) {
  const std::string path = test_files::scratch_dir() + name;
  std::error_code ec;
  std::filesystem::remove_all(path, ec);
  return path;
}

inline std::string fifo(const std::string& name) {
  const std::string path = fresh(name);
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << "mkfifo " << path;
  return path;
}

inline std::string link_to_dev_zero(const std::string& name) {
  const std::string path = fresh(name);
  EXPECT_EQ(::symlink("/dev/zero", path.c_str()), 0) << "symlink " << path;
  return path;
}

inline std::string folder(const std::string& name) {
  const std::string path = fresh(name);
  std::filesystem::create_directory(path);
  return path;
}

//! A file of `bytes` zero bytes that takes no disk space.
inline std::string sparse_file(const std::string& name, std::uint64_t bytes) {
  const std::string path = fresh(name);
  int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  EXPECT_GE(fd, 0) << "create " << path;
  EXPECT_EQ(::ftruncate(fd, static_cast<off_t>(bytes)), 0) << "truncate " << path;
  ::close(fd);
  return path;
}

//! The message of the exception fn throws, or "(no error)".
template <class Fn>
std::string error_of(Fn&& fn) {
  try {
    fn();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

//! error_of(fn) for a reader given the FIFO at `path`. A reader that opens
//! the FIFO waits for a writer: after 5 s one comes and goes, so the reader
//! reads an empty file and the test fails instead of hanging.
template <class Fn>
std::string error_reading_fifo(const std::string& path, Fn&& fn) {
  std::atomic<bool> done{false};
  std::thread writer([&] {
    auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!done && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    while (!done) {  // until the reader has its writer
      int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) ::close(fd);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
  std::string message = error_of(fn);
  done = true;
  writer.join();
  return message;
}

}  // namespace special_files
