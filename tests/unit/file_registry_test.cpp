// The file object registry: objects add themselves for as long as they
// exist (copies and moves included), the host can list their files, and
// proxy.reread_files() rereads each registered or listed object once.
#include <vv/file_objects.hpp>

#include <util/contour.hpp>
#include <util/function.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "test_files.hpp"

namespace {

using test_files::write_scratch;
using vv::file_kind;

bool registered(const vv::file_object* object, file_kind kind) {
  const auto& list = vv::file_objects().objects(kind);
  return std::count(list.begin(), list.end(), object) == 1;
}

std::size_t count_of(file_kind kind) { return vv::file_objects().objects(kind).size(); }

// Counts its rereads; throws when told to.
class counting : public vv::registered_file<file_kind::functions> {
 public:
  explicit counting(std::string file) : registered_file(std::move(file)) {}
  void reread() override {
    ++rereads;
    if (fail) throw std::runtime_error(path() + ": broken");
  }
  int rereads = 0;
  bool fail = false;
};

// A program's own file object, not registered.
struct unregistered : vv::file_object {
  void reread() override { ++rereads; }
  int rereads = 0;
};

const std::string line = "fver 1 1\nname: l\nsamples: 10\nflip: off\npoints: 4\n0 0\n0.3 0.3\n0.6 0.6\n1 1\n";

TEST(FileRegistry, ObjectsRegisterWhileTheyExist) {
  const std::size_t before = count_of(file_kind::functions);
  {
    util::Function f(write_scratch("reg.func", line));
    EXPECT_TRUE(registered(&f, file_kind::functions));
    EXPECT_FALSE(registered(&f, file_kind::contours));
    EXPECT_EQ(count_of(file_kind::functions), before + 1);

    util::Function copy(f);
    EXPECT_TRUE(registered(&copy, file_kind::functions));
    EXPECT_EQ(copy.path(), f.path());

    util::Function moved(std::move(copy));  // a move copies: both keep file and values
    EXPECT_TRUE(registered(&moved, file_kind::functions));
    EXPECT_TRUE(registered(&copy, file_kind::functions));
    EXPECT_EQ(copy.path(), f.path());
    EXPECT_DOUBLE_EQ(copy(0.5), 0.5);
    EXPECT_DOUBLE_EQ(moved(0.5), 0.5);
    EXPECT_EQ(count_of(file_kind::functions), before + 3);

    util::Function empty;
    empty = f;  // assignment keeps the one registration
    EXPECT_TRUE(registered(&empty, file_kind::functions));
    EXPECT_EQ(empty.path(), f.path());
    EXPECT_EQ(count_of(file_kind::functions), before + 4);
  }
  EXPECT_EQ(count_of(file_kind::functions), before);
}

TEST(FileRegistry, AFailedConstructionLeavesNothingRegistered) {
  const std::size_t before = vv::file_objects().size();
  EXPECT_THROW(util::Function(test_files::scratch_dir() + "absent.func"), vv::error);
  EXPECT_EQ(vv::file_objects().size(), before);
}

TEST(FileRegistry, PathsListsEachFileOnce) {
  const std::string fpath = write_scratch("listed.func", line);
  const std::string cpath = write_scratch("listed.con", "4 2 closed\n1 1\n1 -1\n-1 -1\n-1 1\n");
  util::Function f(fpath), again(fpath);
  util::Contour c(cpath);
  util::Function nothing;  // no file: not listed
  std::vector<std::string> paths = vv::file_objects().paths();
  EXPECT_EQ(std::count(paths.begin(), paths.end(), fpath), 1);
  EXPECT_EQ(std::count(paths.begin(), paths.end(), cpath), 1);
  EXPECT_EQ(std::count(paths.begin(), paths.end(), std::string()), 0);
  // Kind order: functions before contours.
  EXPECT_LT(std::find(paths.begin(), paths.end(), fpath), std::find(paths.begin(), paths.end(), cpath));
}

TEST(FileRegistry, ProxyRereadsEachObjectOnce) {
  vv::proxy proxy;
  counting registered_and_listed("a"), only_registered("b");
  unregistered listed;
  proxy.functions = {&registered_and_listed, &registered_and_listed};
  proxy.palettes = {&registered_and_listed};  // even under another kind
  proxy.materials = {&listed};
  proxy.reread_files();
  EXPECT_EQ(registered_and_listed.rereads, 1);
  EXPECT_EQ(only_registered.rereads, 1);
  EXPECT_EQ(listed.rereads, 1);
  proxy.reread_files();
  EXPECT_EQ(registered_and_listed.rereads, 2);
  EXPECT_EQ(only_registered.rereads, 2);
  EXPECT_EQ(listed.rereads, 2);
}

TEST(FileRegistry, AFailureDoesNotStopTheOthers) {
  vv::proxy proxy;
  counting first("first"), second("second"), third("third");
  first.fail = true;
  second.fail = true;
  try {
    proxy.reread_files();
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "first: broken");  // the first failure
  }
  EXPECT_EQ(first.rereads, 1);
  EXPECT_EQ(second.rereads, 1);
  EXPECT_EQ(third.rereads, 1);
}

TEST(FileRegistry, ProxyRereadReachesARealFunction) {
  const std::string path = write_scratch("host.func", line);
  util::Function f(path);
  EXPECT_DOUBLE_EQ(f(0.5), 0.5);
  write_scratch("host.func", "fver 1 1\nname: l\nsamples: 10\nflip: off\npoints: 4\n0 1\n0.3 1\n0.6 1\n1 1\n");
  vv::proxy proxy;
  proxy.reread_files();
  EXPECT_DOUBLE_EQ(f(0.5), 1.0);
}

}  // namespace
