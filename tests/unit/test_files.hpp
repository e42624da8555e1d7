// Files for tests: a scratch folder per test process (removed when the
// tests end) and whole-file reading.
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

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace test_files
