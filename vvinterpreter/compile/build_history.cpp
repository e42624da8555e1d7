#include "compile/build_history.hpp"

#include <filesystem>
#include <fstream>

namespace vvi {

namespace fs = std::filesystem;

namespace {

std::string mark_of(const std::string& cache_dir, const std::string& identity) {
  return cache_dir + "/built/" + identity;
}

}  // namespace

bool compiled_before(const std::string& cache_dir, const std::string& identity) {
  std::error_code ec;
  return fs::exists(mark_of(cache_dir, identity), ec);
}

void remember_compiled(const std::string& cache_dir, const std::string& identity) {
  std::error_code ec;
  fs::create_directories(cache_dir + "/built", ec);
  // Empty: its name is all it says, so two processes writing it at once
  // cannot leave it half-written.
  if (!ec) std::ofstream(mark_of(cache_dir, identity), std::ios::app);
}

}  // namespace vvi
