// Files for tests: a scratch folder per test process (removed when the
// tests end), writing files into it, and whole-file reading.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace test_files {

inline std::string scratch_root() {
  return testing::TempDir() + "vv_test_" + std::to_string(::getpid());
}

//! The scratch folder, with a trailing slash (created on first use).
inline std::string scratch_dir() {
  std::filesystem::create_directories(scratch_root());
  return scratch_root() + "/";
}

class scratch_cleanup : public testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(scratch_root(), ec);
  }
};
inline testing::Environment* const cleanup_registration =
    testing::AddGlobalTestEnvironment(new scratch_cleanup);

//! Writes `bytes` to `name` in the scratch folder and returns its path.
inline std::string write_scratch(const std::string& name, const std::string& bytes) {
  const std::string path = scratch_dir() + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  EXPECT_TRUE(out.good()) << "cannot write " << path;
  return path;
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace test_files
