#include "app/files.hpp"

#include <vv/io/files.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace vvi {

namespace fs = std::filesystem;

std::optional<std::string> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool write_file(const std::string& path, const std::string& text) {
  try {
    vv::io::write_text_file(path, text);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

std::string folder_of(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::absolute(path, ec);
  if (ec) p = path;
  fs::path parent = p.parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

std::string executable_dir() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : self.parent_path().string();
}

std::string default_cache_dir() {
  if (const char* d = std::getenv("VV_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/vv";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/vv";
  return "/tmp/vv-cache";
}

}  // namespace vvi
