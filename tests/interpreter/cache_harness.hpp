// What the model cache's tests share (model_cache_test.cpp,
// compiler_output_test.cpp): folders and files of their own in the
// process's scratch area, and the interpreter run on the suite's cache.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"

namespace cache_harness {

//! A fresh folder in the scratch area, as its canonical path with a slash.
inline std::string fresh_dir(const std::string& name) {
  std::string d = test_files::scratch_dir() + name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return std::filesystem::canonical(d).string() + "/";
}

inline void write(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << path;
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

inline std::string report(const test_run::result& r) {
  return "status " + std::to_string(r.status) + (r.timed_out ? " (timed out)" : "") + "\n--- stdout:\n" + r.out +
         "--- stderr:\n" + r.err;
}

//! vvinterpreter with `cache` and these arguments, in the folder `cwd`.
inline test_run::result run_in(const std::string& cwd, const std::string& cache,
                               const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"env", "-C", cwd, VV_INTERPRETER, "--cache", cache};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_run::run(argv, 280);
}

//! vvinterpreter on the suite's cache with these arguments.
inline test_run::result run(const std::vector<std::string>& args) { return run_in(".", VV_TEST_CACHE, args); }

//! The suite's precompiled header exists once this has compiled a model
//! of the source tree (the same model for every test: its build is made
//! once, where a seed in each test's folder was a compile of its own).
inline void suite_header_exists() {
  test_run::result seeded = run({"--compile-only", VV_TESTS_DIR "/models/header_seed.vvp"});
  ASSERT_EQ(seeded.status, 0) << report(seeded);
}

//! A cache of the test's own that shares the suite's precompiled headers
//! (hard links: nothing here changes them), so its decls/ folder holds
//! this test's parts alone.
inline std::string cache_with_header(const std::string& dir) {
  namespace fs = std::filesystem;
  suite_header_exists();
  const std::string cache = dir + "cache";
  fs::create_directories(cache);
  fs::copy(std::string(VV_TEST_CACHE) + "/pch", cache + "/pch",
           fs::copy_options::recursive | fs::copy_options::copy_symlinks | fs::copy_options::create_hard_links);
  return cache;
}

}  // namespace cache_harness

using namespace cache_harness;
