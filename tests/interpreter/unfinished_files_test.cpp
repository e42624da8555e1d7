// What a supervised child leaves when it is killed while writing a file
// (runner/supervisor.cpp): the temporary it made goes, even when the kill
// came between making it and saying its name, because the child names the
// folder first (runner/output_file.cpp).
#include <gtest/gtest.h>

#include <signal.h>

#include <filesystem>
#include <string>
#include <vector>

#include <vv/io/output_file.hpp>

#include "runner/fault_guard.hpp"
#include "runner/supervisor.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;

namespace {

std::string fresh_dir(const std::string& name) {
  std::string d = test_files::scratch_dir() + name;
  fs::remove_all(d);
  fs::create_directories(d);
  return fs::canonical(d).string();
}

// A child that makes the temporary of `target` and is killed before it says
// its name; `say_folder`: it said the folder first, as write_output does.
vvi::child_end killed_while_making(const std::string& target, bool say_folder) {
  return vvi::run_supervised(
      [target, say_folder] {
        vv::io::output_file out(target);
        if (say_folder) vvi::fault_guard::note_writing_in(out.folder_of_temporary());
        if (!out.make_temporary().empty()) return 2;
        raise(SIGKILL);
        return 0;
      },
      vvi::supervision{});
}

}  // namespace

TEST(UnfinishedFiles, AKillBeforeTheTemporaryIsNamedLeavesNothingInTheFolderNamedFirst) {
  const std::string d = fresh_dir("killed_before_named");
  vvi::child_end end = killed_while_making(d + "/big.obj", true);
  EXPECT_EQ(end.kind, vvi::child_end::crashed);
  EXPECT_EQ(end.writing_folders, std::vector<std::string>{d});
  EXPECT_TRUE(end.writing.empty());
  EXPECT_TRUE(fs::is_empty(d)) << fs::directory_iterator(d)->path();
}

// The same kill without the folder said: the temporary stays (until the
// next write in the folder), which is why the folder is said first.
TEST(UnfinishedFiles, WithoutTheFolderSaidTheTemporaryWouldStay) {
  const std::string d = fresh_dir("killed_unsaid");
  vvi::child_end end = killed_while_making(d + "/big.obj", false);
  EXPECT_EQ(end.kind, vvi::child_end::crashed);
  EXPECT_TRUE(end.writing_folders.empty());
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(d)) left.push_back(e.path().filename().string());
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].rfind(".big.vvtmp-", 0), 0u) << left[0];
}
