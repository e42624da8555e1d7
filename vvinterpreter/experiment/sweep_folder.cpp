#include "experiment/sweep_folder.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/file.h>
#include <unistd.h>

#include <vv/io/files.hpp>

#include "experiment/sweep_identity.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

bool empty_folder(const std::string& dir) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
    if (e.path().filename() != ".lock") return false;
  return !ec;
}

}  // namespace

std::string write_in_folder(const std::string& dir, const std::string& name, const std::string& text) {
  try {
    vv::io::write_file_atomically(dir + "/" + name, text);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

sweep_folder::sweep_folder(const std::string& dir, const std::string& identity_text) : dir_(dir) {
  std::error_code ec;
  fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st) && !fs::is_directory(st)) {
    error_ = dir + ": not a folder (--out names the folder for the sweep)";
    return;
  }
  if (!fs::exists(st) && !fs::create_directories(dir, ec) && ec) {
    error_ = dir + ": cannot make the folder: " + ec.message();
    return;
  }
  lock_ = open((dir + "/.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (lock_ < 0) {
    error_ = dir + ": cannot write in the folder: " + std::strerror(errno);
    return;
  }
  if (flock(lock_, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
    error_ = dir + ": another sweep or merge is working in this folder; wait for it to end";
    return;
  }
  std::string file = dir + "/" + identity_file;
  std::optional<std::string> there = vv::io::read_file(file);
  if (there) {
    if (*there != identity_text)
      error_ = dir + " holds another sweep (" + identity_file + ": " + first_difference(*there, identity_text) +
               "); give another --out folder, or remove this one";
    return;
  }
  if (!empty_folder(dir)) {
    error_ = dir + ": the folder is not empty and holds no sweep (no " + std::string(identity_file) +
             "); give a new or empty --out folder";
    return;
  }
  error_ = write_in_folder(dir, identity_file, identity_text);
}

sweep_folder::~sweep_folder() {
  if (lock_ >= 0) close(lock_);
}

}  // namespace vvi
