// Whole-file reading, atomic writing and path resolution: the one copy
// that vvlib's readers and writers, the translator (vvc) and the host
// (vvinterpreter) share. Needs nothing but the standard library.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "../error.hpp"

namespace vv::io {

//! A file's text with a map from byte offsets to line numbers.
class text_file {
 public:
  text_file(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text_.size(); ++i)
      if (text_[i] == '\n') line_starts_.push_back(i + 1);
  }
  const std::string& name() const noexcept { return name_; }
  const std::string& text() const noexcept { return text_; }
  //! 1-based line of a byte offset (offsets past the end give the last line).
  int line_at(std::ptrdiff_t offset) const noexcept {
    if (offset < 0) return 0;
    auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(),
                               static_cast<std::size_t>(offset));
    return static_cast<int>(it - line_starts_.begin());
  }
  [[noreturn]] void fail(std::ptrdiff_t offset, const std::string& problem) const {
    throw error(name_, line_at(offset), problem);
  }

 private:
  std::string name_, text_;
  std::vector<std::size_t> line_starts_;
};

//! A whole file's bytes, or std::nullopt with the system's reason in *why
//! ("No such file or directory").
inline std::optional<std::string> read_file(const std::string& path, std::string* why = nullptr) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (in) {
    std::ostringstream ss;
    ss << in.rdbuf();
    if (!in.bad()) return ss.str();
  }
  if (why) *why = std::strerror(errno ? errno : EIO);
  return std::nullopt;
}

inline text_file read_text_file(const std::string& path) {
  std::string why;
  std::optional<std::string> text = read_file(path, &why);
  if (!text) throw error(path, 0, "cannot open file: " + why);
  return text_file(path, std::move(*text));
}

//! The folder of a path as written: "a/b" for "a/b/m.vvp", "/" for
//! "/m.vvp", "" for "m.vvp" (resolve() below puts them back together).
inline std::string folder_of(const std::string& path) { return std::filesystem::path(path).parent_path().string(); }

//! The folder of a path, absolute (relative to the working folder when that
//! cannot be found; "." for a bare name then).
inline std::string absolute_folder_of(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  std::string folder = folder_of(ec ? path : p.string());
  return folder.empty() ? "." : folder;
}

//! The extension of a path, lower-cased, with its dot (".obj"), or "".
inline std::string extension_of(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

//! Where writing path really goes: for a symbolic link, the file it names
//! (the link stays a link); otherwise path itself.
inline std::string write_target(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_symlink(path, ec)) return path;
  std::filesystem::path target = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : target.string();
}

//! A temporary name beside path, with the same extension (writers that
//! choose the format by extension still work on it).
inline std::string temporary_beside(const std::string& path) {
  return path + ".vvtmp" + extension_of(path);
}

//! The temporary that writing path uses (beside a link's target).
inline std::string temporary_for(const std::string& path) { return temporary_beside(write_target(path)); }

//! Writes bytes to path atomically: into a temporary beside the file,
//! checking every write and the close (a full disk shows there), then a
//! rename over it. On failure the previous file is untouched, no temporary
//! is left, and the error says why ("No space left on device").
inline void write_file_atomically(const std::string& path, const std::string& bytes) {
  const std::string target = write_target(path);
  const std::string tmp = temporary_beside(target);
  auto fail = [&](int e, bool remove) {
    if (remove) std::remove(tmp.c_str());
    throw error(path, 0, std::string("cannot write file: ") + std::strerror(e));
  };
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(errno, false);
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      int e = n < 0 ? errno : ENOSPC;
      ::close(fd);
      fail(e, true);
    }
    p += n, left -= static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail(errno, true);
  if (std::rename(tmp.c_str(), target.c_str()) != 0) fail(errno, true);
}

//! Writes text to path atomically (see write_file_atomically).
inline void write_text_file(const std::string& path, const std::string& text) { write_file_atomically(path, text); }

//! A program's relative path, resolved against its model folder.
inline std::string resolve(const std::string& base_dir, const std::string& path) {
  if (base_dir.empty() || path.empty() || path[0] == '/') return path;
  return base_dir.back() == '/' ? base_dir + path : base_dir + "/" + path;
}

}  // namespace vv::io
